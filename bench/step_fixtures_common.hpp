#pragma once
// What every step fixture (bench/step_fixtures.hpp) uses: escape() and the four-wheel axes.
#include <cmath>

#include "adcs/core/types.hpp"

namespace adcs::bench {

//! Keeps a value alive without a memory round trip (what benchmark::DoNotOptimize does).
template <class T>
inline void escape(const T& v) noexcept {
  asm volatile("" : : "g"(&v) : "memory");
}

inline Mat<3, 4> four_wheel_axes() {
  Mat<3, 4> G;
  const double s = 1.0 / std::sqrt(3.0);
  G << 1, 0, 0, s, 0, 1, 0, s, 0, 0, 1, s;
  return G;
}

}  // namespace adcs::bench
