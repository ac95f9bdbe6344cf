// What every unit of the C interface (include/adcs/c/adcs.h) shares: the status and policy ABI
// checks, the state layout (the C++ object at offset 0, a word written by init in the last four
// bytes, so a step on a state that init never wrote is refused instead of running on garbage),
// construction by placement new into the caller's storage, and the array conversions. One unit
// per family group (adcs_c.cpp: status, MRP PD, wheel allocation; adcs_c_ppc.cpp: seed 002;
// adcs_c_hybrid.cpp: seed 001), so a flight build compiles only the families it links. Private
// to src/c.
#pragma once

#include <cstdint>
#include <cstring>
#include <new>
#include <type_traits>

#include "adcs/c/adcs.h"
#include "adcs/core/failure_policy.hpp"
#include "adcs/core/status.hpp"
#include "adcs/core/types.hpp"

namespace adcs::c_api {

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

inline constexpr std::uint32_t kInitialised = 0x61646373u;  // "adcs": written by init, checked by step
inline constexpr std::size_t kTag = sizeof(std::uint32_t);

//! The header's size and alignment are exactly the C++ component's plus the init tag, rounded up
//! to the alignment, on this platform: a change of a component's layout must change the header
//! (an ABI change a C user sees), never overflow a caller's buffer.
template <class CState, class C>
constexpr bool holds() {
  constexpr std::size_t a = alignof(CState);
  return sizeof(CState) == (sizeof(C) + kTag + a - 1) / a * a && alignof(C) == a &&
         std::is_trivially_destructible_v<C>;  // re-init and abandoning a state need no destructor
}

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

//! Constructs C from `args` (its parameters, and for seed 001 its uploaded gains) in the caller's
//! state and tags it initialised; returns the construction status.
template <class C, class CState, class... Args>
adcs_status init(CState* state, const Args&... args) noexcept {
  C* c = ::new (static_cast<void*>(state->opaque)) C(args...);
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
inline bool policy(adcs_failure_policy v, FailurePolicy& out) noexcept {
  if (v != ADCS_FAILURE_SAFE_COMMAND && v != ADCS_FAILURE_HOLD_LAST) return false;
  out = static_cast<FailurePolicy>(v);
  return true;
}

}  // namespace adcs::c_api
