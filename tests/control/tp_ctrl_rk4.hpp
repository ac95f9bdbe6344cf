#pragma once
// Test support: one step of seed 001's TP-CTRL closed loop as the spec's prototype integrates it
// (RK4 of the controller-model plant and the reference attitude σ_d together, the law's command
// held over the step), shared by the double and float tests of HybridAdaptive. Test code, not
// flight code.
#include "adcs/plant/vscmg_cluster.hpp"
#include "adcs/reference/sinusoidal_rate.hpp"

namespace adcs_test {

//! Advances the TP-CTRL state x and σ_d from t by h with the gimbal rates and wheel accelerations
//! u held; dσ_d/dt is the reference's (eq. (27) integrated with the plant, as the spec does).
inline void tp_ctrl_rk4_step(const adcs::VscmgCtrlPlant<4, 3>& plant, const adcs::SinusoidalRateReference& ref,
                             double t, double h, const adcs::Vec<7>& u, adcs::VscmgCtrlPlant<4, 3>::State& x,
                             adcs::Vec3& sigma_d) {
  using State = adcs::VscmgCtrlPlant<4, 3>::State;
  using adcs::Vec3;
  auto f = [&](double tt, const State& xs, const Vec3& sd, State& dx, Vec3& dsd) {
    plant.derivative(tt, xs, u, dx);
    dsd = ref.sigma_dot(tt, sd);
  };
  State k1, k2, k3, k4;
  Vec3 d1, d2, d3, d4;
  f(t, x, sigma_d, k1, d1);
  f(t + 0.5 * h, State(x + 0.5 * h * k1), Vec3(sigma_d + 0.5 * h * d1), k2, d2);
  f(t + 0.5 * h, State(x + 0.5 * h * k2), Vec3(sigma_d + 0.5 * h * d2), k3, d3);
  f(t + h, State(x + h * k3), Vec3(sigma_d + h * d3), k4, d4);
  x += h / 6.0 * (k1 + 2 * k2 + 2 * k3 + k4);
  sigma_d += h / 6.0 * (d1 + 2 * d2 + 2 * d3 + d4);
}

}  // namespace adcs_test
