#pragma once
// Active-disturbance-rejection attitude tracking with a linear extended state observer per axis
// (Gao 2003, "Scaling and bandwidth-parameterization based controller tuning"; the observer idea
// of seed 004 eq. (7)), on the x-y-z Euler view of the attitude (issue 17, a cross pairing: no
// paper flies it on seed 002's vehicle).
//
// Model. ϑ̈ = A + B u + D̄ with B = F(ϑ) J⁻¹ (seed 002 eqs. (3)-(4), math/euler_dynamics.hpp).
// With the input matrix taken AT THE MEASUREMENT, B̂ = F(y) J⁻¹, and the virtual control
// v = B̂ u, every axis is a unit-gain double integrator plus a total disturbance:
//
//   ϑ̈_i = v_i + f_i,   f = A + D̄ + (B(ϑ(t)) − B̂) u          (flexible modes, gyroscopic and
//                                                            kinematic coupling, external torque)
//
// Why B̂ = F J⁻¹ and not b0 = diag(J)⁻¹: the products of inertia and the Euler kinematics couple
// the axes through B; with the full B̂ the rigid input channel is inverted exactly at every
// sample (b0 = 1 in v-coordinates), so the observer's b0 error, the classic limit of ADRC
// robustness, is zero for a known J and f is only what the model does not know. The cost is one
// 3 x 3 product J G(y) per step; G(ϑ) (ω = G ϑ̇) is defined everywhere, F = G⁻¹ is singular at
// gimbal lock (|cos ϑ_2| < kEulerSingularCos), where the step returns `singular`.
//
// Measurement. Only the angles y = ϑ are read (ADRC-like: the observer estimates the rate);
// in.state.omega_BN_B is NOT used, so a missing or corrupted gyro does not reach the law.
//
// Observer (per axis, z = [ϑ̂, ϑ̂̇, f̂], discrete "current" ESO, Miklosovic, Radke & Gao 2006):
// the extended model ϑ̈ = v + f, ḟ = 0 discretised EXACTLY with a zero-order hold on v,
//   Φ = [1 h h²/2; 0 1 h; 0 0 1],  Γ = [h²/2; h; 0],  H = [1 0 0],
//   predict  z̄_k = Φ ẑ_{k−1} + Γ v_{k−1}
//   correct  ẑ_k = z̄_k + L (y_k − H z̄_k)                                  seed 004 eq. (7)
//   L = [1 − β³;  3(1 − β)²(1 + β)/(2h);  (1 − β)³/h²],  β = e^{−ω_o h}
// puts the three eigenvalues of the error dynamics (I − L H) Φ at z = β, the image of the
// continuous bandwidth parameterisation (all poles at −ω_o). Stability limit: none on ω_o h —
// β ∈ (0, 1) for every ω_o h > 0 (β → 0 is deadbeat). Forward Euler of the continuous ESO
// (gains 3ω_o, 3ω_o², ω_o³) would need ω_o h < 2, with large transient growth before it (the
// triple pole is a Jordan block); that is why the exact form is used.
//
// Control (linear state feedback on the estimates, k_p = ω_c², k_d = 2ω_c: critically damped):
//   e = ϑ̂ − ϑ_d,  ė = ϑ̂̇ − ϑ̇_d,  v = ϑ̈_d − k_p e − k_d ė − f̂,  u = B̂⁻¹ v = J G(y) v
// Linear feedback, not Han's fal: with it the closed loop of the exact model is linear and the
// separation principle holds (the current-form observer's error does not depend on v), so the
// sampled loop is stable iff the observer is (always, above) and the sampled PD on the double
// integrator is: Jury's test on z² + (a²/2 + 2a − 2) z + (1 + a²/2 − 2a), a = ω_c h, gives
// ω_c h < 1, checked at construction. Guideline (not enforced): ω_o = 3-10 ω_c, and both below
// the first lightly damped structural mode unless the law is meant to cancel it.
// Not saturation-aware: the observer is fed the commanded v; if an actuation stage clips the
// torque, f̂ absorbs the difference (wind-up); use it where the torque is not limited or feed
// the limit upstream.
//
// Angle wrap: the innovation y − ϑ̄ and the error e are wrapped to (−π, π], so ϑ_1, ϑ_3 crossing
// ±π does not kick the observer.
//
// Scalar (issue 19): EsoAdrcAttitudeT<S>; `EsoAdrcAttitude` is the double instance. Everything,
// the gains at construction included, is computed in S. In float the observer's third gain
// l3 = (1 − β)³/h² is formed from 1 − β with β = e^{−ω_o h} close to 1 at small ω_o h: 1 − β
// loses ~log2(1/(ω_o h)) bits (ω_o h = 0.1, the flexible-eso-adrc default: ~3 of float's 24), so
// the float observer's poles sit at e^{−ω_o h} to ~1e-6, not to the last bit.
#include <cmath>

