// Instantiates every flight template with concrete sizes and calls the functions a flight
// program would, so the Cortex-M7 compile check sees real code, not just declarations.
// Keep in step with include/adcs (one block per concept).
#include "adcs/adcs.hpp"

namespace adcs {
template class RigidBodyRw<4>;
template class VscmgFullPlant<4, 3>;
template class VscmgCtrlPlant<4, 3>;
template struct VscmgGeometry<4, 3>;
template class RwTorqueAllocator<4>;
template class MrpPd<4>;
template class HybridAdaptive<4, 3>;
template class FlexibleSpacecraft<2, 4>;
template class PrescribedPerformance<3>;
template class RbfLayer<6, 7>;
template class RbfCompensator<6, 7, 3>;
template class Eskf<27, 9, 9, 9>;
template class Pid<1>;
template class PartitionedEskf<18, 9, 9, 9, 6, 3>;
template class CompositeQuantizer<6>;
template Status saturate_then_quantize<6>(const Vec<6>&, const Vec<6>&, CompositeQuantizer<6>&, Vec<6>&,
                                          std::uint32_t*) noexcept;
template bool keep_psd<27>(Mat<27, 27>&) noexcept;
template Mat<7, 3> rbf_weight_step<7, 3>(const Mat<7, 3>&, const Vec<7>&, const Vec<3>&, const Vec<3>&, double,
                                         double) noexcept;
template class MrpPd<3>;
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
}  // namespace adcs

// A flight-style entry point that exercises the non-template functions.
extern "C" int adcs_target_smoke(const double* in, double* out) {
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
  const adcs::PpcNeuralParams pp{adcs::seed002_tracking_gains(), adcs::seed002_performance()};
  adcs::PpcNeural ppc(pp);
  adcs::AdaptiveTracking atc(adcs::AdaptiveTrackingParams{pp.gains});
  adcs::EulerTrackingMeasurement m;
  m.angles = sigma * 1e-3;
  const adcs::SinusoidalEulerReference eref;
  adcs::EulerTrackingCommand cmd;
  const adcs::Status s3 = ppc.step(m, eref.sample(in[3]), cmd);
  const adcs::Status s4 = atc.step(m, eref.sample(in[3]), cmd);
  out[1] = cmd.torque_B.sum();
  adcs::DragFreeDiscrete dfd;
  const adcs::Status s5 = adcs::drag_free_discretize(adcs::DragFreeParams{}, dfd);
  adcs::DragFreeEskf::Params ep;
  ep.A_d = dfd.A_d;
  ep.B_d = dfd.B_d;
  ep.B_e = dfd.B_e;
  ep.C_d = dfd.C_d;
  adcs::DragFreeEskf alg1(ep);
  adcs::SaturatedEsf alg2(adcs::SaturatedEsfParams{});
  adcs::DragFreeAdrc adrc(adcs::DragFreeAdrcParams{});
  adcs::Vec<9> u9 = adcs::Vec<9>::Zero();
  const adcs::Status s6 = adcs::worst(alg1.predict(u9), alg1.update(adcs::Vec<9>::Constant(in[5])));
  const adcs::Status s7 = adcs::worst(alg2.update(in[6], 0.0), adcs::fuse_axis(alg1, alg2, 0));
  const adcs::Status s8 = adrc.step(alg1.state(), adcs::Vec3::Zero(), adcs::Vec3::Zero(), u9);
  // seed 003: SE(3) tracking with both laws, then sat → Q.
  adcs::Se3ScenarioParams sp;
  adcs::Se3SpacecraftState target;
  const adcs::Status s9 = adcs::se3_target_initial_state(sp, target);
  const adcs::Se3SpacecraftState chaser = adcs::se3_chaser_initial_state(target, adcs::kSe3InitialPoses[0]);
  adcs::Se3DesiredState desired;
  const adcs::Status s10 = adcs::se3_desired_state(adcs::Se3Spacecraft(adcs::se3_target_params(sp)), target, sp, desired);
  adcs::PrescribedTimeSe3 ptc(adcs::PrescribedTimeSe3Params{}, adcs::se3_chaser_nominal_params(sp));
  adcs::FtsmcSe3 ftsmc(adcs::FtsmcSe3Params{}, adcs::se3_chaser_nominal_params(sp));
  adcs::CompositeQuantizer<6> quantizer(adcs::seed003_quantizer_params());
  adcs::Vec6 u6, u6c;
  const adcs::Status s11 = adcs::worst(ptc.step(chaser, desired, u6), ftsmc.step(chaser, desired, u6));
  const adcs::Status s12 = adcs::saturate_then_quantize<6>(u6, adcs::se3_actuator_limits(sp), quantizer, u6c);
  out[3] = u6c.sum() + adcs::se3_log(adcs::se3_exp(u6)).sum();
  out[2] = u9.sum() + adcs::upper_truncated_std_normal(in[7]).mean + adcs::fal(in[8], 0.5, 0.01);
  out[0] = Gd.sum() + F.sum() + F321.sum() + r.sigma_ddot.sum() + adcs::so3_exp(sigma).sum() +
           adcs::normalized_step_scale(in[4], 0.2);
  return static_cast<int>(s) + static_cast<int>(s2) + static_cast<int>(s3) + static_cast<int>(s4) +
         static_cast<int>(s5) + static_cast<int>(s6) + static_cast<int>(s7) + static_cast<int>(s8) +
         static_cast<int>(s9) + static_cast<int>(s10) + static_cast<int>(s11) + static_cast<int>(s12);
}
