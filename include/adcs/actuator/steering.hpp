#pragma once
// Pseudo-inverse steering for a 3×L actuator input matrix X (seed 001 §A.3 step 10): the
// minimum-norm u solving X u = v, u = Xᵀ(XXᵀ)⁻¹v through an LDLT of XXᵀ, with a
// singularity-robust fallback when the conditioning crosses a threshold: below σ_min =
// sigma_threshold the damped inverse Xᵀ(XXᵀ + λ²I)⁻¹v takes over, with λ² rising continuously
// from 0 (math/pinv.hpp), so the command never jumps at the switch and stays bounded at an
// exactly singular X. The status and SteeringInfo say which inverse produced u.
// Actuator failures: steer_available() solves over the available actuators only (a failed
// gimbal or wheel gets exactly 0 and the others take its share), the fallback FDIR applies.
#include <cstdint>

#include "adcs/core/status.hpp"
#include "adcs/core/types.hpp"
#include "adcs/math/pinv.hpp"

namespace adcs {

enum class SteeringMode : std::uint8_t {
  pseudo_inverse,      //!< exact minimum-norm solution, X u = v
  singularity_robust,  //!< damped least squares: X u ≈ v, |u| bounded
};

struct SteeringInfo {
  PinvInfo pinv;                                //!< singular values, condition, damping used
  SteeringMode mode = SteeringMode::pseudo_inverse;
};

//! sigma_threshold is in the units of X's singular values. seed 001 A-REF sees σ_min(X) ≈ 0.017
//! (spec §A.6 R9); the default 1e-3 leaves the paper's run on the exact inverse.
using SteeringParams = DampingParams;

//! u = X⁺v. Returns ok (exact inverse), ill_conditioned (singularity-robust inverse used; u
//! usable), non_finite_input, singular or out_of_range (finite inputs whose solution overflows)
//! with u untouched.
//! Bit k set = actuator k (column k of X) may be commanded. Fixed width: L ≤ 32.
using ActuatorMask = std::uint32_t;

//! Every actuator of an L-column X available.
template <int L>
constexpr ActuatorMask all_actuators() noexcept {
  static_assert(L >= 1 && L <= 32, "ActuatorMask holds at most 32 actuators");
  return L == 32 ? ~ActuatorMask{0} : (ActuatorMask{1} << L) - 1u;
}

template <int L>
[[nodiscard]] Status steer(const Mat<3, L>& X, const Vec3& v, const SteeringParams& params,
                           Vec<L>& u, SteeringInfo* info = nullptr) noexcept {
  SteeringInfo local;
  const Status s = damped_right_pinv_solve<3, L>(X, v, u, params, &local.pinv);
  local.mode = local.pinv.damped ? SteeringMode::singularity_robust : SteeringMode::pseudo_inverse;
  if (info) *info = local;
  return s;
}

//! u = X_a⁺v over the available actuators: X_a is X with the columns of unavailable actuators
//! zeroed, so the minimum-norm solution gives them exactly u_k = 0 (a zero column contributes
//! nothing to X_a X_aᵀ and u = X_aᵀ(·)⁻¹v) and spreads v over the rest. When the remaining
//! columns lose rank, the singularity-robust inverse takes over (ill_conditioned, u bounded).
//! out_of_range (u untouched) when the mask names an actuator beyond L. The columns of
//! unavailable actuators are not read (a failed actuator's model may be garbage, NaN included).
template <int L>
[[nodiscard]] Status steer_available(const Mat<3, L>& X, const Vec3& v, const SteeringParams& params,
                                     ActuatorMask available, Vec<L>& u, SteeringInfo* info = nullptr) noexcept {
  if ((available & ~all_actuators<L>()) != 0u) return Status::out_of_range;
  if (available == all_actuators<L>()) return steer<L>(X, v, params, u, info);
  Mat<3, L> X_a = X;
  for (int k = 0; k < L; ++k)
    if (((available >> k) & 1u) == 0u) X_a.col(k).setZero();
  Vec<L> u_a;
  const Status s = steer<L>(X_a, v, params, u_a, info);
  if (!usable(s)) return s;
  for (int k = 0; k < L; ++k)  // exact zeros, whatever the rounding of X_aᵀ y
    if (((available >> k) & 1u) == 0u) u_a(k) = 0.0;
  u = u_a;
  return s;
}

}  // namespace adcs
