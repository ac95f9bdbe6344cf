#pragma once
// Pseudo-inverse steering for a 3×L actuator input matrix X (seed 001 §A.3 step 10): the
// minimum-norm u solving X u = v, u = Xᵀ(XXᵀ)⁻¹v through an LDLT of XXᵀ, with a
// singularity-robust fallback when the conditioning crosses a threshold: below σ_min =
// sigma_threshold the damped inverse Xᵀ(XXᵀ + λ²I)⁻¹v takes over, with λ² rising continuously
// from 0 (math/pinv.hpp), so the command never jumps at the switch and stays bounded at an
// exactly singular X. The status and SteeringInfo say which inverse produced u.
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
//! usable), non_finite_input or singular (u untouched).
template <int L>
[[nodiscard]] Status steer(const Mat<3, L>& X, const Vec3& v, const SteeringParams& params,
                           Vec<L>& u, SteeringInfo* info = nullptr) noexcept {
  SteeringInfo local;
  const Status s = damped_right_pinv_solve<3, L>(X, v, u, params, &local.pinv);
  local.mode = local.pinv.damped ? SteeringMode::singularity_robust : SteeringMode::pseudo_inverse;
  if (info) *info = local;
  return s;
}

}  // namespace adcs
