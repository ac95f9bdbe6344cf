#pragma once
// Status codes returned by every fallible flight-code call (controllers' step(), inversions,
// solvers). A non-ok status never comes with a non-finite output: the callee either produced a
// usable (possibly degraded) result, or left its outputs and internal state untouched, as each
// function documents.
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
  }
  return "unknown";
}

//! True for results that may be used (ok, or a degraded-but-valid answer).
constexpr bool usable(Status s) noexcept {
  return s == Status::ok || s == Status::ill_conditioned || s == Status::constraint_violated ||
         s == Status::saturated;
}

//! Keeps the most severe of two statuses (the first non-ok wins; a hard failure beats a
//! degraded result). Lets a step() accumulate the statuses of its sub-steps.
constexpr Status worst(Status a, Status b) noexcept {
  if (a == Status::ok) return b;
  if (b == Status::ok) return a;
  return (usable(a) && !usable(b)) ? b : a;
}

}  // namespace adcs
