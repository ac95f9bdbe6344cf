// Cortex-M4F float check (issue 19): the float instances of the attitude chain compiled for a
// single-precision FPU (-mcpu=cortex-m4 -mfpu=fpv4-sp-d16 -mfloat-abi=hard) with
// -Wdouble-promotion -Wfloat-conversion -Werror. tools/check-float-calls.py then walks the call
// graph of this object from the adcs_m4f_* entry points and fails if any software-double helper
// (__aeabi_d*, __aeabi_*2d) or double libm function (sin, cos, sqrt, atan, ...) is reachable: on
// this FPU a single double operation is a ~60-cycle library call.
#include "adcs/actuator/rw_allocation.hpp"
#include "adcs/control/mrp_pd.hpp"

namespace adcs {
template class MrpPd<4, float>;
template class RwTorqueAllocator<4, float>;
}  // namespace adcs

using PdF = adcs::MrpPd<4, float>;
using AllocF = adcs::RwTorqueAllocator<4, float>;

// The step paths, each behind a C entry point (the roots of the call-graph check).
extern "C" int adcs_m4f_mrp_pd_step(PdF* c, const PdF::Input* in, PdF::Output* out) {
  return static_cast<int>(c->step(*in, *out));
}
extern "C" int adcs_m4f_rw_allocation_step(const AllocF* a, const AllocF::Input* in, AllocF::Output* out) {
  return static_cast<int>(a->step(*in, *out));
}
