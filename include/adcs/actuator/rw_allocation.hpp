#pragma once
// Reaction-wheel torque allocation: body torque request L_r -> wheel motor torques u_s.
// The wheels act on the body with -G_s u_s (see plant/rigid_body_rw.hpp), so the minimum-norm
// solution of -G_s u_s = L_r is u_s = -G_s^+ L_r with G_s^+ = G_s^T (G_s G_s^T)^-1. G_s is
// constant, so G_s^+ is computed once. Commands beyond the per-wheel limit are scaled down
// together, which keeps the direction of the delivered torque (clipping each wheel would not).
#include "adcs/core/component.hpp"
#include "adcs/core/failure_hook.hpp"
#include "adcs/core/signals.hpp"
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

//! How the request was met.
struct RwAllocationDiagnostics {
  double scale = 1.0;  //!< [-] common factor applied to fit the limit (1: none)
};

template <int N>
class RwTorqueAllocator {
 public:
  using Params = RwAllocationParams<N>;
  using Input = BodyTorque;
  using Output = WheelTorques<N>;
  using Diagnostics = RwAllocationDiagnostics;

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
  //! invalid_parameter from step() with zero wheel torques.
  Status status() const noexcept { return status_; }
  //! 0: a memoryless stage, run whenever its torque law runs (core/component.hpp).
  double period_s() const noexcept { return 0.0; }
  //! Nothing to reset (memoryless).
  void reset() noexcept {}
  //! Conditioning of G_s seen at construction.
  const PinvInfo& geometry() const noexcept { return info_; }

  //! u_s = -G_s^+ L_r, scaled into the limit. Returns saturated when scaled; non_finite_input on
  //! a non-finite request, out_of_range when a finite but absurd request (|L_r| ~ 1e308)
  //! overflows G_s^+ L_r, invalid_parameter if construction failed: u_s = 0 (the wheels coast)
  //! in those three cases.
  [[nodiscard]] Status step(const Input& in, Output& out, Diagnostics* diag = nullptr) const noexcept {
    out.u_s_Nm.setZero();
    if (status_ != Status::ok) return status_;
    if (!all_finite(in.torque_B_Nm)) return Status::non_finite_input;
    Vec<N> cmd;
    cmd.noalias() = -G_pinv_ * in.torque_B_Nm;
    // Scaling an infinite peak would give inf * 0 = NaN: refuse instead of clipping.
    if (!all_finite(cmd)) return Status::out_of_range;
    double scale = 1.0;
    const double peak = cmd.cwiseAbs().maxCoeff();
    Status s = Status::ok;
    if (peak > p_.torque_limit) {
      scale = p_.torque_limit / peak;
      cmd *= scale;
      // The scaled peak can exceed the limit by one rounding; clamp so |u_s| <= limit exactly.
      cmd = cmd.cwiseMin(p_.torque_limit).cwiseMax(-p_.torque_limit);
      s = Status::saturated;
    }
    out.u_s_Nm = cmd;
    if (diag) diag->scale = scale;
    return s;
  }

 private:
  Params p_;
  Mat<N, 3> G_pinv_;
  PinvInfo info_;
  Status status_ = Status::ok;
};

ADCS_ASSERT_COMPONENT(RwTorqueAllocator<4>);

}  // namespace adcs