#include "adcs/control/euler_tracking_common.hpp"
#include "adcs/core/component.hpp"
#include "adcs/core/failure_policy.hpp"
#include "adcs/core/signals.hpp"
#include "adcs/core/status.hpp"
#include "adcs/core/types.hpp"
#include "adcs/core/validation.hpp"
#include "adcs/math/euler.hpp"

namespace adcs {

//! J and the sample period have no default (NaN: refused): they are the vehicle's and the
//! computer's. The bandwidths have none either: they depend on the vehicle (structural modes,
//! sensor noise, actuator authority), so a forgotten one is refused, never guessed.
template <class S = double>
struct EsoAdrcAttitudeParamsT {
  Mat<3, 3, S> J_B_kgm2 = Mat<3, 3, S>::Constant(unset_v<S>);  //!< [kg m²] nominal inertia in B̂⁻¹ = J G, B components, SPD
  S omega_o_rad_s = unset_v<S>;            //!< [rad/s] observer bandwidth ω_o (poles at −ω_o), > 0
  S omega_c_rad_s = unset_v<S>;            //!< [rad/s] controller bandwidth ω_c (k_p = ω_c², k_d = 2ω_c), > 0
  S period_s = unset_v<S>;                 //!< [s] sample period h, > 0, with ω_c h < 1
  FailurePolicy on_failure = FailurePolicy::safe_command;  //!< after a failed step: zero torque, or hold
  //! The same parameters in another scalar (each value rounded once; validated by the law).
  template <class T>
  EsoAdrcAttitudeParamsT<T> cast() const noexcept {
    return {scalar_cast<T>(J_B_kgm2), narrow_scalar<T>(omega_o_rad_s), narrow_scalar<T>(omega_c_rad_s),
            narrow_scalar<T>(period_s), on_failure};
  }
};
using EsoAdrcAttitudeParams = EsoAdrcAttitudeParamsT<double>;

//! What one step computed (filled only when a pointer is passed).
template <class S = double>
struct EsoAdrcAttitudeDiagnosticsT {
  Vec<3, S> angles_hat_rad = Vec<3, S>::Zero();        //!< [rad] ϑ̂, observer state z1 after the correction
  Vec<3, S> angles_dot_hat_rad_s = Vec<3, S>::Zero();  //!< [rad/s] ϑ̂̇, z2
  Vec<3, S> f_hat_rad_s2 = Vec<3, S>::Zero();          //!< [rad/s²] f̂, z3: the estimated total disturbance
  Vec<3, S> innovation_rad = Vec<3, S>::Zero();        //!< [rad] y − ϑ̄ (predicted), wrapped
  Vec<3, S> e_rad = Vec<3, S>::Zero();                 //!< [rad] ϑ̂ − ϑ_d, wrapped
  Vec<3, S> e_dot_rad_s = Vec<3, S>::Zero();           //!< [rad/s] ϑ̂̇ − ϑ̇_d
  Vec<3, S> v_rad_s2 = Vec<3, S>::Zero();              //!< [rad/s²] virtual control v = B̂ u
};
using EsoAdrcAttitudeDiagnostics = EsoAdrcAttitudeDiagnosticsT<double>;

//! S: the scalar the law computes in (issue 19); `EsoAdrcAttitude` is the double instance.
template <class S = double>
class EsoAdrcAttitudeT {
 public:
  using Params = EsoAdrcAttitudeParamsT<S>;
  using Input = EulerTrackingInputT<S>;
  using Output = BodyTorqueT<S>;
  using Diagnostics = EsoAdrcAttitudeDiagnosticsT<S>;
  using Vec3S = Vec<3, S>;
  using Mat3S = Mat<3, 3, S>;

