#pragma once
// Rigid spacecraft with N reaction wheels (continuous-time truth plant for the harness).
//
// State  x = [sigma_BN (3); omega_BN_B (3) [rad/s]; Omega (N) [rad/s]], Omega = wheel speed
//            relative to the body about its spin axis g_i.
// Input  u = [u_s (N) [N m] motor torques on the wheels; L_B (3) [N m] external torque].
// Model (Schaub & Junkins, Basilisk reactionWheelStateEffector, balanced wheels):
//   h_s,i = J_s,i (g_i^T omega + Omega_i)                 wheel spin momentum
//   H_B   = J_RW omega + G_s h_s = J omega + G_s J_s Omega   total momentum, B components
//   J_RW omega_dot = -omega x H_B - G_s u_s + L_B,   J_RW = J - sum_i J_s,i g_i g_i^T
//   J_s,i (g_i^T omega_dot + Omega_dot_i) = u_s,i
//   sigma_dot = G(sigma) omega                             seed 001 eq. (6)
// J is the total inertia including the wheels (as if locked), the convention users of
// other tools expect.
#include <Eigen/Cholesky>

#include "adcs/core/failure_hook.hpp"
#include "adcs/core/plant.hpp"
#include "adcs/core/status.hpp"
#include "adcs/core/types.hpp"
#include "adcs/core/validation.hpp"
#include "adcs/math/mrp.hpp"

namespace adcs {

//! No field has a default: a forgotten inertia or wheel axis is NaN and the plant refuses the set
//! (status() == invalid_parameter).
template <int N>
struct RigidBodyRwParams {
  Mat3 J_B = Mat3::Constant(kUnset);              //!< [kg m^2] total inertia incl. wheels, B components, SPD
  Mat<3, N> G_s_B = Mat<3, N>::Constant(kUnset);  //!< [-] wheel spin axes g_i (unit columns), B components
  Vec<N> J_s = Vec<N>::Constant(kUnset);          //!< [kg m^2] wheel spin-axis inertias, > 0
};

template <int N>
class RigidBodyRw {
 public:
  static constexpr int kWheels = N;
  static constexpr int kStateSize = 6 + N;
  static constexpr int kInputSize = N + 3;
  using State = Vec<kStateSize>;
  using Input = Vec<kInputSize>;
  using Params = RigidBodyRwParams<N>;

  //! Validates the parameters (status() says the outcome; the failure hook is called on error).
  explicit RigidBodyRw(const Params& p) noexcept : p_(p) {
    J_rw_ = p_.J_B;
    for (int i = 0; i < N; ++i) J_rw_ -= p_.J_s(i) * p_.G_s_B.col(i) * p_.G_s_B.col(i).transpose();
    ldlt_.compute(J_rw_);
    bool ok = symmetric<3>(p_.J_B) && all_finite(p_.G_s_B) && finite_positive(p_.J_s) &&
              ldlt_.info() == Eigen::Success && ldlt_.isPositive();
    for (int i = 0; i < N && ok; ++i) ok = std::abs(p_.G_s_B.col(i).norm() - 1.0) < 1e-9;
    if (ok) ok = (ldlt_.vectorD().array() > 0.0).all();
    status_ = ADCS_CHECK(ok, "RigidBodyRw: J symmetric, J - sum J_s g g^T SPD, axes unit, J_s > 0")
                  ? Status::ok
                  : Status::invalid_parameter;
  }

  //! ok, or invalid_parameter: J_B not finite or not symmetric; J_RW = J − Σ J_s g gᵀ not
  //! positive definite (so neither is J); an axis not unit (1e-9); J_s not finite > 0. A refused
  //! plant has no dynamics: derivative() gives xdot = 0.
  Status status() const noexcept { return status_; }
  const Params& params() const noexcept { return p_; }
  //! J_RW = J - sum_i J_s,i g_i g_i^T [kg m^2]: inertia seen by omega_dot.
  const Mat3& J_rw() const noexcept { return J_rw_; }

  static Vec3 sigma_BN(const State& x) noexcept { return x.template head<3>(); }
  static Vec3 omega_BN_B(const State& x) noexcept { return x.template segment<3>(3); }
  static Vec<N> Omega(const State& x) noexcept { return x.template tail<N>(); }

  //! Wheel spin momenta h_s [N m s].
  Vec<N> wheel_momentum(const State& x) const noexcept {
    return p_.J_s.cwiseProduct(p_.G_s_B.transpose() * omega_BN_B(x) + Omega(x));
  }
  //! Total angular momentum H_B [N m s], B components.
  Vec3 momentum_B(const State& x) const noexcept {
    return p_.J_B * omega_BN_B(x) + p_.G_s_B * p_.J_s.cwiseProduct(Omega(x));
  }
  //! Total angular momentum H_N = C(sigma_BN)^T H_B [N m s], N components (conserved when
  //! L_B = 0).
  Vec3 momentum_N(const State& x) const noexcept {
    return mrp_to_dcm(sigma_BN(x)).transpose() * momentum_B(x);
  }
  //! Kinetic energy [J]: 1/2 omega^T J_RW omega + 1/2 sum h_s,i^2 / J_s,i (conserved when
  //! u_s = 0 and L_B = 0).
  double kinetic_energy(const State& x) const noexcept {
    const Vec3 w = omega_BN_B(x);
    const Vec<N> hs = wheel_momentum(x);
    return 0.5 * w.dot(J_rw_ * w) + 0.5 * hs.cwiseProduct(hs).cwiseQuotient(p_.J_s).sum();
  }

  void derivative(double /*t*/, const State& x, const Input& u, State& xdot) const noexcept {
    if (status_ != Status::ok) {  // no valid model: a finite, frozen state instead of NaN
      xdot.setZero();
      return;
    }
    const Vec3 sigma = sigma_BN(x);
    const Vec3 w = omega_BN_B(x);
    const Vec<N> us = u.template head<N>();
    const Vec3 L = u.template tail<3>();
    const Vec3 H = momentum_B(x);
    const Vec3 wdot = ldlt_.solve(-w.cross(H) - p_.G_s_B * us + L);
    xdot.template head<3>() = mrp_G(sigma) * w;
    xdot.template segment<3>(3) = wdot;
    xdot.template tail<N>() = us.cwiseQuotient(p_.J_s) - p_.G_s_B.transpose() * wdot;
  }

  //! MRP shadow switch at samples: keeps |sigma_BN| <= 1.
  bool normalize(State& x) const noexcept {
    Vec3 s = sigma_BN(x);
    if (!mrp_shadow_switch(s)) return false;
    x.template head<3>() = s;
    return true;
  }

 private:
  Params p_;
  Mat3 J_rw_;
  Eigen::LDLT<Mat3> ldlt_;
  Status status_ = Status::ok;
};

ADCS_ASSERT_PLANT(RigidBodyRw<4>);

}  // namespace adcs
