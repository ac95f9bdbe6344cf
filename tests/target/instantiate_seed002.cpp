// Cortex-M7 instantiation unit 2 of 5 (see instantiate_attitude.cpp): seed 002, the flexible
// spacecraft, prescribed performance, the RBF network and both Euler-angle tracking laws.
#include "adcs/adapt/ppc.hpp"
#include "adcs/adapt/rbf_compensator.hpp"
#include "adcs/adapt/rbf_network.hpp"
#include "adcs/control/adaptive_tracking.hpp"
#include "adcs/control/ppc_neural.hpp"
#include "adcs/plant/flexible_configurations.hpp"
#include "adcs/plant/flexible_spacecraft.hpp"
#include "adcs/reference/sinusoidal_euler.hpp"

namespace adcs {
template class FlexibleSpacecraft<2, 4>;
template class PrescribedPerformance<3>;
template class RbfLayer<6, 7>;
template class RbfCompensator<6, 7, 3>;
template Mat<7, 3> rbf_weight_step<7, 3>(const Mat<7, 3>&, const Vec<7>&, const Vec<3>&, const Vec<3>&, double,
                                         double) noexcept;
}  // namespace adcs

extern "C" int adcs_target_smoke_seed002(const double* in, double* out) {
  const adcs::Vec3 sigma(in[0], in[1], in[2]);
  const adcs::PpcNeuralParams pp{adcs::seed002_tracking_gains(), adcs::seed002_performance()};
  adcs::PpcNeural ppc(pp);
  adcs::AdaptiveTracking atc(adcs::AdaptiveTrackingParams{pp.gains});
  adcs::EulerTrackingInput m;
  m.state.theta_BN_rad = sigma * 1e-3;
  const adcs::SinusoidalEulerReference eref;
  m.reference = eref.sample(in[3]);
  adcs::BodyTorque cmd;
  const adcs::Status s3 = ppc.step(m, cmd);
  const adcs::Status s4 = atc.step(m, cmd);
  out[1] = cmd.torque_B_Nm.sum();
  return static_cast<int>(s3) + static_cast<int>(s4);
}
