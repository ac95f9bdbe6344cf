#pragma once
// Discrete PID per channel: out = K_P e_p + K_I e_i + K_D e_d with e_i = h Σ_{j≤k} e_p,j (the
// integral in units·s, spec §B.7 [D]); the caller supplies e_d (an estimated rate, not a
// difference quotient). Used as seed 004's linear baseline (Fig. 9: K_P 5.55, K_I 0, K_D 9).
#include <cmath>

#include "adcs/core/component.hpp"
#include "adcs/core/failure_policy.hpp"
#include "adcs/core/status.hpp"
#include "adcs/core/types.hpp"
#include "adcs/core/validation.hpp"

namespace adcs {

//! Gains are finite and >= 0: the errors carry the sign (e = command − state), so a negative gain
//! would be positive feedback. K_P has no default (NaN until set: refused); K_I = K_D = 0 switch
//! their terms off (seed 004 Fig. 9's PID runs with K_I = 0); h = 0.1 s is seed 004 §4's period.
template <int N>
struct PidParams {
  Vec<N> kp = Vec<N>::Constant(kUnset);  //!< proportional gains, no default
  Vec<N> ki = Vec<N>::Zero();  //!< integral gains (per unit·s); 0: no integral term
  Vec<N> kd = Vec<N>::Zero();  //!< derivative gains; 0: no derivative term
  double period_s = 0.1;       //!< [s] h, the integration step of e_i (seed 004 §4)
  FailurePolicy on_failure = FailurePolicy::safe_command;  //!< after a failed sample: out = 0, or hold
};

template <int N>
struct PidInput {
  Vec<N> e_p = Vec<N>::Zero();  //!< proportional error (command − state), per channel
  Vec<N> e_d = Vec<N>::Zero();  //!< its rate (an estimate, not a difference quotient)
};

template <int N>
struct PidOutput {
  Vec<N> u = Vec<N>::Zero();  //!< K_P e_p + K_I e_i + K_D e_d, per channel
};

//! The integral after the sample.
template <int N>
struct PidDiagnostics {
  Vec<N> e_i = Vec<N>::Zero();  //!< h Σ e_p
};

template <int N>
class Pid {
 public:
  using Params = PidParams<N>;
  using Input = PidInput<N>;
  using Output = PidOutput<N>;
  using Diagnostics = PidDiagnostics<N>;

  explicit Pid(const PidParams<N>& p) noexcept : p_(p) {
    const bool ok = finite_nonnegative(p_.kp) && finite_nonnegative(p_.ki) && finite_nonnegative(p_.kd) &&
                    finite_positive(p_.period_s);
    status_ = ok ? Status::ok : Status::invalid_parameter;
  }
  //! ok, or invalid_parameter: a gain not finite or < 0 (K_P unset), h not finite or not > 0.
  //! A refused PID answers invalid_parameter from every step() with its failure command.
  Status status() const noexcept { return status_; }
  double period_s() const noexcept { return p_.period_s; }
  void reset() noexcept {
    e_i_.setZero();
    last_.setZero();
  }
  const Vec<N>& integral() const noexcept { return e_i_; }

  //! One sample. non_finite_input, or out_of_range (finite but absurd errors, ~1e308, whose
  //! integral or output overflows), leave the integral untouched and set `out` to the failure
  //! command (zero, or the last good output under on_failure = hold_last).
  [[nodiscard]] Status step(const Input& in, Output& out, Diagnostics* diag = nullptr) noexcept {
    const Vec<N>& e_p = in.e_p;
    const Vec<N>& e_d = in.e_d;
    const Vec<N> fallback = failure_command(p_.on_failure, last_, Vec<N>(Vec<N>::Zero()));
    if (status_ != Status::ok) {
      out.u = fallback;
      return status_;
    }
    if (!all_finite(e_p) || !all_finite(e_d)) {
      out.u = fallback;
      return Status::non_finite_input;
    }
    const Vec<N> e_i = e_i_ + p_.period_s * e_p;
    const Vec<N> cmd = p_.kp.cwiseProduct(e_p) + p_.ki.cwiseProduct(e_i) + p_.kd.cwiseProduct(e_d);
    // Commit only finite results: an Inf integral would poison every later sample.
    if (!all_finite(e_i) || !all_finite(cmd)) {
      out.u = fallback;
      return Status::out_of_range;
    }
    e_i_ = e_i;
    last_ = cmd;
    out.u = cmd;
    if (diag) diag->e_i = e_i;
    return Status::ok;
  }

 private:
  PidParams<N> p_;
  Vec<N> e_i_ = Vec<N>::Zero();
  Vec<N> last_ = Vec<N>::Zero();
  Status status_ = Status::ok;
};

ADCS_ASSERT_COMPONENT(Pid<3>);

}  // namespace adcs
