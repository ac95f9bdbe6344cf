#pragma once
// Gaussian radial-basis-function network with a σ-modification weight law, seed 002 §3
// (spec §B.3 steps 11, 12, 14):
//
//   h_j(x) = exp(−‖x − c_j‖² / (2 b_j²)),  j = 1..NH                          (RBF layer)
//   D̂ = Ŵᵀ h(x)                                 (NO outputs, Ŵ is NH x NO)   (step 12)
//   Ŵ̇_i = τ_i (s_i h − β Ŵ_i)                   (column i, output i)         seed 002 eq. (13)
//
// The weight law is integrated over one control period T with s and h held (ZOH), exactly:
//   Ŵ_i⁺ = e^{−τ_i β T} Ŵ_i + (1 − e^{−τ_i β T})/β · s_i h     (β > 0, via expm1)
// which is the explicit-Euler step to O(T²), never overshoots the leakage, and is what the
// continuous law gives under the hold. β = 0 falls back to Ŵ_i⁺ = Ŵ_i + τ_i T s_i h.
#include <cmath>

#include "adcs/core/status.hpp"
#include "adcs/core/types.hpp"
#include "adcs/core/validation.hpp"

namespace adcs {

//! No default: centres and widths depend on the input's range (NaN until set, so a forgotten
//! layer is refused). seed002_rbf_layer() (control/euler_tracking_common.hpp) is seed 002 §4's.
template <int NI, int NH, class S = double>
struct RbfLayerParams {
  //! c_j (columns), units of the input x; finite
  Mat<NI, NH, S> centers = Mat<NI, NH, S>::Constant(unset_v<S>);
  //! b_j, units of x; finite, > 0
  Vec<NH, S> widths = Vec<NH, S>::Constant(unset_v<S>);
  template <class T>
  RbfLayerParams<NI, NH, T> cast() const noexcept {
    return {scalar_cast<T>(centers), scalar_cast<T>(widths)};
  }
};

//! Gaussian layer h(x) with fixed centres and widths.
template <int NI, int NH, class S = double>
class RbfLayer {
 public:
  using Params = RbfLayerParams<NI, NH, S>;
  explicit RbfLayer(const Params& p) noexcept : p_(p) {
    const bool ok = all_finite(p_.centers) && finite_positive(p_.widths);
    status_ = ok ? Status::ok : Status::invalid_parameter;
    for (int j = 0; j < NH; ++j) inv_two_b2_(j) = S(1) / (S(2) * p_.widths(j) * p_.widths(j));
  }
  //! ok, or invalid_parameter: a centre not finite, a width not finite or not > 0.
  Status status() const noexcept { return status_; }
  const Params& params() const noexcept { return p_; }

  //! h_j(x) ∈ (0, 1], = 1 at x = c_j. The caller checks x is finite. A refused layer activates
  //! nothing (h = 0), so no estimate is built from parameters that were never valid.
  Vec<NH, S> activations(const Vec<NI, S>& x) const noexcept {
    if (status_ != Status::ok) return Vec<NH, S>::Zero();
    Vec<NH, S> h;
    for (int j = 0; j < NH; ++j) h(j) = std::exp(-(x - p_.centers.col(j)).squaredNorm() * inv_two_b2_(j));
    return h;
  }

 private:
  Params p_;
  Vec<NH, S> inv_two_b2_ = Vec<NH, S>::Ones();
  Status status_ = Status::ok;
};

//! One period of seed 002 eq. (13) for all columns (see the header comment). tau (NO) >= 0, beta >= 0.
//! In float, e^{−x} for the paper's x = τβT = 5e-7 is 1 − x to within float's spacing at 1
//! (6e-8): the leakage per step is rounded by up to ~12 % (β's effect, not the learning term's).
template <int NH, int NO, class S>
Mat<NH, NO, S> rbf_weight_step(const Mat<NH, NO, S>& W, const identity_t<Vec<NH, S>>& h,
                               const identity_t<Vec<NO, S>>& s, const identity_t<Vec<NO, S>>& tau,
                               identity_t<S> beta, identity_t<S> T) noexcept {
  Mat<NH, NO, S> next;
  for (int i = 0; i < NO; ++i) {
    if (beta > S(0)) {
      const S x = tau(i) * beta * T;
      next.col(i) = std::exp(-x) * W.col(i) + (-std::expm1(-x) / beta * s(i)) * h;  // expm1: no cancellation
    } else {
      next.col(i) = W.col(i) + (tau(i) * T * s(i)) * h;
    }
  }
  return next;
}

}  // namespace adcs
