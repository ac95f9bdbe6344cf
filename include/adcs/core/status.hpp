#pragma once
// Status codes returned by every fallible flight-code call (controllers' step(), inversions,
// solvers). A non-ok status never comes with a non-finite output: the callee either produced a
// usable (possibly degraded) result, or left its outputs and internal state untouched, as each
// function documents. The one exception is request_not_met: the output is written, finite and
// bounded, but it does not do what was asked (see written()).
#include <cstdint>

namespace adcs {

enum class [[nodiscard]] Status : std::uint8_t {
  ok = 0,                //!< Result computed as specified.
  non_finite_input,      //!< An input contained NaN or Inf. Outputs held, state untouched.
  out_of_range,          //!< An input was finite but outside its documented domain.
  singular,              //!< A matrix to invert was singular (or its factorisation failed).
  ill_conditioned,       //!< Conditioning crossed its threshold; a regularised (damped) result
                         //!< was returned instead of the exact one.
  constraint_violated,   //!< A constraint (projection bound, funnel, limit) was reached; the
                         //!< result is the constrained one and the event is counted.
  saturated,             //!< A command exceeded an actuator limit and was clipped/scaled.
  not_converged,         //!< A bounded iteration hit its limit without converging.
  invalid_parameter,     //!< A parameter struct failed validation (construction / reset()).
  request_not_met,       //!< A finite, bounded output was written, but it misses the request by
                         //!< more than its documented bound (CMG steering at a singularity or at
                         //!< the momentum envelope: torque error above the bound). Not usable()
                         //!< as the requested result; each function says whether the output may
                         //!< still be applied (a singularity-escape command is meant to be).
};

//! Short, stable, human-readable name of a status (for logs and ground tools).
constexpr const char* to_string(Status s) noexcept {
  switch (s) {
    case Status::ok: return "ok";
    case Status::non_finite_input: return "non_finite_input";
    case Status::out_of_range: return "out_of_range";
    case Status::singular: return "singular";
    case Status::ill_conditioned: return "ill_conditioned";
    case Status::constraint_violated: return "constraint_violated";
    case Status::saturated: return "saturated";
    case Status::not_converged: return "not_converged";
    case Status::invalid_parameter: return "invalid_parameter";
    case Status::request_not_met: return "request_not_met";
  }
  return "unknown";
}

//! True for results that may be used (ok, or a degraded-but-valid answer).
constexpr bool usable(Status s) noexcept {
  return s == Status::ok || s == Status::ill_conditioned || s == Status::constraint_violated ||
         s == Status::saturated;
}

//! True when the outputs were written: the usable statuses and request_not_met (whose output is
//! finite and bounded but misses its request). Every other status leaves the outputs untouched.
constexpr bool written(Status s) noexcept { return usable(s) || s == Status::request_not_met; }

//! Keeps the most severe of two statuses (the first non-ok wins; a hard failure beats a
//! degraded result). Lets a step() accumulate the statuses of its sub-steps.
constexpr Status worst(Status a, Status b) noexcept {
  if (a == Status::ok) return b;
  if (b == Status::ok) return a;
  return (usable(a) && !usable(b)) ? b : a;
}

}  // namespace adcs
