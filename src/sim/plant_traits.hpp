#pragma once
// Compile-time detection of the optional members of the Plant concept (docs/CONTRACTS.md):
//   bool normalize(State& x) const noexcept;                                   (MRP shadow switch)
//   void jacobian(double t, const State&, const Input&, Mat<kStateSize,kStateSize>& J) const noexcept;
// Why SFINAE rather than a base class: plants are plain flight-code structs with no virtuals.
#include <type_traits>
#include <utility>

#include "adcs/core/types.hpp"

namespace adcs::sim {

template <class Plant, class = void>
struct has_normalize : std::false_type {};
template <class Plant>
struct has_normalize<Plant, std::void_t<decltype(std::declval<const Plant&>().normalize(
                                std::declval<typename Plant::State&>()))>>
    : std::is_convertible<decltype(std::declval<const Plant&>().normalize(
                              std::declval<typename Plant::State&>())),
                          bool> {};
template <class Plant>
inline constexpr bool has_normalize_v = has_normalize<Plant>::value;

template <class Plant, class = void>
struct has_jacobian : std::false_type {};
template <class Plant>
struct has_jacobian<Plant,
                    std::void_t<decltype(std::declval<const Plant&>().jacobian(
                        0.0, std::declval<const typename Plant::State&>(),
                        std::declval<const typename Plant::Input&>(),
                        std::declval<adcs::Mat<Plant::kStateSize, Plant::kStateSize>&>()))>>
    : std::true_type {};
template <class Plant>
inline constexpr bool has_jacobian_v = has_jacobian<Plant>::value;

//! Applies plant.normalize(x) when the plant has one; returns whether x changed (false otherwise).
template <class Plant>
bool normalize_if_any(const Plant& plant, typename Plant::State& x) noexcept {
  if constexpr (has_normalize_v<Plant>) {
    return static_cast<bool>(plant.normalize(x));
  } else {
    (void)plant;
    (void)x;
    return false;
  }
}

}  // namespace adcs::sim
