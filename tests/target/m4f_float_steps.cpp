// Cortex-M4F float check (issue 19): the float instances of the attitude chain and seeds 001-004
// that have no float C family (seed 002's and seed 003's baselines, the ESO-based ADRC flown on
// seed 002's vehicle, seed 003's actuation stage, seed 004's U-D kernels, Algorithms 1 and 2 and
// its PID) compiled for a single-precision FPU (-mcpu=cortex-m4 -mfpu=fpv4-sp-d16
// -mfloat-abi=hard) with -Wdouble-promotion -Wfloat-conversion -Werror. tools/check-float-calls.py
// then walks the call graph of this object from the adcs_m4f_* entry points and fails if any
// software-double helper (__aeabi_d*, __aeabi_*2d) or double libm function (sin, cos, sqrt, atan,
// ...) is reachable: on this FPU a single double operation is a ~60-cycle library call. The laws
// with a float C family are walked in the cross C library (target_m4f_c_api_no_double); every float
// class is in the clang whole-class check (ADCS_M4F_WHOLE_CLASS).
#include <new>

#include "adcs/actuator/quantizer.hpp"
#include "adcs/actuator/rw_allocation.hpp"
#include "adcs/control/hybrid_adaptive.hpp"
#include "adcs/control/adaptive_tracking.hpp"
#include "adcs/control/eso_adrc_attitude.hpp"
#include "adcs/control/ftsmc_se3.hpp"
#include "adcs/control/mrp_pd.hpp"
#include "adcs/control/ppc_neural.hpp"
#include "adcs/control/prescribed_time_se3.hpp"
#include "adcs/estimate/drag_free_eskf.hpp"
#include "adcs/estimate/saturated_esf.hpp"
#include "adcs/control/adrc.hpp"
#include "adcs/math/sparse_rows.hpp"
#include "adcs/math/ud.hpp"

namespace adcs {
// The laws with a float C family (src/c: MRP PD, the wheel allocation, seed 002's PPATC, seed 001,
// seed 003's BsPdTC, seed 004's ADRC) are compiled to code for this FPU once, in the cross C library
// (tests/target/CMakeLists.txt, adcs_c_target), and ctest target_m4f_c_api_no_double walks their
// init and step entry points there. Here they are in the clang whole-class check only (every
// member, -Wdouble-promotion -Wfloat-conversion -Werror): compiled to code in this unit as well,
// they were ~25 arm-none-eabi-g++ CPU-s of a second copy (docs/DECISIONS.md, "CI under 20
// minutes", item 27).
#ifdef ADCS_M4F_WHOLE_CLASS
template class MrpPd<4, float>;
template class RwTorqueAllocator<4, float>;
template class PpcNeuralT<float>;
template class PrescribedTimeSe3T<float>;
// Seed 001: its constructor runs the design in double on purpose (pole placement, Lyapunov solve:
// software double once at start-up); the C family builds the law from ground-designed gains.
template class HybridAdaptive<4, 3, float>;
// Seed 004's ADRC (Han's fal: powf) with the Fig. 9 PID inside, constructor included.
template class DragFreeAdrcT<float>;
#endif
// Seed 002's baseline (its constructor is float too: an LLT of J).
template class AdaptiveTrackingT<float>;
// Seed 002's vehicle with the ESO-based ADRC (the cross pairing): its constructor forms the
// observer gains in float (expf), so it is checked too.
template class EsoAdrcAttitudeT<float>;
// Seed 003's baseline, constructor included (an LDLT of J0 and two powf for S's l1, l2).
template class FtsmcSe3T<float>;
// Seed 003's actuation stage (sat -> Q), constructor included (powf/logf of the level table).
template class SaturatedQuantizer<6, float>;
// Seed 004's Algorithm 2 (one accelerometer axis), constructor included (an LDLT of P_0): its
// truncated-normal moments in float (erfcf, expf, sqrtf).
template class SaturatedEsfT<float>;
template class Pid<3, float>;
}  // namespace adcs

using AtcF = adcs::AdaptiveTrackingT<float>;
using EsoF = adcs::EsoAdrcAttitudeT<float>;
using FtsF = adcs::FtsmcSe3T<float>;
using SatQF = adcs::SaturatedQuantizer<6, float>;
using EsfF = adcs::SaturatedEsfT<float>;
using PidF = adcs::Pid<3, float>;
// Seed 004's U-D kernels (math/ud.hpp, math/sparse_rows.hpp) at the attitude block's size (18
// states, 12 noise columns): the first part of seed 004 in float; its filters are still double.
using UdF = adcs::UdFactors<18, float>;
using SparseF = adcs::SparseRows<18, 18, float>;
// Seed 004's Algorithm 1 in U-D form, float (DragFreeEskfT<float>): its step here, the whole
// class (constructor included) in the clang whole-class check.
using EskfF = adcs::DragFreeEskfT<float>;

