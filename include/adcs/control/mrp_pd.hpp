#pragma once
// MRP proportional-derivative attitude tracking law with gyroscopic compensation, the
// baseline against Basilisk's mrpFeedback (K_i = 0) + rwMotorTorque:
//   L_r = -K sigma_BR - P omega_BR_B + J_RW (domega_RN_B - omega_BN_B x omega_RN_B)
//         + omega_BN_B x (J_RW omega_BN_B + G_s h_s)
// (Schaub & Junkins, "Analytical Mechanics of Space Systems", eq. (8.106)-(8.110)); globally
// asymptotically stable for K > 0, P > 0 with unsaturated torques. The output is the body torque
// request L_r (BodyTorque); RwTorqueAllocator maps it to wheel torques.
#include "adcs/core/component.hpp"
#include "adcs/core/failure_policy.hpp"
#include "adcs/core/signals.hpp"
#include "adcs/core/status.hpp"
#include "adcs/core/types.hpp"
#include "adcs/core/validation.hpp"
#include "adcs/math/mrp.hpp"

namespace adcs {

//! No field has a default: a forgotten gain, inertia or wheel axis is NaN and the controller
//! refuses the set (status() == invalid_parameter) instead of running with made-up values.
template <int N, class S = double>
struct MrpPdParams {
  S K = unset_v<S>;                                            //!< [N m] attitude gain on sigma_BR, > 0
  Mat<3, 3, S> P = Mat<3, 3, S>::Constant(unset_v<S>);        //!< [N m s] rate gain on omega_BR_B, SPD
  Mat<3, 3, S> J_rw_B = Mat<3, 3, S>::Constant(unset_v<S>);   //!< [kg m^2] J - sum J_s g g^T, B components, SPD
  Mat<3, N, S> G_s_B = Mat<3, N, S>::Constant(unset_v<S>);    //!< [-] wheel spin axes (unit), B components
  Vec<N, S> J_s = Vec<N, S>::Constant(unset_v<S>);            //!< [kg m^2] wheel spin inertias, >= 0
  S period_s = unset_v<S>;                                     //!< [s] sample period the law runs at, > 0
  FailurePolicy on_failure = FailurePolicy::safe_command;      //!< after a failed step: zero torque, or hold
  //! The same parameters in another scalar (each value rounded once; validation is redone by the
  //! controller that receives them).
  template <class T>
  MrpPdParams<N, T> cast() const noexcept {
    MrpPdParams<N, T> q;
    q.K = narrow_scalar<T>(K);
    q.P = scalar_cast<T>(P);
    q.J_rw_B = scalar_cast<T>(J_rw_B);
    q.G_s_B = scalar_cast<T>(G_s_B);
    q.J_s = scalar_cast<T>(J_s);
    q.period_s = narrow_scalar<T>(period_s);
    q.on_failure = on_failure;
    return q;
  }
};

template <int N, class S = double>
struct MrpPdInput {
  AttitudeStateT<S> state{};                  //!< measured σ_BN, ω_BN_B
  Vec<N, S> Omega_rad_s = Vec<N, S>::Zero();  //!< [rad/s] wheel speeds relative to the body
  AttitudeReferenceT<S> reference{};          //!< σ_RN, ω_RN_N, ω̇_RN_N
  template <class T>
  MrpPdInput<N, T> cast() const noexcept {
    return {state.template cast<T>(), scalar_cast<T>(Omega_rad_s), reference.template cast<T>()};
  }
};

template <class S = double>
struct MrpPdDiagnosticsT {
  Vec<3, S> sigma_BR = Vec<3, S>::Zero();    //!< [-] attitude error used
  Vec<3, S> omega_BR_B = Vec<3, S>::Zero();  //!< [rad/s] rate error used
};
using MrpPdDiagnostics = MrpPdDiagnosticsT<double>;

template <int N, class S = double>
class MrpPd {
 public:
  using Scalar = S;
  using Params = MrpPdParams<N, S>;
  using Input = MrpPdInput<N, S>;
  using Output = BodyTorqueT<S>;
  using Diagnostics = MrpPdDiagnosticsT<S>;

