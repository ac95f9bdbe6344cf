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
template <int N>
struct MrpPdParams {
  double K = kUnset;                                //!< [N m] attitude gain on sigma_BR, > 0
  Mat3 P = Mat3::Constant(kUnset);                  //!< [N m s] rate gain on omega_BR_B, SPD
  Mat3 J_rw_B = Mat3::Constant(kUnset);             //!< [kg m^2] J - sum J_s g g^T, B components, SPD
  Mat<3, N> G_s_B = Mat<3, N>::Constant(kUnset);    //!< [-] wheel spin axes (unit), B components
  Vec<N> J_s = Vec<N>::Constant(kUnset);            //!< [kg m^2] wheel spin inertias, >= 0
  double period_s = kUnset;                         //!< [s] sample period the law runs at, > 0
  FailurePolicy on_failure = FailurePolicy::safe_command;  //!< after a failed step: zero torque, or hold
};

template <int N>
struct MrpPdInput {
  AttitudeState state{};          //!< measured σ_BN, ω_BN_B
  Vec<N> Omega_rad_s = Vec<N>::Zero();  //!< [rad/s] wheel speeds relative to the body
  AttitudeReference reference{};  //!< σ_RN, ω_RN_N, ω̇_RN_N
};

struct MrpPdDiagnostics {
  Vec3 sigma_BR = Vec3::Zero();    //!< [-] attitude error used
  Vec3 omega_BR_B = Vec3::Zero();  //!< [rad/s] rate error used
};

template <int N>
class MrpPd {
 public:
  using Params = MrpPdParams<N>;
  using Input = MrpPdInput<N>;
  using Output = BodyTorque;
  using Diagnostics = MrpPdDiagnostics;

  explicit MrpPd(const Params& p) noexcept : p_(p), status_(validate(p)) { reset(); }

  //! ok, or invalid_parameter when a parameter is missing (NaN), not finite or unphysical: K > 0;
  //! P and J_rw_B symmetric positive definite; G_s_B unit columns; J_s >= 0; period_s > 0. A
  //! refused controller answers invalid_parameter from every step() with its failure command.
  Status status() const noexcept { return status_; }
  const Params& params() const noexcept { return p_; }
  double period_s() const noexcept { return p_.period_s; }

  static Status validate(const Params& p) noexcept {
    const bool ok = finite_positive(p.K) && symmetric_positive_definite<3>(p.P) &&
                    symmetric_positive_definite<3>(p.J_rw_B) && unit_columns<3, N>(p.G_s_B) &&
                    finite_nonnegative(p.J_s) && finite_positive(p.period_s);
    return ok ? Status::ok : Status::invalid_parameter;
  }

  //! Clears the held command (the law has no other time-varying state).
  void reset() noexcept { last_ = Output{}; }

  //! Computes L_r. On non-finite input returns non_finite_input, on an overflowing result
  //! out_of_range; `out` then receives the failure command (core/failure_policy.hpp: zero
  //! torque, or the last good command under hold_last). The output is always finite.
  [[nodiscard]] Status step(const Input& in, Output& out, Diagnostics* diag = nullptr) noexcept {
    const AttitudeState& m = in.state;
    const AttitudeReference& r = in.reference;
    if (status_ != Status::ok) {
      out = failure_command(p_.on_failure, last_, Output{});
      return status_;
    }
    if (!all_finite(m.sigma_BN) || !all_finite(m.omega_BN_B) || !all_finite(in.Omega_rad_s) ||
        !all_finite(r.sigma_RN) || !all_finite(r.omega_RN_N) || !all_finite(r.domega_RN_N)) {
      out = failure_command(p_.on_failure, last_, Output{});
      return Status::non_finite_input;
    }
    const Mat3 C_BN = mrp_to_dcm(m.sigma_BN);
    const Vec3 omega_RN_B = C_BN * r.omega_RN_N;
    const Vec3 domega_RN_B = C_BN * r.domega_RN_N;
    const Vec3 sigma_BR = mrp_subtract(m.sigma_BN, r.sigma_RN);
    const Vec3 omega_BR_B = m.omega_BN_B - omega_RN_B;
    const Vec3& w = m.omega_BN_B;
    Vec3 H_B;
    if constexpr (N > 0) {
      const Vec<N> h_s = p_.J_s.cwiseProduct(p_.G_s_B.transpose() * w + in.Omega_rad_s);
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

}  // namespace adcs
