#pragma once
// Test support: the spec's prototype integrator for an SE(3) spacecraft (seed 003, spec Appendix
// C.1), shared by the plant and control tests. Ground/test code, not flight code.
#include "adcs/plant/se3_spacecraft.hpp"

namespace adcs_test {

using adcs::Se3Spacecraft;
using adcs::Se3SpacecraftRates;
using adcs::Se3SpacecraftState;
using adcs::Status;
using adcs::Vec3;
using adcs::Vec6;

// One RK4 step of dt on (R, ξ) under a held control wrench tau_c and disturbance tau_d; stage attitudes C0 exp(c dt ω)
// use the previous stage's ω, and the step ends with the Lie-group update C ← C exp(dt ω̄×),
// ω̄ the RK4 average of the stage rates (spec Appendix C.1 prototype method).
inline bool rk4_step(const Se3Spacecraft& sc, Se3SpacecraftState& x, double dt, const Vec6& tau_c = Vec6::Zero(),
                     const Vec6& tau_d = Vec6::Zero()) {
  const Vec6 xi0 = x.xi();
  Se3SpacecraftRates k[4];
  Vec6 xi[4];
  Vec3 R[4];
  const double c[4] = {0.0, 0.5 * dt, 0.5 * dt, dt};
  for (int i = 0; i < 4; ++i) {
    Se3SpacecraftState s;
    if (i == 0) {
      xi[0] = xi0;
      R[0] = x.R_N;
      s.C_NB = x.C_NB;
    } else {
      xi[i] = xi0 + c[i] * k[i - 1].xi_dot();
      R[i] = x.R_N + c[i] * k[i - 1].R_dot_N;
      s.C_NB = x.C_NB * adcs::so3_exp(c[i] * xi[i - 1].head<3>());
    }
    s.R_N = R[i];
    s.omega_BN_B = xi[i].head<3>();
    s.v_B = xi[i].tail<3>();
    if (sc.derivative(s, tau_c, tau_d, k[i]) != Status::ok) return false;
  }
  const Vec3 omega_bar = (xi[0].head<3>() + 2.0 * xi[1].head<3>() + 2.0 * xi[2].head<3>() +
                          xi[3].head<3>()) / 6.0;
  const Vec6 xi_new = xi0 + dt / 6.0 * (k[0].xi_dot() + 2.0 * k[1].xi_dot() +
                                        2.0 * k[2].xi_dot() + k[3].xi_dot());
  x.R_N += dt / 6.0 * (k[0].R_dot_N + 2.0 * k[1].R_dot_N + 2.0 * k[2].R_dot_N + k[3].R_dot_N);
  adcs::se3_spacecraft_attitude_step(x.C_NB, dt * omega_bar);
  x.omega_BN_B = xi_new.head<3>();
  x.v_B = xi_new.tail<3>();
  return true;
}

}  // namespace adcs_test