  explicit MrpPd(const Params& p) noexcept : p_(p), status_(validate(p)) { reset(); }

  //! ok, or invalid_parameter when a parameter is missing (NaN), not finite or unphysical: K > 0;
  //! P and J_rw_B symmetric positive definite; G_s_B unit columns; J_s >= 0; period_s > 0. A
  //! refused controller answers invalid_parameter from every step() with its failure command.
  Status status() const noexcept { return status_; }
  const Params& params() const noexcept { return p_; }
  S period_s() const noexcept { return p_.period_s; }

  static Status validate(const Params& p) noexcept {
    const bool ok = finite_positive(p.K) && symmetric_positive_definite<3, S>(p.P) &&
                    symmetric_positive_definite<3, S>(p.J_rw_B) && unit_columns<3, N, S>(p.G_s_B) &&
                    finite_nonnegative(p.J_s) && finite_positive(p.period_s);
    return ok ? Status::ok : Status::invalid_parameter;
  }

  //! Clears the held command (the law has no other time-varying state).
  void reset() noexcept { last_ = Output{}; }

  //! Computes L_r. On non-finite input returns non_finite_input, on an overflowing result
  //! out_of_range; `out` then receives the failure command (core/failure_policy.hpp: zero
  //! torque, or the last good command under hold_last). The output is always finite.
  [[nodiscard]] Status step(const Input& in, Output& out, Diagnostics* diag = nullptr) noexcept {
    const AttitudeStateT<S>& m = in.state;
    const AttitudeReferenceT<S>& r = in.reference;
    if (status_ != Status::ok) {
      out = failure_command(p_.on_failure, last_, Output{});
      return status_;
    }
    if (!all_finite(m.sigma_BN) || !all_finite(m.omega_BN_B) || !all_finite(in.Omega_rad_s) ||
        !all_finite(r.sigma_RN) || !all_finite(r.omega_RN_N) || !all_finite(r.domega_RN_N)) {
      out = failure_command(p_.on_failure, last_, Output{});
      return Status::non_finite_input;
    }
    const Mat<3, 3, S> C_BN = mrp_to_dcm(m.sigma_BN);
    const Vec<3, S> omega_RN_B = C_BN * r.omega_RN_N;
    const Vec<3, S> domega_RN_B = C_BN * r.domega_RN_N;
    const Vec<3, S> sigma_BR = mrp_subtract(m.sigma_BN, r.sigma_RN);
    const Vec<3, S> omega_BR_B = m.omega_BN_B - omega_RN_B;
    const Vec<3, S>& w = m.omega_BN_B;
    Vec<3, S> H_B;
    if constexpr (N > 0) {
      const Vec<N, S> h_s = p_.J_s.cwiseProduct(p_.G_s_B.transpose() * w + in.Omega_rad_s);
      H_B = p_.J_rw_B * w + p_.G_s_B * h_s;
    } else {  // no wheels: no G_s h_s term (a product with the empty 3x0 G_s would be UB)
      H_B = p_.J_rw_B * w;
    }
    Output c;
    c.torque_B_Nm = -p_.K * sigma_BR - p_.P * omega_BR_B + p_.J_rw_B * (domega_RN_B - w.cross(omega_RN_B)) +
                    w.cross(H_B);
    if (diag) {
      diag->sigma_BR = sigma_BR;
      diag->omega_BR_B = omega_BR_B;
    }
    if (!all_finite(c.torque_B_Nm)) {  // overflow from absurd (finite) inputs
      out = failure_command(p_.on_failure, last_, Output{});
      return Status::out_of_range;
    }
    last_ = c;
    out = c;
    return Status::ok;
  }

 private:
  Params p_;
  Status status_;
  Output last_;
};

ADCS_ASSERT_COMPONENT(MrpPd<4>);
ADCS_ASSERT_COMPONENT(MrpPd<4, float>);

}  // namespace adcs
