// Cortex-M7 instantiation unit 4 of 5 (see instantiate_attitude.cpp): seed 004's flight filters
// and laws as the drag-free sample runs them: Algorithm 1 as two U-D blocks, Algorithm 2, fusion,
// ADRC, the PID baseline (the Joseph-form reference is host-only: tests and bench).
#include "adcs/control/adrc.hpp"
#include "adcs/control/pid.hpp"
#include "adcs/estimate/drag_free_eskf.hpp"
#include "adcs/estimate/fusion.hpp"
#include "adcs/estimate/partitioned_eskf.hpp"
#include "adcs/estimate/saturated_esf.hpp"
#include "adcs/math/truncated_normal.hpp"
#include "adcs/plant/drag_free.hpp"

namespace adcs {
template class Pid<1>;
template class PartitionedFilter<EskfUd<18, 9, 9, 6, kDragFreeAttitudeNoiseColumns>,
                                 EskfUd<9, 9, 9, 3, kDragFreeTranslationNoiseColumns>>;
}  // namespace adcs

extern "C" int adcs_target_smoke_seed004(const double* in, double* out) {
  adcs::DragFreeDiscrete dfd;
  const adcs::Status s5 = adcs::drag_free_discretize(adcs::DragFreeParams{}, dfd);
  adcs::DragFreeEskf::Params ep;
  ep.A_d = dfd.A_d;
  ep.B_d = dfd.B_d;
  ep.B_e = dfd.B_e;
  ep.C_d = dfd.C_d;
  ep.period_s = adcs::DragFreeParams{}.period_s;
  adcs::DragFreeEskf alg1(ep);
  adcs::SaturatedEsf alg2(adcs::SaturatedEsfParams{});
  adcs::DragFreeAdrc adrc(adcs::DragFreeAdrcParams{});
  adcs::DragFreeEskf::Input e1_in;  // u = 0, Δf̄ = 0
  e1_in.y.setConstant(in[5]);
  adcs::DragFreeEskf::Output e1_out;
  const adcs::Status s6 = alg1.step(e1_in, e1_out);
  adcs::SaturatedEsf::Output e2_out;
  const adcs::Status s7 =
      adcs::worst(alg2.step(adcs::SaturatedEsfInput{0.0, 0.0, in[6], 0.0}, e2_out), adcs::fuse_axis(alg1, alg2, 0));
  adcs::DragFreeActuation act;
  const adcs::Status s8 = adrc.step(adcs::DragFreeAdrcInput{alg1.state(), adcs::Vec3::Zero(), adcs::Vec3::Zero()}, act);
  adcs::Pid<3> pid(adcs::PidParams<3>{});
  adcs::PidOutput<3> pid_out;
  const adcs::Status s9 = pid.step(adcs::PidInput<3>{act.F_Csc_N, act.T_Csc_Nm}, pid_out);
  out[2] = act.stacked().sum() + pid_out.u.sum() + adcs::upper_truncated_std_normal(in[7]).mean +
           adcs::fal(in[8], 0.5, 0.01);
  return static_cast<int>(s5) + static_cast<int>(s6) + static_cast<int>(s7) + static_cast<int>(s8) +
         static_cast<int>(s9);
}
