#pragma once
// Attitude reference driven by a sinusoidal body rate (seed 001 eq. (27)):
//   ω_f(t) = a ⊙ [sin(2πt/T_1), sin(2πt/T_2), sin(2πt/T_3)]     (reference axes) [rad/s]
//   σ̇_d = G(σ_d) ω_f,   σ̈_d = Ġ(σ_d, σ̇_d) ω_f + G(σ_d) ω̇_f                  (seed 001 §A.2.5)
// σ_d itself is integrated by the caller alongside the plant (same integrator, same step), and
// never shadow-switched (spec §A.2.4: e = σ − σ_d needs both on one continuous branch); σ̇_d and
// σ̈_d are evaluated analytically from σ_d(t) here.
#include "adcs/core/signals.hpp"
#include "adcs/core/status.hpp"
#include "adcs/core/types.hpp"
#include "adcs/core/validation.hpp"
#include "adcs/math/mrp.hpp"

namespace adcs {

//! Defaults: seed 001 eq. (27) (the hybrid-* scenarios' reference).
struct SinusoidalRateParams {
  Vec3 amplitude_rad_s = Vec3::Constant(0.02);     //!< [rad/s] a, seed 001 eq. (27); finite
  Vec3 period_s = Vec3(800.0, 600.0, 400.0);       //!< [s] T_k, seed 001 eq. (27); finite, > 0
};

class SinusoidalRateReference {
 public:
  explicit SinusoidalRateReference(const SinusoidalRateParams& p = {}) noexcept
      : p_(p),
        status_(all_finite(p.amplitude_rad_s) && finite_positive(p.period_s) ? Status::ok
                                                                              : Status::invalid_parameter) {}

  //! ok, or invalid_parameter: an amplitude not finite, a period not finite > 0. A refused
  //! reference does not move: ω_f = ω̇_f = 0 (finite; σ_d stays where the caller holds it).
  Status status() const noexcept { return status_; }

  //! ω_f(t) [rad/s].   seed 001 eq. (27)
  Vec3 omega(double t) const noexcept {
    if (status_ != Status::ok) return Vec3::Zero();
    Vec3 w;
    for (int k = 0; k < 3; ++k) w(k) = p_.amplitude_rad_s(k) * std::sin(kTwoPi * t / p_.period_s(k));
    return w;
  }
  //! ω̇_f(t) [rad/s²].   seed 001 §A.2.5
  Vec3 omega_dot(double t) const noexcept {
    if (status_ != Status::ok) return Vec3::Zero();
    Vec3 wd;
    for (int k = 0; k < 3; ++k)
      wd(k) = p_.amplitude_rad_s(k) * kTwoPi / p_.period_s(k) * std::cos(kTwoPi * t / p_.period_s(k));
    return wd;
  }
  //! σ̇_d = G(σ_d) ω_f(t): the right-hand side the caller integrates.
  Vec3 sigma_dot(double t, const Vec3& sigma_d) const noexcept { return mrp_G(sigma_d) * omega(t); }

  //! σ_d, σ̇_d, σ̈_d, ω_f, ω̇_f at time t for the integrated σ_d.
  MrpReferenceSample sample(double t, const Vec3& sigma_d) const noexcept {
    MrpReferenceSample r;
    r.sigma = sigma_d;
    r.omega = omega(t);
    r.omega_dot = omega_dot(t);
    const Mat3 G = mrp_G(sigma_d);
    r.sigma_dot = G * r.omega;
    r.sigma_ddot = mrp_G_dot(sigma_d, r.sigma_dot) * r.omega + G * r.omega_dot;
    return r;
  }

  const SinusoidalRateParams& params() const noexcept { return p_; }

 private:
  static constexpr double kTwoPi = 6.283185307179586476925286766559;
  SinusoidalRateParams p_;
  Status status_;
};

}  // namespace adcs