  explicit EsoAdrcAttitudeT(const Params& p) noexcept : p_(p) {
    const S h = p_.period_s;
    const bool ok_basic = symmetric_positive_definite<3, S>(p_.J_B_kgm2) && finite_positive(h) &&
                          finite_positive(p_.omega_o_rad_s) && finite_positive(p_.omega_c_rad_s) &&
                          p_.omega_c_rad_s * h < S(1);
    if (ok_basic) {
      const S beta = std::exp(-p_.omega_o_rad_s * h), m = S(1) - beta;
      l1_ = S(1) - beta * beta * beta;
      l2_ = S(1.5) * m * m * (S(1) + beta) / h;
      l3_ = m * m * m / (h * h);
      kp_ = p_.omega_c_rad_s * p_.omega_c_rad_s;
      kd_ = S(2) * p_.omega_c_rad_s;
    }
    const bool ok = ok_basic && std::isfinite(l1_) && std::isfinite(l2_) && std::isfinite(l3_) && l3_ > S(0);
    status_ = ok ? Status::ok : Status::invalid_parameter;
    reset();
  }

  //! ok, or invalid_parameter: J_B_kgm2 not finite, symmetric and positive definite; period_s,
  //! omega_o_rad_s or omega_c_rad_s not finite > 0; ω_c h ≥ 1 (the sampled PD on the double
  //! integrator is unstable there, see the header); an observer gain not finite (ω_o h so small
  //! that (1 − β)³/h² underflows). ω_o h has no upper limit (current-form exact ESO). A refused
  //! law answers invalid_parameter from every step() with its failure command.
  Status status() const noexcept { return status_; }
  S period_s() const noexcept { return p_.period_s; }
  const Params& params() const noexcept { return p_; }

  //! The observer forgets its state (the next step starts it again from that step's angles, with
  //! ϑ̂̇ = 0 and f̂ = 0) and the held command is cleared.
  void reset() noexcept {
    z1_.setZero();
    z2_.setZero();
    z3_.setZero();
    v_prev_.setZero();
    started_ = false;
    last_ = Output{};
  }

  //! Observer gains L = [l1, l2 [1/s], l3 [1/s²]] (the same on every axis).
  Vec3S observer_gains() const noexcept { return Vec3S(l1_, l2_, l3_); }
  bool started() const noexcept { return started_; }
  const Vec3S& angles_hat_rad() const noexcept { return z1_; }
  const Vec3S& angles_dot_hat_rad_s() const noexcept { return z2_; }
  const Vec3S& f_hat_rad_s2() const noexcept { return z3_; }

