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
template <int N, class S = double>
struct RwAllocationParams {
  //! [-] wheel spin axes (unit columns, within 1e-6), B components; must span R^3
  Mat<3, N, S> G_s_B = Mat<3, N, S>::Constant(unset_v<S>);
  S torque_limit = S(0.2);  //!< [N m] per-wheel motor torque limit (finite, > 0)
  //! The same parameters in another scalar (validated again by the allocator that receives them).
  template <class T>
  RwAllocationParams<N, T> cast() const noexcept {
    RwAllocationParams<N, T> q;
    q.G_s_B = scalar_cast<T>(G_s_B);
    q.torque_limit = narrow_scalar<T>(torque_limit);
    return q;
  }
};

//! How the request was met.
template <class S = double>
struct RwAllocationDiagnosticsT {
  S scale = S(1);  //!< [-] common factor applied to fit the limit (1: none)
};
using RwAllocationDiagnostics = RwAllocationDiagnosticsT<double>;

template <int N, class S = double>
class RwTorqueAllocator {
 public:
  using Scalar = S;
  using Params = RwAllocationParams<N, S>;
  using Input = BodyTorqueT<S>;
  using Output = WheelTorques<N, S>;
  using Diagnostics = RwAllocationDiagnosticsT<S>;

  explicit RwTorqueAllocator(const Params& p) noexcept : p_(p) {
    G_pinv_.setZero();
    // Axes first: the pseudo-inverse of a NaN (unset) geometry is not attempted.
    const bool axes = unit_columns<3, N, S>(p_.G_s_B);
    const Status s = axes ? right_pinv<3, N, S>(p_.G_s_B, G_pinv_, &info_) : Status::invalid_parameter;
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
  S period_s() const noexcept { return S(0); }
  //! Nothing to reset (memoryless).
  void reset() noexcept {}
  //! Conditioning of G_s seen at construction.
  const PinvInfoT<S>& geometry() const noexcept { return info_; }

  //! u_s = -G_s^+ L_r, scaled into the limit. Returns saturated when scaled; non_finite_input on
  //! a non-finite request, out_of_range when a finite but absurd request (|L_r| ~ 1e308)
  //! overflows G_s^+ L_r, invalid_parameter if construction failed: u_s = 0 (the wheels coast)
  //! in those three cases.
  [[nodiscard]] Status step(const Input& in, Output& out, Diagnostics* diag = nullptr) const noexcept {
    out.u_s_Nm.setZero();
    if (status_ != Status::ok) return status_;
    if (!all_finite(in.torque_B_Nm)) return Status::non_finite_input;
    Vec<N, S> cmd;
    cmd.noalias() = -G_pinv_ * in.torque_B_Nm;
    // Scaling an infinite peak would give inf * 0 = NaN: refuse instead of clipping.
    if (!all_finite(cmd)) return Status::out_of_range;
    S scale = S(1);
    const S peak = cmd.cwiseAbs().maxCoeff();
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
  Mat<N, 3, S> G_pinv_;
  PinvInfoT<S> info_;
  Status status_ = Status::ok;
};

ADCS_ASSERT_COMPONENT(RwTorqueAllocator<4>);
ADCS_ASSERT_COMPONENT(RwTorqueAllocator<4, float>);

}  // namespace adcs
