#pragma once
// Euler-angle reference with analytic derivatives (seed 002 §4, spec §B.5, B.4 #23):
//   ϑ_d(t) = a sin(ω_r t),  ϑ̇_d = ω_r a cos(ω_r t),  ϑ̈_d = −ω_r² a sin(ω_r t)
// with a = (π/180)[0.5, 1, −0.5] rad and ω_r = 0.1 rad/s in the paper.
#include <cmath>

#include "adcs/core/signals.hpp"
#include "adcs/core/status.hpp"
#include "adcs/core/types.hpp"
#include "adcs/core/validation.hpp"

namespace adcs {

//! Defaults: seed 002 §4's reference (the flexible-* scenarios' manoeuvre).
struct SinusoidalEulerParams {
  Vec3 amplitude_rad = Vec3(0.5, 1.0, -0.5) * (3.14159265358979323846 / 180.0);  //!< [rad] a, seed 002 §4; finite
  double frequency_rad_s = 0.1;  //!< [rad/s] ω_r, seed 002 §4; finite, >= 0 (0: a constant ϑ_d = 0)
};

class SinusoidalEulerReference {
 public:
  explicit SinusoidalEulerReference(const SinusoidalEulerParams& p = {}) noexcept
      : p_(p),
        status_(all_finite(p.amplitude_rad) && finite_nonnegative(p.frequency_rad_s) ? Status::ok
                                                                                      : Status::invalid_parameter) {}

  //! ok, or invalid_parameter: an amplitude not finite, ω_r not finite or < 0. A refused
  //! reference samples as ϑ_d = 0 at rest (finite: a law tracking it holds attitude).
  Status status() const noexcept { return status_; }

  //! ϑ_d, ϑ̇_d, ϑ̈_d at time t [s] (finite t: callers check).
  EulerReferenceSample sample(double t) const noexcept {
    if (status_ != Status::ok) return EulerReferenceSample{};
    const double w = p_.frequency_rad_s, s = std::sin(w * t), c = std::cos(w * t);
    return EulerReferenceSample{p_.amplitude_rad * s, p_.amplitude_rad * (w * c), p_.amplitude_rad * (-w * w * s)};
  }
  const SinusoidalEulerParams& params() const noexcept { return p_; }

 private:
  SinusoidalEulerParams p_;
  Status status_;
};

}  // namespace adcs