// The step paths, each behind a C entry point (the roots of the call-graph check).
extern "C" int adcs_m4f_adaptive_tracking_step(AtcF* c, const AtcF::Input* in, AtcF::Output* out) {
  return static_cast<int>(c->step(*in, *out));
}
extern "C" int adcs_m4f_eso_adrc_attitude_step(EsoF* c, const EsoF::Input* in, EsoF::Output* out) {
  return static_cast<int>(c->step(*in, *out));
}
extern "C" void adcs_m4f_eso_adrc_attitude_init(EsoF* c, const EsoF::Params* p) { ::new (static_cast<void*>(c)) EsoF(*p); }
extern "C" int adcs_m4f_ftsmc_se3_step(FtsF* c, const FtsF::Input* in, FtsF::Output* out) {
  return static_cast<int>(c->step(*in, *out));
}
extern "C" void adcs_m4f_ftsmc_se3_init(FtsF* c, const FtsF::Params* p) { ::new (static_cast<void*>(c)) FtsF(*p); }
extern "C" int adcs_m4f_saturated_quantizer_step(SatQF* c, const SatQF::Input* in, SatQF::Output* out) {
  return static_cast<int>(c->step(*in, *out));
}
extern "C" void adcs_m4f_saturated_quantizer_init(SatQF* c, const SatQF::Params* p) { ::new (static_cast<void*>(c)) SatQF(*p); }
extern "C" int adcs_m4f_saturated_esf_step(EsfF* f, const EsfF::Input* in, EsfF::Output* out) {
  return static_cast<int>(f->step(*in, *out));
}
extern "C" void adcs_m4f_saturated_esf_init(EsfF* f, const EsfF::Params* p) { ::new (static_cast<void*>(f)) EsfF(*p); }
extern "C" int adcs_m4f_pid_step(PidF* c, const PidF::Input* in, PidF::Output* out) {
  return static_cast<int>(c->step(*in, *out));
}
extern "C" int adcs_m4f_ud_factorize(const adcs::Mat<18, 18, float>* P, UdF* out) {
  return adcs::ud_factorize(*P, *out) ? 1 : 0;
}
extern "C" void adcs_m4f_mwgs_ud(adcs::Mat<18, 30, float>* W, const Eigen::Matrix<float, 1, 30>* w, UdF* out) {
  adcs::mwgs_ud(*W, *w, *out);
}
extern "C" void adcs_m4f_agee_turner_update(UdF* f, float c, adcs::Vec<18, float>* a) {
  adcs::agee_turner_update(*f, c, *a);
}
extern "C" float adcs_m4f_bierman_update(UdF* f, const adcs::Vec<18, float>* fvec, float r, int first,
                                         adcs::Vec<18, float>* k) {
  return adcs::bierman_update(*f, *fvec, r, first, *k);
}
extern "C" void adcs_m4f_sparse_propagate(const SparseF* A, const UdF* f, adcs::Mat<18, 18, float>* out) {
  *out = A->mul_by_transpose(adcs::Mat<18, 18, float>(f->U.transpose()));
}
extern "C" int adcs_m4f_drag_free_eskf_step(EskfF* f, const EskfF::Input* in, EskfF::Output* out) {
  return static_cast<int>(f->step(*in, *out));
}
// Its constructor (the parameter check: LDLT/LLT of S, R, P_0 in float, the coupling check on the
// 27-state matrices, the U-D factorisations) is compiled to code only by the whole-class check
// below: here it cost 46 arm-none-eabi-g++ CPU-s (the step 36), measured alone.
#ifdef ADCS_M4F_WHOLE_CLASS
template class adcs::EskfUd<18, adcs::kDragFreeInputs, adcs::kDragFreeInputs, 6, adcs::kDragFreeAttitudeNoiseColumns, float>;
template class adcs::EskfUd<9, adcs::kDragFreeInputs, adcs::kDragFreeInputs, 3, adcs::kDragFreeTranslationNoiseColumns, float>;
template class adcs::PartitionedFilter<
    adcs::EskfUd<18, adcs::kDragFreeInputs, adcs::kDragFreeInputs, 6, adcs::kDragFreeAttitudeNoiseColumns, float>,
    adcs::EskfUd<9, adcs::kDragFreeInputs, adcs::kDragFreeInputs, 3, adcs::kDragFreeTranslationNoiseColumns, float>>;
extern "C" void adcs_m4f_drag_free_eskf_init(EskfF* f, const EskfF::Params* p) { ::new (static_cast<void*>(f)) EskfF(*p); }
#endif
