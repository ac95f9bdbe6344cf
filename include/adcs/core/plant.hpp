#pragma once
// The one shape of every continuous plant (issue 17; docs/CONTRACTS.md "Plant"), checked at
// compile time like the component shape (core/component.hpp):
//
//   struct P {
//     static constexpr int kStateSize, kInputSize;
//     using State = Vec<kStateSize>; using Input = Vec<kInputSize>;   // held (ZOH) input
//     Status status() const noexcept;                                // construction outcome
//     void derivative(double t, const State& x, const Input& u, State& xdot) const noexcept;
//   };
//
// optional: bool normalize(State&) const noexcept (MRP shadow switch, quaternion norm) and an
// analytic jacobian(). A plant with a structured state (Se3Spacecraft) or a discrete model
// (the drag-free satellite) meets it through an adapter (plant/se3_spacecraft_plant.hpp,
// plant/drag_free_plant.hpp), so the ground's CVODE/RK4 integrators and closed loop take any plant.
// Usage: ADCS_ASSERT_PLANT(MyPlant); right after the class.
#include <type_traits>
#include <utility>

#include "adcs/core/component.hpp"  // detail::void_t
#include "adcs/core/status.hpp"
#include "adcs/core/types.hpp"

namespace adcs {
namespace detail {

template <class T, class = void>
struct has_plant_sizes : std::false_type {};
template <class T>
struct has_plant_sizes<T, void_t<decltype(T::kStateSize), decltype(T::kInputSize), typename T::State,
                                 typename T::Input>>
    : std::bool_constant<std::is_same_v<typename T::State, Vec<T::kStateSize>> &&
                         std::is_same_v<typename T::Input, Vec<T::kInputSize>>> {};

template <class T, class = void>
struct has_derivative : std::false_type {};
template <class T>
struct has_derivative<T, void_t<decltype(std::declval<const T&>().derivative(
                             0.0, std::declval<const typename T::State&>(), std::declval<const typename T::Input&>(),
                             std::declval<typename T::State&>()))>>
    : std::bool_constant<noexcept(std::declval<const T&>().derivative(
          0.0, std::declval<const typename T::State&>(), std::declval<const typename T::Input&>(),
          std::declval<typename T::State&>()))> {};

}  // namespace detail

template <class T>
inline constexpr bool is_plant_v =
    detail::has_plant_sizes<T>::value && detail::has_status<T>::value && detail::has_derivative<T>::value;

}  // namespace adcs

//! Fails the build, naming the missing part, unless the type has the plant shape.
#define ADCS_ASSERT_PLANT(...)                                                                               \
  static_assert(::adcs::detail::has_plant_sizes<__VA_ARGS__>::value,                                        \
                #__VA_ARGS__ ": a plant defines kStateSize, kInputSize, State = Vec<kStateSize>, Input = Vec<kInputSize>"); \
  static_assert(::adcs::detail::has_status<__VA_ARGS__>::value,                                             \
                #__VA_ARGS__ ": Status status() const noexcept missing");                                  \
  static_assert(::adcs::detail::has_derivative<__VA_ARGS__>::value,                                         \
                #__VA_ARGS__ ": void derivative(double, const State&, const Input&, State&) const noexcept missing")
