#pragma once
// Neural compensation of a lumped disturbance with an adaptive robust term — the part seed 002's
// PPATC (seed 002 eq. (12)) and its ATC comparison law share (spec §B.3 steps 11-14):
//
//   h = h(x),  D̂ = Ŵᵀ h                                   RBF estimate        (steps 11-12)
//   robust = μ̂² s/(μ̂ ‖s‖ + σ)                             bound compensation  (seed 002 eq. (12))
//   Ŵ̇_i = τ_wi (s_i h − β Ŵ_i),  μ̂̇ = τ_μ (‖s‖ − γ μ̂)     adaptation          (seed 002 eqs. (13)-(14))
//
// The estimates are integrated over each control period with s and h held (exact ZOH steps of
// rbf_network.hpp / bound_estimator.hpp). μ̂ ≥ 0 is an invariant (set_state refuses μ̂ < 0).
#include "adcs/adapt/bound_estimator.hpp"
#include "adcs/adapt/rbf_network.hpp"
#include "adcs/core/status.hpp"
#include "adcs/core/types.hpp"

namespace adcs {

//! The gains default to seed 002 Table 2; the layer has no default (RbfLayerParams: refused
//! until set; seed002_compensator() in control/euler_tracking_common.hpp is the paper's).
template <int NI, int NH, int NO, class S = double>
struct RbfCompensatorParams {
  RbfLayerParams<NI, NH, S> layer{};       //!< centres c_j and widths b_j (units of x); no default
  Vec<NO, S> tau_w = Vec<NO, S>::Constant(S(0.5));  //!< [-] τ_wi, seed 002 Table 2
  S tau_mu = S(0.5);                   //!< [-] τ_μ, seed 002 Table 2
  S beta = S(0.01);                    //!< [-] weight leakage β, seed 002 Table 2
  S gamma = S(0.01);                   //!< [-] bound leakage γ, seed 002 Table 2
  S sigma = S(0.01);                   //!< [-] robust-term constant σ > 0, seed 002 Table 2
  template <class T>
  RbfCompensatorParams<NI, NH, NO, T> cast() const noexcept {
    return {layer.template cast<T>(), scalar_cast<T>(tau_w), narrow_scalar<T>(tau_mu),
            narrow_scalar<T>(beta),   narrow_scalar<T>(gamma), narrow_scalar<T>(sigma)};
  }
};

template <int NI, int NH, int NO, class S = double>
class RbfCompensator {
 public:
  using Params = RbfCompensatorParams<NI, NH, NO, S>;
  struct Output {
    Vec<NH, S> h = Vec<NH, S>::Zero();        //!< RBF activations
    Vec<NO, S> D_hat = Vec<NO, S>::Zero();    //!< Ŵᵀ h
    Vec<NO, S> robust = Vec<NO, S>::Zero();   //!< μ̂² s/(μ̂‖s‖ + σ)
  };

  explicit RbfCompensator(const Params& p) noexcept : p_(p), layer_(p.layer) {
    const bool ok = layer_.status() == Status::ok && finite_nonnegative(p_.tau_w) && finite_nonnegative(p_.tau_mu) &&
                    finite_nonnegative(p_.beta) && finite_nonnegative(p_.gamma) && finite_positive(p_.sigma);
    status_ = ok ? Status::ok : Status::invalid_parameter;
  }
  //! ok, or invalid_parameter: the layer refused (RbfLayer), τ_w, τ_μ, β or γ not finite or < 0,
  //! σ not finite or not > 0. A refused compensator evaluates to zero and never adapts.
  Status status() const noexcept { return status_; }
  const Params& params() const noexcept { return p_; }

  //! Ŵ(0) = 0, μ̂(0) = 0 (spec §B.5 assumption).
  void reset() noexcept {
    W_.setZero();
    mu_ = S(0);
  }

  //! D̂ and the robust term for NN input x and sliding variable s (both finite: caller checks).
  //! Zero when refused (status() != ok): no compensation from invalid gains.
  Output evaluate(const Vec<NI, S>& x, const Vec<NO, S>& s) const noexcept {
    Output o;
    if (status_ != Status::ok) return o;
    o.h = layer_.activations(x);
    o.D_hat = W_.transpose() * o.h;
    o.robust = bound_robust_term(mu_, s, p_.sigma);
    return o;
  }

  //! Next estimates after one period T with s and h held; committed by commit(). A refused
  //! compensator proposes its current (initial) estimates.
  void propose(const Output& o, const Vec<NO, S>& s, S T, Mat<NH, NO, S>& W_next, S& mu_next) const noexcept {
    if (status_ != Status::ok) {
      W_next = W_;
      mu_next = mu_;
      return;
    }
    W_next = rbf_weight_step<NH, NO, S>(W_, o.h, s, p_.tau_w, p_.beta, T);   // seed 002 eq. (13)
    mu_next = bound_estimate_step<S>(mu_, s.norm(), p_.tau_mu, p_.gamma, T);  // seed 002 eq. (14)
  }
  void commit(const Mat<NH, NO, S>& W_next, S mu_next) noexcept {
    W_ = W_next;
    mu_ = mu_next;
  }

  //! Warm start / oracle tests. Rejects non-finite values and μ̂ < 0 (state untouched).
  [[nodiscard]] Status set_state(const Mat<NH, NO, S>& W, S mu) noexcept {
    if (!all_finite(W) || !std::isfinite(mu)) return Status::non_finite_input;
    if (mu < S(0)) return Status::out_of_range;
    W_ = W;
    mu_ = mu;
    return Status::ok;
  }
  const Mat<NH, NO, S>& weights() const noexcept { return W_; }
  S mu() const noexcept { return mu_; }

 private:
  Params p_;
  RbfLayer<NI, NH, S> layer_;
  Mat<NH, NO, S> W_ = Mat<NH, NO, S>::Zero();
  S mu_ = S(0);
  Status status_ = Status::ok;
};

}  // namespace adcs
