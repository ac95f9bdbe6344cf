// The C interface (include/adcs/c/adcs.h) over the C++ components: each C state holds the C++
// object at offset 0 and a word written by init in its last four bytes, so a step on a state that
// init never wrote is refused instead of running on garbage. No heap (placement new into the
// caller's storage), no exception (every C++ call used here is noexcept), no static state.
// Compiled for the host, the Cortex-M7 and the Cortex-M4F (CMakeLists.txt: adcs_c;
// cmake/TargetCheck.cmake), and the static_asserts below check the header's sizes on each.
#include "adcs/c/adcs.h"

#include <cstdint>
#include <cstring>
#include <new>
#include <type_traits>

#include "adcs/actuator/rw_allocation.hpp"
#include "adcs/control/mrp_pd.hpp"

namespace adcs::c_api {
namespace {

// The numeric values the header promises are the C++ enumerators' (core/status.hpp).
static_assert(ADCS_STATUS_OK == static_cast<int>(Status::ok), "status ABI");
static_assert(ADCS_STATUS_NON_FINITE_INPUT == static_cast<int>(Status::non_finite_input), "status ABI");
static_assert(ADCS_STATUS_OUT_OF_RANGE == static_cast<int>(Status::out_of_range), "status ABI");
static_assert(ADCS_STATUS_SINGULAR == static_cast<int>(Status::singular), "status ABI");
static_assert(ADCS_STATUS_ILL_CONDITIONED == static_cast<int>(Status::ill_conditioned), "status ABI");
static_assert(ADCS_STATUS_CONSTRAINT_VIOLATED == static_cast<int>(Status::constraint_violated), "status ABI");
static_assert(ADCS_STATUS_SATURATED == static_cast<int>(Status::saturated), "status ABI");
static_assert(ADCS_STATUS_NOT_CONVERGED == static_cast<int>(Status::not_converged), "status ABI");
static_assert(ADCS_STATUS_INVALID_PARAMETER == static_cast<int>(Status::invalid_parameter), "status ABI");
static_assert(ADCS_STATUS_REQUEST_NOT_MET == static_cast<int>(Status::request_not_met), "status ABI");
static_assert(ADCS_FAILURE_SAFE_COMMAND == static_cast<int>(FailurePolicy::safe_command), "policy ABI");
static_assert(ADCS_FAILURE_HOLD_LAST == static_cast<int>(FailurePolicy::hold_last), "policy ABI");

constexpr std::uint32_t kInitialised = 0x61646373u;  // "adcs": written by init, checked by step
constexpr std::size_t kTag = sizeof(std::uint32_t);

//! The header's size and alignment are exactly the C++ component's plus the init tag, rounded up
//! to the alignment, on this platform: a change of a component's layout must change the header
//! (an ABI change a C user sees), never overflow a caller's buffer.
template <class CState, class C>
constexpr bool holds() {
  constexpr std::size_t a = alignof(CState);
  return sizeof(CState) == (sizeof(C) + kTag + a - 1) / a * a && alignof(C) == a &&
         std::is_trivially_destructible_v<C>;  // re-init and abandoning a state need no destructor
}
static_assert(holds<adcs_mrp_pd4_state, MrpPd<4, double>>(), "ADCS_MRP_PD4_STATE_SIZE/_ALIGN");
static_assert(holds<adcs_mrp_pd4f_state, MrpPd<4, float>>(), "ADCS_MRP_PD4F_STATE_SIZE/_ALIGN");
static_assert(holds<adcs_rw_alloc4_state, RwTorqueAllocator<4, double>>(), "ADCS_RW_ALLOC4_STATE_SIZE/_ALIGN");
static_assert(holds<adcs_rw_alloc4f_state, RwTorqueAllocator<4, float>>(), "ADCS_RW_ALLOC4F_STATE_SIZE/_ALIGN");

template <class CState>
void write_tag(CState& s, std::uint32_t tag) noexcept {
  std::memcpy(s.opaque + sizeof(s.opaque) - kTag, &tag, kTag);
}
template <class CState>
bool initialised(const CState& s) noexcept {
  std::uint32_t tag = 0;
  std::memcpy(&tag, s.opaque + sizeof(s.opaque) - kTag, kTag);
  return tag == kInitialised;
}

template <class C, class CState>
adcs_status init(const typename C::Params& p, CState* state) noexcept {
  C* c = ::new (static_cast<void*>(state->opaque)) C(p);
  write_tag(*state, kInitialised);
  return static_cast<adcs_status>(c->status());
}

template <class C, class CState>
C* component(CState* state) noexcept {
  if (state == nullptr || !initialised(*state)) return nullptr;
  return std::launder(reinterpret_cast<C*>(state->opaque));
}

// Row-major C arrays to Eigen (column-major) matrices.
template <int R, int K, class S>
Mat<R, K, S> from_rows(const S (&a)[R][K]) noexcept {
  return Eigen::Map<const Eigen::Matrix<S, R, K, (R > 1 && K > 1) ? Eigen::RowMajor : Eigen::ColMajor>>(&a[0][0]);
}
template <int N, class S>
Vec<N, S> from_array(const S (&a)[N]) noexcept {
  return Eigen::Map<const Vec<N, S>>(a);
}
template <int N, class S>
void to_array(const Vec<N, S>& v, S (&a)[N]) noexcept {
  Eigen::Map<Vec<N, S>> m(a);
  m = v;
}

// An out-of-range policy value refuses the set (as a NaN gain does), never an invalid enum.
bool policy(adcs_failure_policy v, FailurePolicy& out) noexcept {
  if (v != ADCS_FAILURE_SAFE_COMMAND && v != ADCS_FAILURE_HOLD_LAST) return false;
  out = static_cast<FailurePolicy>(v);
  return true;
}

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
  return init<MrpPd<4, S>>(p, state);
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
  return init<RwTorqueAllocator<4, S>>(p, state);
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
