#pragma once
// Step normalisation for an explicitly discretised gradient adaptive law (beyond seed 001).
//
// The paper's estimates θ̂̇ = α Yᵀ B0ᵀ P e are integrated by explicit Euler at the control period
// T (spec §A.3 step 13). The estimate and the tracking error form a loop whose per-step gain is
// about λ = T α ‖Y‖² ‖P22‖ (spec §A.5: α_F ‖Y_F‖² p22 reaches ~4e2 s⁻¹ on A-REF, so T ≥ 5 ms
// makes λ ≥ 2 and the update diverges). Dividing the step by (1 + λ/λ_max) keeps the loop gain
// below λ_max whatever T is, and leaves the law unchanged where λ ≪ λ_max:
//
//   θ⁺ = θ + T α Φ / (1 + λ/λ_max)
//
// This is the normalised gradient of adaptive control (Ioannou & Sun, Robust Adaptive Control,
// §4.3, m² = 1 + κ‖φ‖²) with κ chosen from the sample period; for a scalar linear loop with
// λ_max = 1 it is exactly the backward-Euler (implicit) step. The scale is in (0, 1], positive,
// so the projection's direction logic (Proj(θ, cΦ) = c Proj(θ, Φ) for c > 0) is unchanged.
#include <cmath>

#include "adcs/core/types.hpp"

namespace adcs {

//! How a controller integrates its adaptive estimates over one control period.
enum class AdaptationStep {
  explicit_euler,  //!< θ⁺ = θ + T θ̇ (the papers' reference discretisation)
  normalized,      //!< θ⁺ = θ + T θ̇ / (1 + λ/λ_max), λ the per-step loop gain (this file)
};

//! 1/(1 + λ/λ_max) for a per-step loop gain λ >= 0 and a limit λ_max > 0; 1 for a non-finite
//! or negative λ_max (callers validate parameters; this never divides by zero).
//! S: the scalar of the law (issue 19).
template <class S>
inline S normalized_step_scale(S step_gain, identity_t<S> max_step_gain) noexcept {
  if (!(max_step_gain > S(0)) || !std::isfinite(max_step_gain)) return S(1);
  if (!(step_gain > S(0))) return S(1);
  return S(1) / (S(1) + step_gain / max_step_gain);  // step_gain = +inf gives 0: the step freezes
}

}  // namespace adcs
