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
//! S is the scalar the PID computes in (issue 19).
template <int N, class S = double>
struct PidParams {
  Vec<N, S> kp = Vec<N, S>::Constant(unset_v<S>);  //!< proportional gains, no default
  Vec<N, S> ki = Vec<N, S>::Zero();  //!< integral gains (per unit·s); 0: no integral term
  Vec<N, S> kd = Vec<N, S>::Zero();  //!< derivative gains; 0: no derivative term
  S period_s = S(0.1);               //!< [s] h, the integration step of e_i (seed 004 §4)
  FailurePolicy on_failure = FailurePolicy::safe_command;  //!< after a failed sample: out = 0, or hold

  //! The same parameters in the scalar T, each value rounded once (narrow_scalar).
  template <class T>
  PidParams<N, T> cast() const noexcept {
    PidParams<N, T> out;
    out.kp = scalar_cast<T>(kp);
    out.ki = scalar_cast<T>(ki);
    out.kd = scalar_cast<T>(kd);
    out.period_s = narrow_scalar<T>(period_s);
    out.on_failure = on_failure;
    return out;
  }
};

template <int N, class S = double>
struct PidInput {
  Vec<N, S> e_p = Vec<N, S>::Zero();  //!< proportional error (command − state), per channel
  Vec<N, S> e_d = Vec<N, S>::Zero();  //!< its rate (an estimate, not a difference quotient)
};

template <int N, class S = double>
struct PidOutput {
  Vec<N, S> u = Vec<N, S>::Zero();  //!< K_P e_p + K_I e_i + K_D e_d, per channel
};

//! The integral after the sample.
template <int N, class S = double>
struct PidDiagnostics {
  Vec<N, S> e_i = Vec<N, S>::Zero();  //!< h Σ e_p
};

template <int N, class S = double>
class Pid {
 public:
  using Scalar = S;
  using Params = PidParams<N, S>;
  using Input = PidInput<N, S>;
  using Output = PidOutput<N, S>;
  using Diagnostics = PidDiagnostics<N, S>;
  using VecN = Vec<N, S>;

  explicit Pid(const Params& p) noexcept : p_(p) {
    const bool ok = finite_nonnegative(p_.kp) && finite_nonnegative(p_.ki) && finite_nonnegative(p_.kd) &&
                    finite_positive(p_.period_s);
    status_ = ok ? Status::ok : Status::invalid_parameter;
  }
  //! ok, or invalid_parameter: a gain not finite or < 0 (K_P unset), h not finite or not > 0.
  //! A refused PID answers invalid_parameter from every step() with its failure command.
  Status status() const noexcept { return status_; }
  S period_s() const noexcept { return p_.period_s; }
  void reset() noexcept {
    e_i_.setZero();
    last_.setZero();
  }
  const VecN& integral() const noexcept { return e_i_; }

  //! One sample. non_finite_input, or out_of_range (finite but absurd errors, ~1e308, whose
  //! integral or output overflows), leave the integral untouched and set `out` to the failure
  //! command (zero, or the last good output under on_failure = hold_last).
  [[nodiscard]] Status step(const Input& in, Output& out, Diagnostics* diag = nullptr) noexcept {
    const VecN& e_p = in.e_p;
    const VecN& e_d = in.e_d;
    const VecN fallback = failure_command(p_.on_failure, last_, VecN(VecN::Zero()));
    if (status_ != Status::ok) {
      out.u = fallback;
      return status_;
    }
    if (!all_finite(e_p) || !all_finite(e_d)) {
      out.u = fallback;
      return Status::non_finite_input;
    }
    const VecN e_i = e_i_ + p_.period_s * e_p;
    const VecN cmd = p_.kp.cwiseProduct(e_p) + p_.ki.cwiseProduct(e_i) + p_.kd.cwiseProduct(e_d);
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
  Params p_;
  VecN e_i_ = VecN::Zero();
  VecN last_ = VecN::Zero();
  Status status_ = Status::ok;
};

ADCS_ASSERT_COMPONENT(Pid<3>);
ADCS_ASSERT_COMPONENT(Pid<3, float>);

}  // namespace adcs
