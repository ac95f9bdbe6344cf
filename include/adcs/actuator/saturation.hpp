#pragma once
// Per-actuator magnitude limits |u_k| <= limit_k, applied element by element as a physical
// actuator does (each gimbal motor or wheel saturates on its own; the direction of u is not
// preserved — use the allocator's common scaling where direction matters, rw_allocation.hpp).
#include "adcs/core/types.hpp"

namespace adcs {

//! Clamps u to [−limit_k, limit_k] per element; a limit that is not > 0 (0, negative, NaN)
//! means "no limit" for that element, +inf is no limit too. Returns how many elements were
//! clipped (0 = none). A non-finite u_k is left as is: callers check finiteness first.
template <int L>
int saturate_each(Vec<L>& u, const Vec<L>& limit) noexcept {
  int clipped = 0;
  for (int k = 0; k < L; ++k) {
    const double lim = limit(k);
    if (!(lim > 0.0)) continue;
    if (u(k) > lim) {
      u(k) = lim;
      ++clipped;
    } else if (u(k) < -lim) {
      u(k) = -lim;
      ++clipped;
    }
  }
  return clipped;
}

}  // namespace adcs
