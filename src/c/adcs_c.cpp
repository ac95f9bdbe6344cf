// The C interface (include/adcs/c/adcs.h) over the C++ components, first unit: the status helpers,
// the MRP PD law and the reaction-wheel allocation (the families of examples/c). No heap
// (placement new into the caller's storage), no exception (every C++ call used here is noexcept),
// no static state. Compiled for the host, the Cortex-M7 and the Cortex-M4F (CMakeLists.txt:
// adcs_c; cmake/TargetCheck.cmake), and the static_asserts below check the header's sizes on each.
// Seed 002's family is in adcs_c_ppc.cpp; the shared layout in c_api_common.hpp.
#include "adcs/c/adcs.h"

#include "adcs/actuator/rw_allocation.hpp"
#include "adcs/control/mrp_pd.hpp"
#include "c_api_common.hpp"

namespace adcs::c_api {
namespace {

static_assert(holds<adcs_mrp_pd4_state, MrpPd<4, double>>(), "ADCS_MRP_PD4_STATE_SIZE/_ALIGN");
static_assert(holds<adcs_mrp_pd4f_state, MrpPd<4, float>>(), "ADCS_MRP_PD4F_STATE_SIZE/_ALIGN");
static_assert(holds<adcs_rw_alloc4_state, RwTorqueAllocator<4, double>>(), "ADCS_RW_ALLOC4_STATE_SIZE/_ALIGN");
static_assert(holds<adcs_rw_alloc4f_state, RwTorqueAllocator<4, float>>(), "ADCS_RW_ALLOC4F_STATE_SIZE/_ALIGN");

template <class S, class CParams, class CState>
adcs_status mrp_pd_init(const CParams* cp, CState* state) noexcept {
  if (cp == nullptr || state == nullptr) return ADCS_STATUS_INVALID_PARAMETER;
  MrpPdParams<4, S> p;
  p.K = cp->K;
  p.P = from_rows(cp->P);
  p.J_rw_B = from_rows(cp->J_rw_B);
  p.G_s_B = from_rows(cp->G_s_B);
  p.J_s = from_array(cp->J_s);
  p.period_s = cp->period_s;
  if (!policy(cp->on_failure, p.on_failure)) p.K = unset_v<S>;  // refused by validate()
  return init<MrpPd<4, S>>(state, p);
}

template <class S, class CState, class CInput, class COutput>
adcs_status mrp_pd_step(CState* state, const CInput* ci, COutput* co) noexcept {
  MrpPd<4, S>* c = component<MrpPd<4, S>>(state);
  if (c == nullptr || ci == nullptr || co == nullptr) return ADCS_STATUS_INVALID_PARAMETER;
  MrpPdInput<4, S> in;
  in.state.sigma_BN = from_array(ci->sigma_BN);
  in.state.omega_BN_B = from_array(ci->omega_BN_B);
  in.Omega_rad_s = from_array(ci->Omega_rad_s);
  in.reference.sigma_RN = from_array(ci->sigma_RN);
  in.reference.omega_RN_N = from_array(ci->omega_RN_N);
  in.reference.domega_RN_N = from_array(ci->domega_RN_N);
  BodyTorqueT<S> out;
  const Status s = c->step(in, out);
  to_array(out.torque_B_Nm, co->torque_B_Nm);
  return static_cast<adcs_status>(s);
}

template <class S, class CParams, class CState>
adcs_status rw_alloc_init(const CParams* cp, CState* state) noexcept {
  if (cp == nullptr || state == nullptr) return ADCS_STATUS_INVALID_PARAMETER;
  RwAllocationParams<4, S> p;
  p.G_s_B = from_rows(cp->G_s_B);
  p.torque_limit = cp->torque_limit;
  return init<RwTorqueAllocator<4, S>>(state, p);
}

template <class S, class CState, class CInput, class COutput>
adcs_status rw_alloc_step(CState* state, const CInput* ci, COutput* co) noexcept {
  RwTorqueAllocator<4, S>* c = component<RwTorqueAllocator<4, S>>(state);
  if (c == nullptr || ci == nullptr || co == nullptr) return ADCS_STATUS_INVALID_PARAMETER;
  WheelTorques<4, S> out;
  const Status s = c->step(BodyTorqueT<S>{from_array(ci->torque_B_Nm)}, out);
  to_array(out.u_s_Nm, co->u_s_Nm);
  return static_cast<adcs_status>(s);
}

}  // namespace
}  // namespace adcs::c_api

extern "C" {


int adcs_status_usable(adcs_status s) {
  return s >= 0 && s <= ADCS_STATUS_REQUEST_NOT_MET && adcs::usable(static_cast<adcs::Status>(s));
}
const char* adcs_status_name(adcs_status s) {
  if (s < 0 || s > ADCS_STATUS_REQUEST_NOT_MET) return "unknown";
  return adcs::to_string(static_cast<adcs::Status>(s));
}

adcs_status adcs_mrp_pd4_init(const adcs_mrp_pd4_params* p, adcs_mrp_pd4_state* s) {
  return adcs::c_api::mrp_pd_init<double>(p, s);
}
adcs_status adcs_mrp_pd4_step(adcs_mrp_pd4_state* s, const adcs_mrp_pd4_input* in, adcs_mrp_pd4_output* out) {
  return adcs::c_api::mrp_pd_step<double>(s, in, out);
}
adcs_status adcs_mrp_pd4f_init(const adcs_mrp_pd4f_params* p, adcs_mrp_pd4f_state* s) {
  return adcs::c_api::mrp_pd_init<float>(p, s);
}
adcs_status adcs_mrp_pd4f_step(adcs_mrp_pd4f_state* s, const adcs_mrp_pd4f_input* in, adcs_mrp_pd4f_output* out) {
  return adcs::c_api::mrp_pd_step<float>(s, in, out);
}
adcs_status adcs_rw_alloc4_init(const adcs_rw_alloc4_params* p, adcs_rw_alloc4_state* s) {
  return adcs::c_api::rw_alloc_init<double>(p, s);
}
adcs_status adcs_rw_alloc4_step(adcs_rw_alloc4_state* s, const adcs_rw_alloc4_input* in, adcs_rw_alloc4_output* out) {
  return adcs::c_api::rw_alloc_step<double>(s, in, out);
}
adcs_status adcs_rw_alloc4f_init(const adcs_rw_alloc4f_params* p, adcs_rw_alloc4f_state* s) {
  return adcs::c_api::rw_alloc_init<float>(p, s);
}
adcs_status adcs_rw_alloc4f_step(adcs_rw_alloc4f_state* s, const adcs_rw_alloc4f_input* in, adcs_rw_alloc4f_output* out) {
  return adcs::c_api::rw_alloc_step<float>(s, in, out);
}

}  // extern "C"
