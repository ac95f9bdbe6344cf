#pragma once
// Euler-angle reference with analytic derivatives (seed 002 §4, spec §B.5, B.4 #23):
//   ϑ_d(t) = a sin(ω_r t),  ϑ̇_d = ω_r a cos(ω_r t),  ϑ̈_d = −ω_r² a sin(ω_r t)
// with a = (π/180)[0.5, 1, −0.5] rad and ω_r = 0.1 rad/s in the paper.
#include <cmath>

#include "adcs/core/types.hpp"

namespace adcs {

//! Everything an Euler-angle tracking law needs from the reference at one instant.
struct EulerReferenceSample {
  Vec3 angles = Vec3::Zero();       //!< [rad] ϑ_d (x-y-z)
  Vec3 angles_dot = Vec3::Zero();   //!< [rad/s] ϑ̇_d
  Vec3 angles_ddot = Vec3::Zero();  //!< [rad/s²] ϑ̈_d
};

struct SinusoidalEulerParams {
  Vec3 amplitude_rad = Vec3(0.5, 1.0, -0.5) * (3.14159265358979323846 / 180.0);  //!< [rad] a, seed 002 §4
  double frequency_rad_s = 0.1;  //!< [rad/s] ω_r, seed 002 §4
};

class SinusoidalEulerReference {
 public:
  explicit SinusoidalEulerReference(const SinusoidalEulerParams& p = {}) noexcept : p_(p) {}
  EulerReferenceSample sample(double t) const noexcept {
    const double w = p_.frequency_rad_s, s = std::sin(w * t), c = std::cos(w * t);
    return EulerReferenceSample{p_.amplitude_rad * s, p_.amplitude_rad * (w * c), p_.amplitude_rad * (-w * w * s)};
  }
  const SinusoidalEulerParams& params() const noexcept { return p_; }

 private:
  SinusoidalEulerParams p_;
};

}  // namespace adcs
