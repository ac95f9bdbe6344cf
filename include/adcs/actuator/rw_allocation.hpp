#pragma once
// Reaction-wheel torque allocation: body torque request L_r -> wheel motor torques u_s.
// The wheels act on the body with -G_s u_s (see plant/rigid_body_rw.hpp), so the minimum-norm
// solution of -G_s u_s = L_r is u_s = -G_s^+ L_r with G_s^+ = G_s^T (G_s G_s^T)^-1. G_s is
// constant, so G_s^+ is computed once. Commands beyond the per-wheel limit are scaled down
// together, which keeps the direction of the delivered torque (clipping each wheel would not).
#include "adcs/core/failure_hook.hpp"
#include "adcs/core/status.hpp"
#include "adcs/core/types.hpp"
#include "adcs/core/validation.hpp"
#include "adcs/math/pinv.hpp"

namespace adcs {

//! The wheel axes have no default (NaN until set: refused). The limit defaults to the 0.2 N m of
//! the rigid-rw-mrp-pd foundation vehicle (issue 15's four-wheel case).
template <int N>
struct RwAllocationParams {
  //! [-] wheel spin axes (unit columns, within 1e-6), B components; must span R^3
  Mat<3, N> G_s_B = Mat<3, N>::Constant(kUnset);
  double torque_limit = 0.2;  //!< [N m] per-wheel motor torque limit (finite, > 0)
};

template <int N>
class RwTorqueAllocator {
 public:
  using Params = RwAllocationParams<N>;

  explicit RwTorqueAllocator(const Params& p) noexcept : p_(p) {
    G_pinv_.setZero();
    // Axes first: the pseudo-inverse of a NaN (unset) geometry is not attempted.
    const bool axes = unit_columns<3, N>(p_.G_s_B);
    const Status s = axes ? right_pinv<3, N>(p_.G_s_B, G_pinv_, &info_) : Status::invalid_parameter;
    status_ = ADCS_CHECK(s == Status::ok && finite_positive(p_.torque_limit),
                         "RwTorqueAllocator: wheel axes must be unit and span R^3, torque_limit finite > 0")
                  ? Status::ok
                  : Status::invalid_parameter;
  }

  //! ok, or invalid_parameter: G_s_B not finite, a column not unit, or the axes not spanning R^3
  //! (G_s G_sᵀ singular); torque_limit not finite or not > 0. A refused allocator answers
  //! invalid_parameter from allocate() and leaves u_s untouched.
  Status status() const noexcept { return status_; }
  //! Conditioning of G_s seen at construction.
  const PinvInfo& geometry() const noexcept { return info_; }

  //! u_s = -G_s^+ L_r_B, scaled into the limit. Returns saturated when scaled, non_finite_input
  //! (u_s untouched) on a non-finite request, out_of_range (u_s untouched) when a finite but
  //! absurd request (|L_r_B| ~ 1e308) overflows G_s^+ L_r_B, invalid_parameter if construction
  //! failed.
  [[nodiscard]] Status allocate(const Vec3& L_r_B, Vec<N>& u_s) const noexcept {
    if (status_ != Status::ok) return status_;
    if (!all_finite(L_r_B)) return Status::non_finite_input;
    Vec<N> cmd;
    cmd.noalias() = -G_pinv_ * L_r_B;
    // Scaling an infinite peak would give inf * 0 = NaN: refuse instead of clipping.
    if (!all_finite(cmd)) return Status::out_of_range;
    const double peak = cmd.cwiseAbs().maxCoeff();
    Status s = Status::ok;
    if (peak > p_.torque_limit) {
      cmd *= p_.torque_limit / peak;
      // The scaled peak can exceed the limit by one rounding; clamp so |u_s| <= limit exactly.
      cmd = cmd.cwiseMin(p_.torque_limit).cwiseMax(-p_.torque_limit);
      s = Status::saturated;
    }
    u_s = cmd;
    return s;
  }

 private:
  Params p_;
  Mat<N, 3> G_pinv_;
  PinvInfo info_;
  Status status_ = Status::ok;
};

}  // namespace adcs
