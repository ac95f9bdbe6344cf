#pragma once
// Step fixtures (bench/step_fixtures.hpp): seed 002's Euler-angle tracking laws.
#include "adcs/control/adaptive_tracking.hpp"
#include "adcs/control/ppc_neural.hpp"
#include "adcs/plant/flexible_configurations.hpp"  // seed002_tracking_gains()
#include "adcs/reference/sinusoidal_euler.hpp"
#include "step_fixtures_common.hpp"

namespace adcs::bench {

// ------------------------------------------------------------------ seed 002
//! One Euler-angle law step (PPATC or ATC) near the scenario's initial state, time and angles
//! moving: kinematics, (funnel transform,) RBF layer, adaptation.
template <class Law>
struct EulerTrackingStep {
  Law law;
  SinusoidalEulerReference ref;
  typename Law::Input in;
  typename Law::Output out;
  double k = 0.0;
  explicit EulerTrackingStep(const typename Law::Params& p) : law(p) {
    in.state.theta_BN_rad = Vec3(0.25, 0.15, -0.20) * (3.14159265358979 / 180.0);
    in.state.omega_BN_B = Vec3(2e-4, 1e-4, -3e-4);
  }
  void operator()() noexcept {
    in.t_s = 1e-9 * k;
    in.state.theta_BN_rad(0) += 1e-15;
    k += 1.0;
    in.reference = ref.sample(in.t_s);
    escape(law.step(in, out));
    escape(out.torque_B_Nm);
    if (static_cast<long>(k) % 4096 == 0) law.reset();
  }
};
struct FlexiblePPCStep : EulerTrackingStep<PpcNeural> {
  FlexiblePPCStep() : EulerTrackingStep({seed002_tracking_gains(), seed002_performance()}) {}
};
struct AdaptiveTrackingStep : EulerTrackingStep<AdaptiveTracking> {
  AdaptiveTrackingStep() : EulerTrackingStep({seed002_tracking_gains()}) {}
};

}  // namespace adcs::bench
