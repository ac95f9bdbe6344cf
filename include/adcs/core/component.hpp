#pragma once
// The one shape of every flight component: controller, estimator, actuation stage (issue 17).
// Checked at compile time with the C++17 detection idiom, as manif checks its minimal API, so that
// anything built per component (no-allocation tests, fuzzers, benchmarks, instruction counts,
// target replays) is written once over a list of component types:
//
//   struct C {
//     using Params = ...; using Input = ...; using Output = ...; using Diagnostics = ...;
//     explicit C(const Params&) noexcept;
//     Status status() const noexcept;        // ok, or invalid_parameter (checked at construction)
//     void reset() noexcept;                 // back to the state after construction
//     S period_s() const noexcept;           // [s] the sample period the component runs at (S: its
//                                            // scalar, double unless it is a float instance); 0 for a
//                                            // memoryless actuation stage (allocation, saturation,
//                                            // steering), which runs whenever the law feeding it does
//     [[nodiscard]] Status step(const Input&, Output&, Diagnostics* = nullptr) noexcept;
//   };
//
// One failure semantics for all (docs/FAILURE-POLICY.md): a step whose status is not usable()
// writes the component's failure output and leaves its internal state untouched. The failure
// output is the safe command for a law (zero torque, wrench, rates; or the last good command
// under FailurePolicy::hold_last), zero for an actuation stage (the actuators idle), and the
// current estimate for an estimator (a rejected measurement leaves the prediction: the filter
// coasts). One documented exception: a steering stage's request_not_met is written() — the
// escape law's bounded command, which is how it leaves a singularity — and is output as such.
// Diagnostics hold what the step computed before it stopped: after a failed step their content
// is partial and unspecified (the status says what happened).
//
// Usage: ADCS_ASSERT_COMPONENT(MyLaw); right after the class, so a component that drifts from the
// shape fails to compile with a message naming what is missing.
#include <type_traits>
#include <utility>

#include "adcs/core/status.hpp"

namespace adcs {
namespace detail {

template <class...>
using void_t = void;

template <class T, class = void>
struct has_types : std::false_type {};
template <class T>
struct has_types<T, void_t<typename T::Params, typename T::Input, typename T::Output, typename T::Diagnostics>>
    : std::true_type {};

template <class T, class = void>
struct has_status : std::false_type {};
template <class T>
struct has_status<T, void_t<decltype(std::declval<const T&>().status())>>
    : std::bool_constant<std::is_same_v<decltype(std::declval<const T&>().status()), Status> &&
                         noexcept(std::declval<const T&>().status())> {};

template <class T, class = void>
struct has_reset : std::false_type {};
template <class T>
struct has_reset<T, void_t<decltype(std::declval<T&>().reset())>>
    : std::bool_constant<noexcept(std::declval<T&>().reset())> {};

template <class T, class = void>
struct has_period : std::false_type {};
template <class T>
struct has_period<T, void_t<decltype(std::declval<const T&>().period_s())>>
    : std::bool_constant<std::is_floating_point_v<decltype(std::declval<const T&>().period_s())> &&
                         noexcept(std::declval<const T&>().period_s())> {};

//! The call the concept is about, spelled once: step(const Input&, Output&, Diagnostics*).
template <class T>
using step_call_t = decltype(std::declval<T&>().step(std::declval<const typename T::Input&>(),
                                                     std::declval<typename T::Output&>(),
                                                     std::declval<typename T::Diagnostics*>()));

template <class T, class = void>
struct has_step : std::false_type {};
template <class T>
struct has_step<T, void_t<step_call_t<T>>>
    : std::bool_constant<std::is_same_v<step_call_t<T>, Status> &&
                         noexcept(std::declval<T&>().step(std::declval<const typename T::Input&>(),
                                                          std::declval<typename T::Output&>(),
                                                          std::declval<typename T::Diagnostics*>()))> {};

template <class T, class = void>
struct has_step_without_diagnostics : std::false_type {};
template <class T>
struct has_step_without_diagnostics<
    T, void_t<decltype(std::declval<T&>().step(std::declval<const typename T::Input&>(),
                                               std::declval<typename T::Output&>()))>> : std::true_type {};

template <class T, class = void>
struct constructible_from_params : std::false_type {};
template <class T>
struct constructible_from_params<T, void_t<typename T::Params>>
    : std::bool_constant<std::is_nothrow_constructible_v<T, const typename T::Params&>> {};

}  // namespace detail

//! True when T has the component shape above (each part is also available on its own, for the
//! messages of ADCS_ASSERT_COMPONENT).
template <class T>
inline constexpr bool is_component_v =
    detail::has_types<T>::value && detail::constructible_from_params<T>::value && detail::has_status<T>::value &&
    detail::has_reset<T>::value && detail::has_period<T>::value && detail::has_step<T>::value &&
    detail::has_step_without_diagnostics<T>::value;

}  // namespace adcs

//! Fails the build, naming the missing part, unless the type has the component shape. Variadic so
//! a template with several arguments needs no extra parentheses: ADCS_ASSERT_COMPONENT(HybridAdaptive<4, 3>).
#define ADCS_ASSERT_COMPONENT(...)                                                                          \
  static_assert(::adcs::detail::has_types<__VA_ARGS__>::value,                                              \
                #__VA_ARGS__ ": a component defines Params, Input, Output and Diagnostics");               \
  static_assert(::adcs::detail::constructible_from_params<__VA_ARGS__>::value,                              \
                #__VA_ARGS__ ": a component is constructed noexcept from const Params&");                  \
  static_assert(::adcs::detail::has_status<__VA_ARGS__>::value,                                             \
                #__VA_ARGS__ ": Status status() const noexcept missing");                                  \
  static_assert(::adcs::detail::has_reset<__VA_ARGS__>::value, #__VA_ARGS__ ": void reset() noexcept missing"); \
  static_assert(::adcs::detail::has_period<__VA_ARGS__>::value,                                             \
                #__VA_ARGS__ ": S period_s() const noexcept (S floating point) missing");                                \
  static_assert(::adcs::detail::has_step<__VA_ARGS__>::value,                                               \
                #__VA_ARGS__ ": Status step(const Input&, Output&, Diagnostics*) noexcept missing");       \
  static_assert(::adcs::detail::has_step_without_diagnostics<__VA_ARGS__>::value,                           \
                #__VA_ARGS__ ": step's Diagnostics* must default to nullptr")
