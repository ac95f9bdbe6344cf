#pragma once
// Step fixtures (bench/step_fixtures.hpp): rigid body + wheels and seed 001.
#include <cstdlib>

#include "adcs/actuator/rw_allocation.hpp"
#include "adcs/control/hybrid_adaptive.hpp"
#include "adcs/control/mrp_pd.hpp"
#include "adcs/core/signals.hpp"
#include "adcs/plant/vscmg_configurations.hpp"
#include "adcs/reference/sinusoidal_rate.hpp"
#include "step_fixtures_common.hpp"

namespace adcs::bench {

// ------------------------------------------------------------------ rigid body + wheels
//! MrpPd::step() (the controller of rigid-rw-mrp-pd).
struct MrpPdStep {
  MrpPd<4> ctrl{params()};
  MrpPd<4>::Input in;
  BodyTorque out;
  double k = 0.0;
  static MrpPdParams<4> params() {
    MrpPdParams<4> p;
    p.K = 1.44;
    p.P = Vec3(36, 32, 28).asDiagonal();
    p.J_rw_B = Vec3(900, 800, 600).asDiagonal();
    p.G_s_B = four_wheel_axes();
    p.J_s.setConstant(0.05);
    p.period_s = 0.1;  // [s] rigid-rw-mrp-pd's control_period_s (validated only)
    return p;
  }
  MrpPdStep() {
    in.state.sigma_BN << 0.1, -0.2, 0.3;
    in.state.omega_BN_B << 0.01, 0.002, -0.003;
    in.Omega_rad_s << 10, 20, 30, 40;
    in.reference.sigma_RN << 0.1, 0.2, -0.3;
  }
  void operator()() noexcept {
    in.state.sigma_BN(0) = 0.1 + 1e-9 * k;
    k += 1.0;
    escape(ctrl.step(in, out));
    escape(out.torque_B_Nm);
  }
};

//! RwTorqueAllocator::step() (precomputed pseudo-inverse + scaling).
struct RwAllocationStep {
  RwTorqueAllocator<4> alloc{params()};
  BodyTorque L{Vec3(0.05, -0.3, 0.1)};
  WheelTorques<4> us;
  static RwAllocationParams<4> params() {
    RwAllocationParams<4> p;
    p.G_s_B = four_wheel_axes();
    return p;
  }
  void operator()() noexcept {
    L.torque_B_Nm(0) += 1e-12;
    escape(alloc.step(L, us));
    escape(us.u_s_Nm);
  }
};

// ------------------------------------------------------------------ seed 001
//! HybridAdaptive::step() (M = 4 CMGs, N = 3 wheels): regressors, steering via LDLT of X Xᵀ,
//! adaptation with projection. Estimates reset every 4096 steps to stay near nominal.
struct HybridAdaptiveStep {
  HybridAdaptive<4, 3> ctrl;
  HybridAdaptive<4, 3>::Input in;
  HybridAdaptive<4, 3>::Output out;
  double k = 0.0;
  static HybridAdaptive<4, 3>::Params params(AdaptationStep a) {
    HybridAdaptive<4, 3>::Params p;
    p.nominal = pyramid_4cmg_3rw_nominal();
    p.adaptation_step = a;
    return p;
  }
  explicit HybridAdaptiveStep(AdaptationStep a = AdaptationStep::explicit_euler) : ctrl(params(a)) {
    in.state.sigma_BN << 0.3, -0.2, 0.1;
    in.state.omega_BN_B << 0.01, -0.02, 0.015;
    in.actuators.gamma_rad << 0.1, -0.2, 0.15, 0.05;
    in.reference = SinusoidalRateReference{}.sample(123.0, Vec3(0.29, -0.21, 0.1));
  }
  void operator()() noexcept {
    in.actuators.gamma_rad(0) = 0.1 + 1e-9 * k;
    k += 1.0;
    escape(ctrl.step(in, out));
    escape(out);
    if (static_cast<long>(k) % 4096 == 0) ctrl.reset();
  }
};
struct HybridAdaptiveNormalizedStep : HybridAdaptiveStep {
  HybridAdaptiveNormalizedStep() : HybridAdaptiveStep(AdaptationStep::normalized) {}
};

}  // namespace adcs::bench
