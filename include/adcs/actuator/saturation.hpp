#pragma once
// Per-actuator magnitude limits |u_k| <= limit_k, applied element by element as a physical
// actuator does (each gimbal motor or wheel saturates on its own; the direction of u is not
// preserved — use the allocator's common scaling where direction matters, rw_allocation.hpp).
#include "adcs/core/component.hpp"
#include "adcs/core/status.hpp"
#include "adcs/core/types.hpp"
#include "adcs/core/validation.hpp"

namespace adcs {

//! Clamps u to [−limit_k, limit_k] per element; a limit that is not > 0 (0, negative, NaN)
//! means "no limit" for that element, +inf is no limit too. Returns how many elements were
//! clipped (0 = none). A non-finite u_k is left as is: callers check finiteness first.
//! Scalar S (issue 19): deduced from u.
template <int L, class S = double>
int saturate_each(Vec<L, S>& u, const identity_t<Vec<L, S>>& limit) noexcept {
  int clipped = 0;
  for (int k = 0; k < L; ++k) {
    const S lim = limit(k);
    if (!(lim > S(0))) continue;
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

template <int L, class S = double>
struct SaturationParams {
  Vec<L, S> limit = Vec<L, S>::Constant(unset_v<S>);  //!< [channel units] |u_k| ≤ limit_k; > 0, +inf: none; no default
  //! The same limits in another scalar (beyond T's range: +Inf, i.e. no limit).
  template <class T>
  SaturationParams<L, T> cast() const noexcept {
    return SaturationParams<L, T>{scalar_cast<T>(limit)};
  }
};

struct SaturationDiagnostics {
  int clipped = 0;  //!< channels clipped this step
};

//! saturate_each as a component (an actuator's magnitude limits in front of a plant): Input and
//! Output are the L-channel command, in the scalar S (issue 19).
template <int L, class S = double>
class Saturation {
 public:
  using Params = SaturationParams<L, S>;
  using Input = Vec<L, S>;
  using Output = Vec<L, S>;
  using Diagnostics = SaturationDiagnostics;

  explicit Saturation(const Params& p) noexcept
      : p_(p), status_(!p.limit.hasNaN() && (p.limit.array() > S(0)).all() ? Status::ok : Status::invalid_parameter) {}
  //! ok, or invalid_parameter: a limit NaN (unset) or not > 0 (+inf is allowed: no limit).
  Status status() const noexcept { return status_; }
  S period_s() const noexcept { return S(0); }  //!< memoryless (core/component.hpp)
  void reset() noexcept {}

  //! u clamped per channel; saturated when a channel was clipped. non_finite_input or
  //! invalid_parameter: u = 0 (the actuators idle).
  [[nodiscard]] Status step(const Input& u, Output& out, Diagnostics* diag = nullptr) const noexcept {
    if (status_ != Status::ok || !all_finite(u)) {
      out.setZero();
      return status_ != Status::ok ? status_ : Status::non_finite_input;
    }
    out = u;
    const int clipped = saturate_each<L, S>(out, p_.limit);
    if (diag) diag->clipped = clipped;
    return clipped > 0 ? Status::saturated : Status::ok;
  }

 private:
  Params p_;
  Status status_;
};

ADCS_ASSERT_COMPONENT(Saturation<6>);
ADCS_ASSERT_COMPONENT(Saturation<6, float>);

}  // namespace adcs
