#pragma once
// Ready-made flexible-spacecraft data: seed 002 Table 1 (spec §B.5), 2 solar panels x 4 modes.
// Every number below is GIVEN by the paper except where marked; F_s2 = −F_s1 (symmetric panels)
// and the shared Ω, ξ are the spec's reading B.4 #17. Also the paper's tracking gains with its
// true inertia (the laws' own header holds no plant data).
#include <cmath>

#include "adcs/control/euler_tracking_common.hpp"
#include "adcs/plant/flexible_spacecraft.hpp"

namespace adcs {

inline FlexibleSpacecraftParams<2, 4> flexible_params_seed002() noexcept {
  FlexibleSpacecraftParams<2, 4> p;
  p.J << 420.8, 3.6, -4.2,  //
      3.6, 410.6, 9.4,      //
      -4.2, 9.4, 690.7;     // [kg m²] seed 002 Table 1
  Mat<3, 4> F1;
  F1 << 2.62, -1.24e-3, -8.20e-4, 6.44e-1,  //
      6.89e-3, 1.24e-1, 4.37e-1, 6.26e-3,    //
      -3.44e-3, -2.73, -5.08e-2, 3.29e-3;    // [kg^½ m] seed 002 Table 1
  p.F_s[0] = F1;
  p.F_s[1] = -F1;  // spec B.4 #17: symmetric panels
  const double two_pi = 2.0 * 3.14159265358979323846;
  for (int l = 0; l < 2; ++l) {
    p.Omega[l] = two_pi * Vec<4>(0.379, 1.042, 1.331, 2.226);  // [rad/s] seed 002 Table 1
    p.xi[l] = Vec<4>::Constant(0.005);                          // [-] seed 002 Table 1
  }
  return p;
}

//! The paper's gains with its true inertia (seed 002 Tables 1-2): what both laws use on §B.5.
inline EulerTrackingGains seed002_tracking_gains() noexcept {
  EulerTrackingGains g;
  g.J = flexible_params_seed002().J;
  return g;
}

}  // namespace adcs