  //! One sample: observer predict + correct with the measured angles, then u = J G(y) v.
  //! ok; non_finite_input (an angle or a reference sample NaN/Inf; the rate is not read);
  //! singular (|cos ϑ_2| < kEulerSingularCos: the Euler view has no B there); out_of_range (a
  //! finite but absurd input overflowed); invalid_parameter (refused law). On any of these `out`
  //! is the failure command (zero torque, or the last good command under hold_last) and the
  //! observer state is untouched. The first step after construction or reset() initialises the
  //! observer at ϑ̂ = y, ϑ̂̇ = 0, f̂ = 0 (the rate is not measured: a vehicle at rest).
  [[nodiscard]] Status step(const Input& in, Output& out, Diagnostics* diag = nullptr) noexcept {
    out = failure_command(p_.on_failure, last_, Output{});
    if (status_ != Status::ok) return status_;
    const Vec3S& y = in.state.theta_BN_rad;
    const EulerReferenceSampleT<S>& r = in.reference;
    if (!all_finite(y) || !all_finite(r.angles) || !all_finite(r.angles_dot) || !all_finite(r.angles_ddot))
      return Status::non_finite_input;
    Mat3S F;  // only to detect gimbal lock: B̂ = F J⁻¹ does not exist there
    const Status ks = euler123_F<S>(y, F);
    if (ks != Status::ok) return ks;
    const S h = p_.period_s;
    Vec3S z1, z2, z3, innov;
    if (started_) {
      // predict with the exact ZOH model of ϑ̈ = v + f, ḟ = 0               seed 004 eq. (7)
      const Vec3S a = z3_ + v_prev_;
      const Vec3S z1p = z1_ + h * z2_ + (S(0.5) * h * h) * a;
      const Vec3S z2p = z2_ + h * a;
      innov = wrap(y - z1p);
      // correct with the current measurement (current-form ESO, poles at e^{−ω_o h})
      z1 = z1p + l1_ * innov;
      z2 = z2p + l2_ * innov;
      z3 = z3_ + l3_ * innov;
    } else {
      innov.setZero();
      z1 = y;
      z2.setZero();
      z3.setZero();
    }
    const Vec3S e = wrap(z1 - r.angles);
    const Vec3S e_dot = z2 - r.angles_dot;
    const Vec3S v = r.angles_ddot - kp_ * e - kd_ * e_dot - z3;  // ϑ̈ = v + f, f̂ cancelled
    Output c;
    c.torque_B_Nm.noalias() = p_.J_B_kgm2 * (euler123_G(y) * v);  // u = B̂⁻¹ v = J G(y) v
    if (diag) {
      diag->angles_hat_rad = z1;
      diag->angles_dot_hat_rad_s = z2;
      diag->f_hat_rad_s2 = z3;
      diag->innovation_rad = innov;
      diag->e_rad = e;
      diag->e_dot_rad_s = e_dot;
      diag->v_rad_s2 = v;
    }
    if (!all_finite(c.torque_B_Nm) || !all_finite(z1) || !all_finite(z2) || !all_finite(z3))
      return Status::out_of_range;  // overflow from absurd (finite) inputs: nothing committed
    z1_ = z1;
    z2_ = z2;
    z3_ = z3;
    v_prev_ = v;
    started_ = true;
    last_ = c;
    out = c;
    return Status::ok;
  }

 private:
  static constexpr S kTwoPi = S(6.28318530717958647692);
  //! Each component to (−π, π] (identity for the small errors of tracking).
  static Vec3S wrap(const Vec3S& x) noexcept {
    Vec3S w;
    for (int i = 0; i < 3; ++i) w(i) = std::remainder(x(i), kTwoPi);
    return w;
  }

  Params p_;
  Status status_ = Status::ok;
  S l1_ = S(0), l2_ = S(0), l3_ = S(0);  // observer gains [-, 1/s, 1/s²]
  S kp_ = S(0), kd_ = S(0);              // [1/s², 1/s]
  Vec3S z1_ = Vec3S::Zero(), z2_ = Vec3S::Zero(), z3_ = Vec3S::Zero();  // ϑ̂, ϑ̂̇, f̂
  Vec3S v_prev_ = Vec3S::Zero();         // v of the last committed step (held over the period)
  bool started_ = false;
  Output last_{};
};

using EsoAdrcAttitude = EsoAdrcAttitudeT<double>;
ADCS_ASSERT_COMPONENT(EsoAdrcAttitude);
ADCS_ASSERT_COMPONENT(EsoAdrcAttitudeT<float>);

}  // namespace adcs
