// Cortex-M7 instantiation unit 1 of 5 (cmake/TargetCheck.cmake, -fsyntax-only): attitude math, the rigid and
// VSCMG plants, wheel allocation, CMG steering and the seed 001 laws, with concrete sizes, and a
// flight-style entry point calling the non-template functions, so the compile check sees real
// code, not just declarations. The five units together instantiate every flight template;
// keep them in step with include/adcs (one block per concept). Split in five so that the two
// cores share what was one 600-second translation unit.
#include "adcs/actuator/limits.hpp"
#include "adcs/actuator/rw_allocation.hpp"
#include "adcs/actuator/saturation.hpp"
#include "adcs/actuator/steering.hpp"
#include "adcs/actuator/vscmg_steering.hpp"
#include "adcs/adapt/normalized_step.hpp"
#include "adcs/adapt/projection.hpp"
#include "adcs/control/hybrid_adaptive.hpp"
#include "adcs/control/mrp_pd.hpp"
#include "adcs/core/signals.hpp"
#include "adcs/math/euler.hpp"
#include "adcs/math/lyapunov.hpp"
#include "adcs/math/mrp.hpp"
#include "adcs/math/pinv.hpp"
#include "adcs/math/place.hpp"
#include "adcs/math/so3.hpp"
#include "adcs/plant/rigid_body_rw.hpp"
#include "adcs/plant/vscmg_cluster.hpp"
#include "adcs/plant/vscmg_configurations.hpp"
#include "adcs/reference/sinusoidal_rate.hpp"

namespace adcs {
template class RigidBodyRw<4>;
template class VscmgFullPlant<4, 3>;
template class VscmgCtrlPlant<4, 3>;
template struct VscmgGeometry<4, 3>;
template class RwTorqueAllocator<4>;
template class Saturation<7>;
template class VscmgSteering<4, 3>;
template class MrpPd<4>;
template class MrpPd<3>;
template class HybridAdaptive<4, 3>;
template Status right_pinv_solve<3, 7>(const Mat<3, 7>&, const Vec<3>&, Vec<7>&, PinvInfo*) noexcept;
template Status right_pinv<3, 4>(const Mat<3, 4>&, Mat<4, 3>&, PinvInfo*) noexcept;
template Status damped_right_pinv_solve<3, 7>(const Mat<3, 7>&, const Vec<3>&, Vec<7>&,
                                              const DampingParams&, PinvInfo*) noexcept;
template Status solve_continuous_lyapunov<6>(const Mat<6, 6>&, const Mat<6, 6>&, Mat<6, 6>&) noexcept;
template Status solve_continuous_lyapunov<12>(const Mat<12, 12>&, const Mat<12, 12>&,
                                              Mat<12, 12>&) noexcept;
template Status place_double_integrator<3>(const AxisPoles<3>&, Mat<3, 6>&) noexcept;
template Status smooth_projection<6>(const Vec<6>&, const Vec<6>&, const ProjectionParams&, Vec<6>&,
                                     bool*) noexcept;
template Status smooth_projection<3>(const Vec<3>&, const Vec<3>&, const ProjectionParams&, Vec<3>&,
                                     bool*) noexcept;
template bool radial_safeguard<6>(Vec<6>&, double) noexcept;
template int saturate_each<7>(Vec<7>&, const Vec<7>&) noexcept;
template VscmgDeviation<4, 3> rigid_mounting_deviation<4, 3>(const VscmgGeometry<4, 3>&,
                                                            const Mat<3, 4>&, const Mat<3, 3>&) noexcept;
template Status steer<7>(const Mat<3, 7>&, const Vec3&, const SteeringParams&, Vec<7>&,
                         SteeringInfo*) noexcept;
template Status steer_escape<4>(const Mat<3, 4>&, const Vec3&, const EscapeSteeringParams&, double, Vec<4>&,
                                SteeringInfo*) noexcept;
template struct VscmgGeometry<4, 0>;
template Status set_cmg_pyramid<4, 0>(double, double, VscmgGeometry<4, 0>&) noexcept;
template Status wheel_pyramid_axes<4>(double, Mat<3, 4>&) noexcept;
template Status limit_wheel_torques<4>(const ActuatorLimits<0, 4>&, const Vec<4>&, Vec<4>&, LimitReport*) noexcept;
template Status limit_vscmg_command<4, 3>(const ActuatorLimits<4, 3>&, const Vec<3>&, const Vec<3>&, Vec<7>&,
                                          LimitReport*) noexcept;
template Status limit_vscmg_command<4, 0>(const ActuatorLimits<4, 0>&, const Vec<0>&, const Vec<0>&, Vec<4>&,
                                          LimitReport*) noexcept;
}  // namespace adcs

// A flight-style entry point that exercises the non-template attitude functions.
extern "C" int adcs_target_smoke_attitude(const double* in, double* out) {
  const adcs::Vec3 sigma(in[0], in[1], in[2]);
  const adcs::Mat3 C = adcs::mrp_to_dcm(sigma);
  const adcs::Vec3 back = adcs::dcm_to_mrp(C);
  adcs::Mat3 F;
  const adcs::Status s = adcs::euler123_F(adcs::dcm_to_euler123(C), F);
  const adcs::Mat3 Gd = adcs::mrp_G_dot(sigma, back) + adcs::mrp_G_inv(sigma) +
                        adcs::euler123_G_dot(back, sigma) + adcs::euler321_G(back);
  adcs::Mat3 F321;
  const adcs::Status s2 = adcs::euler321_F(adcs::dcm_to_euler321(C), F321);
  const adcs::SinusoidalRateReference ref;
  const adcs::MrpReferenceSample r = ref.sample(in[3], sigma);
  // The signal views (core/signals.hpp) and their conversions.
  const adcs::AttitudeState x{sigma, back};
  const adcs::AttitudeStateEuler123 xe = adcs::to_euler123(x);
  const adcs::AttitudeStateQuaternion xq = adcs::to_quaternion(adcs::to_mrp(xe));
  const adcs::AttitudeReference ar = adcs::to_attitude_reference(r);
  adcs::EulerReferenceSample er;
  const adcs::Status s3 = adcs::to_euler_reference(ar, er);
  out[0] = Gd.sum() + F.sum() + F321.sum() + r.sigma_ddot.sum() + adcs::so3_exp(sigma).sum() +
           adcs::normalized_step_scale(in[4], 0.2) + adcs::to_mrp(xq).sigma_BN.sum() +
           adcs::to_mrp_reference(ar).sigma_ddot.sum() + er.angles_ddot.sum();
  return static_cast<int>(s) + static_cast<int>(s2) + static_cast<int>(s3);
}
