#pragma once
// Smooth projection operator for adaptive laws (seed 001 eq. (26), §A.3 step 12, §A.4 #18/#19):
//
//   Proj(θ, Φ) = α Φ                                               if ‖θ‖² < β or θᵀΦ ≤ 0
//   Proj(θ, Φ) = α [ Φ − ((‖θ‖² − β)/δ) (θᵀΦ/‖θ‖²) θ ]              if ‖θ‖² ≥ β and θᵀΦ > 0
//
// (Pomet–Praly / Krstić–Kanellakopoulos–Kokotović form.) Properties, each tested:
//  - continuous in θ (the correction vanishes at ‖θ‖² = β);
//  - invariance: d/dt‖θ‖² = 2αθᵀΦ(β + δ − ‖θ‖²)/δ when active, so ‖θ(0)‖² ≤ β + δ keeps
//    ‖θ(t)‖² ≤ β + δ for the continuous law;
//  - Lyapunov: (θ* − θ)ᵀ(αΦ − Proj) ≤ 0 whenever ‖θ*‖² ≤ β.
// Works for any block size K. Never divides by zero: the active branch needs θᵀΦ > 0, so θ ≠ 0.
#include <cmath>

#include "adcs/core/status.hpp"
#include "adcs/core/types.hpp"

namespace adcs {

//! Defaults: β and δ of seed 001 §4 (β_Gi = 0.05, δ_Gi = 0.1); α = 1, the bare operator
//! (HybridAdaptive passes its α_G = 1e3, seed 001 §4). S: the scalar of θ (issue 19).
template <class S = double>
struct ProjectionParamsT {
  S alpha = S(1);      //!< [-] adaptation gain α (>= 0); 1: Proj(θ, Φ) itself
  S beta = S(0.05);    //!< [θ units²] radius² β (> 0) beyond which the correction starts
  S delta = S(0.1);    //!< [θ units²] boundary-layer width δ (> 0); invariant set ‖θ‖² ≤ β + δ
};
using ProjectionParams = ProjectionParamsT<double>;

//! True when the parameters define a projection (finite, α >= 0, β > 0, δ > 0). Checked by
//! every smooth_projection() call (invalid_parameter, outputs untouched) and by the adaptive laws
//! at construction.
template <class S>
inline bool valid(const ProjectionParamsT<S>& p) noexcept {
  return std::isfinite(p.alpha) && std::isfinite(p.beta) && std::isfinite(p.delta) &&
         p.alpha >= S(0) && p.beta > S(0) && p.delta > S(0);
}

//! θ̇ = Proj(θ, Φ) into `theta_dot`. S is not deduced (any Eigen expression of size K converts):
//! double unless given, `smooth_projection<K, float>(...)`. `active` (optional) reports whether the correction acted.
//! Returns non_finite_input or invalid_parameter with the outputs untouched, ok otherwise.
template <int K, class S = double>
[[nodiscard]] Status smooth_projection(const identity_t<Vec<K, S>>& theta, const identity_t<Vec<K, S>>& Phi,
                                       const identity_t<ProjectionParamsT<S>>& p, Vec<K, S>& theta_dot,
                                       bool* active = nullptr) noexcept {
  if (!valid(p)) return Status::invalid_parameter;
  if (!all_finite(theta) || !all_finite(Phi)) return Status::non_finite_input;
  const S n2 = theta.squaredNorm();
  const S tPhi = theta.dot(Phi);
  const bool on = n2 >= p.beta && tPhi > S(0);  // seed 001 §A.4 #19: the two cases partition
  if (on) {
    const S c = (n2 - p.beta) / p.delta;  // seed 001 §A.4 #18
    theta_dot = p.alpha * (Phi - (c * tPhi / n2) * theta);
  } else {
    theta_dot = p.alpha * Phi;
  }
  if (active) *active = on;
  return Status::ok;
}

//! Discrete-time safeguard (seed 001 §A.3 step 13, not in the paper): an explicit-Euler step
//! can overshoot the invariant ball; rescale θ radially onto ‖θ‖² = bound_sq if it did.
//! Returns true when it rescaled (callers count these events; a correct run has none).
template <int K, class S = double>
bool radial_safeguard(identity_t<Vec<K, S>>& theta, identity_t<S> bound_sq) noexcept {
  const S n2 = theta.squaredNorm();
  if (!(n2 > bound_sq)) return false;
  theta *= std::sqrt(bound_sq / n2);
  return true;
}

}  // namespace adcs
