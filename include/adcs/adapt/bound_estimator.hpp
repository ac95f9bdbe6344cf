#pragma once
// Adaptive estimate of an unknown bound μ* with σ-modification, seed 002 eq. (14):
//   μ̂̇ = τ_μ (‖s‖ − γ μ̂)
// integrated over one control period with ‖s‖ held (exact under ZOH, see rbf_network.hpp):
//   μ̂⁺ = e^{−τ_μ γ T} μ̂ + (1 − e^{−τ_μ γ T})/γ · ‖s‖       (γ > 0; γ = 0: μ̂ + τ_μ T ‖s‖)
// μ̂ ≥ 0 is invariant (spec B-S12): both terms are non-negative whenever μ̂ ≥ 0.
#include <cmath>

#include <Eigen/Core>

#include "adcs/core/types.hpp"  // identity_t

namespace adcs {

template <class S>
inline S bound_estimate_step(S mu, identity_t<S> s_norm, identity_t<S> tau_mu, identity_t<S> gamma,
                             identity_t<S> T) noexcept {
  if (gamma > S(0)) {
    const S x = tau_mu * gamma * T;
    return std::exp(-x) * mu + (-std::expm1(-x) / gamma) * s_norm;  // expm1: no cancellation
  }
  return mu + tau_mu * T * s_norm;
}

//! The robust term μ̂² s/(μ̂‖s‖ + σ) of seed 002 eq. (12); its denominator is ≥ σ > 0 for μ̂ ≥ 0.
template <class Derived>
typename Derived::PlainObject bound_robust_term(typename Derived::Scalar mu, const Eigen::MatrixBase<Derived>& s,
                                                typename Derived::Scalar sigma) noexcept {
  return (mu * mu / (mu * s.norm() + sigma)) * s;
}

}  // namespace adcs
