#pragma once
// Algorithm 1 (the extended-state Kalman filter of seed 004, spec §B.4; estimate/eskf.hpp has the
// equations) with the covariance kept as U-D factors, P = U D Uᵀ (math/ud.hpp): the same filter,
// positive semidefinite by construction, so neither a PSD test nor an eigen projection is on the
// step path (issue 20). Every operation only adds non-negative terms to D:
//
// time update   P⁻ = (1+θ) A_d P A_dᵀ + (1 + 1/θ) Q1 + Q2                                   seed 004 eq. (9)
//               (1+θ) A_d U D Uᵀ A_dᵀ: T = A_d U; rows L.. of A_d are upper triangular with a
//               nonzero diagonal (found at construction), so the columns L.. of the new U are
//               those of T scaled by 1/T_jj (D_j ← T_jj² (1+θ) D_j) and only the leading L x L
//               block is re-factored (Thornton's MWGS, mwgs_ud);
//               + Σ_i w_i g_i g_iᵀ, G = [B_e columns with q_i > 0 | B_d U_s columns with d_s,i > 0]
//               (S = U_s D_s U_sᵀ), weights (1 + 1/θ) 4 l q_i and d_s,i: one Agee–Turner rank-one
//               update each
// measurement   Bierman's scalar update, one decorrelated output at a time: R = U_R D_R U_Rᵀ,
//               z = U_R⁻¹ Y, C̃ = U_R⁻¹ C_d (rows of C̃ in turn, x updated after each)
// fusion        replace_substate (seed 004 eqs. (40)-(41)) by rank-one updates, no re-factoring
//
// Why U-D and not a square-root (Cholesky) form: both keep P PSD by construction, but U-D needs
// no square roots (the Cortex-M4F has no double sqrt; the M7's takes 30+ cycles), Bierman's
// update costs O(N²) per output against a QR of an (N+NY) x N array, and the rank-one updates
// let the time update use the structure of A_d instead of re-triangularising [A_d U | G] whole.
// The factors live in two fixed buffers, no heap: a step writes its candidate factors into the
// spare one and accept() makes it the current one, so no 18 x 18 factor is copied into a
// candidate and back (Candidate).
//
// Structure used: A_d from its nonzeros (SparseRows), C̃ likewise (Bierman starts at the first
// state a row reaches), only the noise columns that carry noise (NG of them, a template parameter),
// the upper-triangular rows of A_d (the drag-free attitude block in its U-D order has L = 6 of
// 18, the translation block 6 of 9). The drag-free model has no per-axis decoupling to use: I_sc,
// K_rot and K_trans have off-diagonal entries (seed 004 Table 2), so each block is one filter
// (estimate/drag_free_eskf.hpp).
#include <array>
#include <cmath>

#include "adcs/core/component.hpp"
#include "adcs/core/status.hpp"
#include "adcs/core/types.hpp"
#include "adcs/core/validation.hpp"
#include "adcs/estimate/eskf.hpp"
#include "adcs/estimate/extended_state_covariance.hpp"
#include "adcs/math/sparse_rows.hpp"
#include "adcs/math/ud.hpp"

namespace adcs {

//! Algorithm 1 in U-D form. N states, NU inputs, NL disturbance channels (l), NY outputs, at most
//! NG noise columns (B_e columns with q_i > 0 plus B_d U_s columns with d_s,i > 0; construction
//! refuses more). S is the scalar (issue 19: double by default; float for a single-precision FPU,
//! where the factors keep D >= 0 whatever the rounding; tests/estimate/test_drag_free_eskf_float.cpp
//! measures what seed 004's states keep of their precision).
template <int N, int NU, int NL, int NY, int NG = NL + NU, class S = double>
class EskfUd : public detail::CandidateFilter<EskfUd<N, NU, NL, NY, NG, S>, N, NU, NL, NY, S> {
 public:
  using Scalar = S;
  using Params = EskfParams<N, NU, NL, NY, S>;
  using Input = EskfInput<NU, NL, NY, S>;
  using Output = EskfOutput<N, S>;
  using Diagnostics = EskfDiagnosticsT<S>;
  using State = Vec<N, S>;
  using Covariance = Mat<N, N, S>;
  using Factors = UdFactors<N, S>;
  static constexpr int kStates = N, kInputs = NU, kChannels = NL, kOutputs = NY;

  explicit EskfUd(const Params& p) noexcept : p_(p) {
    bool ok = valid(p_);
    sqrt_q_ = p_.q.cwiseMax(S(0)).cwiseSqrt();
    A_nz_.assign(p_.A_d);
    Bd_nz_.assign(p_.B_d);
    Be_nz_.assign(p_.B_e);
    // lead_ = L: rows L.. of A_d are upper triangular with a nonzero diagonal (then so are those
    // of A_d U: the time update scales them instead of re-factoring, see predict_candidate).
    lead_ = 0;
    for (int i = 0; i < N; ++i)
      if (A_nz_.first_col(i) < i || !(p_.A_d(i, i) != S(0))) lead_ = i + 1;
    UdFactors<NU, S> Sf = UdFactors<NU, S>::zero();
    ok = ok && ud_factorize<NU>(p_.S, Sf) && ud_factorize<NY>(p_.R, Rf_) && ud_factorize<N>(p_.P0, f0_);
    if (ok) {
      // C̃ = U_R⁻¹ C_d: back substitution, rows from the last (U_R unit upper triangular).
      Mat<NY, N, S> Ct = p_.C_d;
      for (int i = NY - 1; i >= 0; --i)
        for (int k = i + 1; k < NY; ++k) Ct.row(i) -= Rf_.U(i, k) * Ct.row(k);
      C_nz_.assign(Ct);
      for (int i = 0; i < NY; ++i) first_[i] = C_nz_.first_col(i);
      ok = collect_noise_columns(Sf);
    }
    status_ = ok ? Status::ok : Status::invalid_parameter;
    const S trP0 = p_.P0.trace();
    theta_fixed_ = trP0 > S(0) ? std::sqrt(q1_trace_ / trP0) : S(0);  // θ* (literal)
    reset();
  }

  //! ok, or invalid_parameter: as Eskf::status (valid(EskfParams)), or more than NG noise columns.
  //! A refused filter answers invalid_parameter from predict(), update() and step() with its
  //! estimate untouched.
  Status status() const noexcept { return status_; }
  const Params& params() const noexcept { return p_; }
  S period_s() const noexcept { return p_.period_s; }

  //! step(), predict(), update(), set_estimate(): detail::CandidateFilter.
  //! θ* = √(tr Q1 / tr P_0), the fixed θ of ThetaPolicy::fixed_initial.
  S theta_fixed() const noexcept { return theta_fixed_; }

  //! X̂ = X̂_0, P = P_0 (its factors, computed once at construction), θ cleared.
  void reset() noexcept {
    x_ = p_.x0;
    cur_ = 0;
    fb_[0] = f0_;
    ++generation_;  // a candidate made before the reset can no longer be accepted
    theta_ = S(0);
  }

  // ---- Two-phase form (detail::CandidateFilter, PartitionedFilter), as Eskf's.
  //! A step's result before accept(). Its factors are not in it: they are written into the
  //! filter's spare buffer (issue 20: copying the 18-state factors into each candidate and back
  //! was ~3,500 Cortex-M7 instructions per sample). So a filter holds one candidate at a time:
  //! making another replaces it, and accept() of any but the last one made changes nothing.
  struct Candidate {
    State x;
    S theta = S(-1);          //!< θ of a prediction; < 0 otherwise
    int slot = -1;            //!< the buffer holding its factors (< 0: none written)
    unsigned generation = 0;  //!< which of the filter's candidates it is
  };

  //! (A_d U)ᵀ (the first half of the time update; column i is row i of A_d U), from A_d's
  //! nonzeros: contiguous column operations on Uᵀ (SparseRows::mul_by_transpose). Measured on
  //! the Cortex-M7: 6,000 instructions fewer per sample than a row-by-row loop over U's
  //! triangle, which does half the multiply-adds on strided data.
  using Propagation = Mat<N, N, S>;
  Propagation propagate() const noexcept { return A_nz_.mul_by_transpose(Mat<N, N, S>(f().U.transpose())); }
  //! tr(A_d P A_dᵀ) = Σ_k D_k ‖(A_d U)(:, k)‖².
  S propagated_trace(const Propagation& AUt) const noexcept {
    return (f().D.transpose() * AUt.cwiseAbs2()).sum();
  }
  //! tr Q1, Q1 = 4 B_e (l diag q) B_eᵀ.
  S q1_trace() const noexcept { return q1_trace_; }

  //! The time update with a given (A_d U)ᵀ and θ (see the file comment). The
  //! limits θ → 0 (no increment bound) and θ → ∞ (A_d P A_dᵀ = 0) as bounded_increment_prediction.
  [[nodiscard]] Status predict_candidate(const Vec<NU, S>& u, const Vec<NL, S>& delta_f_nominal, const Propagation& AUt,
                                         S theta, Candidate& out) const noexcept {
    if (status_ != Status::ok) return status_;
    if (!all_finite(u) || !all_finite(delta_f_nominal)) return Status::non_finite_input;
    out.x = detail::extended_state_prediction<N, NU, NL>(A_nz_, Bd_nz_, Be_nz_, sqrt_q_, x_, u, delta_f_nominal);
    Factors& f = begin_candidate(out);
    S wP = S(1), wQ1 = S(1);  // θ → ∞: APA = 0, no inflation
    if (!(theta > S(0))) wQ1 = S(0);  // no increment bound: the plain Kalman prediction (Q1 = 0)
    else if (std::isfinite(theta)) {
      wP = S(1) + theta;
      wQ1 = S(1) + S(1) / theta;
    }
    // (1+θ) A_d P A_dᵀ = T D̃ Tᵀ with T = A_d U, D̃ = (1+θ) D. Rows L.. of T are upper triangular
    // with T_ii = A_ii ≠ 0 (construction), so with S = diag(T_ii), i ≥ L:
    //   U⁻(:, L:) = T(:, L:) S⁻¹,  D⁻(L:) = S² D̃(L:)              (exact: T22 D̃2 T22ᵀ = U22 S²D̃2 U22ᵀ)
    // and the leading L x L block is T11 D̃1 T11ᵀ, re-factored by Thornton's MWGS (mwgs_ud).
    Mat<N, N, S> T = AUt.transpose();
    const Eigen::Matrix<S, 1, N> wD = wP * this->f().D.transpose();
    const std::array<int, N> first{};
    mwgs_ud<N, N>(T, wD, first, lead_, lead_, f);  // T11 only (rows and columns < L)
    for (int j = lead_; j < N; ++j) {  // the columns mwgs_ud leaves to us, whole
      const S s_j = T(j, j);
      S* u = f.U.col(j).data();
      const S* t = T.col(j).data();
      for (int i = 0; i < j; ++i) u[i] = t[i] / s_j;
      u[j] = S(1);
      for (int i = j + 1; i < N; ++i) u[i] = S(0);
      f.D(j) = s_j * s_j * wD(j);
    }
    // + (1 + 1/θ) Q1 + Q2 = Σ_k w_k g_k g_kᵀ: one Agee–Turner rank-one update per noise column.
    for (int k = 0; k < ng_; ++k) {
      const S wk = g_weight_(k) + wQ1 * g_weight_q1_(k);
      Vec<N, S> g = G_.col(k);
      agee_turner_update<N>(f, wk, g);
    }
    if (!all_finite(out.x) || !representable(f)) return Status::out_of_range;
    out.theta = theta;
    return Status::ok;
  }

  //! The measurement update (update()): z = U_R⁻¹ Y, then one Bierman update per row of C̃.
  //! non_finite_input / out_of_range (overflow) change nothing. The innovation variances are ≥ the
  //! decorrelated R's D_R > 0, so there is no singular case.   Algorithm 1 measurement update
  [[nodiscard]] Status update_candidate(const Vec<NY, S>& Y, Candidate& out) const noexcept {
    if (status_ != Status::ok) return status_;
    if (!all_finite(Y)) return Status::non_finite_input;
    Vec<NY, S> z = Y;  // U_R z = Y, rows from the last
    for (int i = NY - 1; i >= 0; --i)
      for (int k = i + 1; k < NY; ++k) z(i) -= Rf_.U(i, k) * z(k);
    out.x = x_;
    Factors& f = begin_candidate(out);
    Vec<N, S> fv, k;
    if (NY == 0) f = this->f();  // no output: the candidate's factors are the current ones
    for (int i = 0; i < NY; ++i) {
      // The first output reads the current factors and writes the candidate's (out of place: no
      // copy of them first), the others update the candidate's in place.
      const Factors& in = i == 0 ? this->f() : f;
      fv.setZero();  // f = Uᵀ c̃ᵢᵀ from c̃ᵢ's nonzeros
      for (int e = C_nz_.start[i]; e < C_nz_.start[i + 1]; ++e) fv += C_nz_.val[e] * in.U.row(C_nz_.col[e]).transpose();
      const S innovation = z(i) - C_nz_.row_dot(i, out.x);
      bierman_update<N>(in, f, fv, Rf_.D(i), first_[i], k);
      out.x += k * innovation;
    }
    if (!all_finite(out.x) || !representable(f)) return Status::out_of_range;
    out.theta = S(-1);
    return Status::ok;
  }

  //! Makes the candidate the filter's estimate: its factors' buffer becomes the current one.
  //! Nothing changes for a candidate that is not the last one this filter made (Candidate).
  void accept(const Candidate& c) noexcept {
    if (c.slot < 0 || c.generation != generation_) return;
    x_ = c.x;
    cur_ = c.slot;
    ++generation_;  // accepted once
    if (c.theta >= S(0)) theta_ = c.theta;
  }

  const State& state() const noexcept { return x_; }
  //! The factors themselves.
  const Factors& factors() const noexcept { return f(); }
  //! P = U D Uᵀ, formed (N³/6: for tests and telemetry, not the step).
  Covariance covariance() const noexcept { return ud_covariance<N>(f()); }
  S covariance_entry(int i, int j) const noexcept { return ud_covariance_entry<N>(f(), i, j); }
  S theta() const noexcept { return theta_; }
  //! Always 0: the factored covariance never leaves the PSD cone (Eskf counts its projections).
  long psd_projections() const noexcept { return 0; }

  //! set_estimate's check: non_finite_input for non-finite values; invalid_parameter for a P that
  //! is not symmetric PSD (it has no U-D factors).
  [[nodiscard]] Status estimate_candidate(const State& x, const Covariance& P, Candidate& out) const noexcept {
    if (!all_finite(x) || !all_finite(P)) return Status::non_finite_input;
    Factors& f = begin_candidate(out);
    if (!symmetric<N, S>(P) || !ud_factorize<N>(P, f) || !representable(f)) return Status::invalid_parameter;
    out.x = x;
    out.theta = S(-1);
    return Status::ok;
  }

  //! Eskf::replace_substate (seed 004 eqs. (40)-(41)) on the factors: P' = E P E + Γᵀ P_o Γ with E
  //! zeroing the rows and columns idx. E U D Uᵀ E keeps U's columns k ∉ idx (rows idx zeroed) and
  //! turns each column j ∈ idx into c_j = E U(:, j), which lies above j: so P' = Ũ D̃ Ũᵀ +
  //! Σ_j D_j c_j c_jᵀ + Σ_b D_o,b (Γᵀ U_o,b)(Γᵀ U_o,b)ᵀ with Ũ = U whose rows and columns idx are
  //! those of I and D̃_idx = 0, and the sums are Agee–Turner rank-one updates (non-negative
  //! weights: PSD by construction, no factorisation of a formed P). invalid_parameter for bad or
  //! repeated indices or a P_o that is not symmetric PSD, non_finite_input for non-finite values,
  //! out_of_range for a result beyond double's range (representable); nothing changes then.
  template <int K>
  [[nodiscard]] Status replace_substate(const std::array<int, K>& idx, const Vec<K, S>& x_o, const Mat<K, K, S>& P_o) noexcept {
    if (const Status s = detail::substate_check<N, K>(idx, x_o, P_o); s != Status::ok) return s;
    UdFactors<K, S> fo = UdFactors<K, S>::zero();
    if (!symmetric<K, S>(P_o) || !ud_factorize<K>(P_o, fo)) return Status::invalid_parameter;
    ++generation_;  // the spare is overwritten: an outstanding candidate can no longer be accepted
    Factors& f = fb_[1 - cur_];
    f = this->f();
    Mat<N, K, S> c;
    Vec<K, S> d;
    for (int a = 0; a < K; ++a) {
      c.col(a) = f.U.col(idx[a]);
      d(a) = f.D(idx[a]);
    }
    for (int a = 0; a < K; ++a) {  // E: rows idx of c and of U; columns idx of U become e_j
      c.row(idx[a]).setZero();
      f.U.row(idx[a]).setZero();
      f.U.col(idx[a]).setZero();
      f.U(idx[a], idx[a]) = S(1);
      f.D(idx[a]) = S(0);
    }
    Vec<N, S> v;
    for (int a = 0; a < K; ++a) {  // + D_j c_j c_jᵀ
      v = c.col(a);
      agee_turner_update<N>(f, d(a), v);
    }
    for (int b = 0; b < K; ++b) {  // + Γᵀ P_o Γ
      v.setZero();
      for (int a = 0; a < K; ++a) v(idx[a]) = fo.U(a, b);
      agee_turner_update<N>(f, fo.D(b), v);
    }
    if (!representable(f)) return Status::out_of_range;  // nothing changed
    cur_ = 1 - cur_;
    for (int a = 0; a < K; ++a) x_(idx[a]) = x_o(a);
    return Status::ok;
  }

 private:
  //! The current factors.
  const Factors& f() const noexcept { return fb_[cur_]; }
  //! The spare buffer, for a new candidate's factors (Candidate); stamps the candidate.
  Factors& begin_candidate(Candidate& out) const noexcept {
    out.slot = 1 - cur_;
    out.generation = ++generation_;
    return fb_[out.slot];
  }

  //! The factors are finite and so is P = U D Uᵀ: every P_ii = Σ_k U_ik² D_k is (then so is every
  //! P_ij, |P_ij| ≤ √(P_ii P_jj), and each partial sum of it by Cauchy–Schwarz). Finite factors
  //! can still describe a P beyond DBL_MAX (found by fuzz_seed004): such a step is refused. The
  //! sums also test the factors themselves: every D_k is in P_kk (U_kk = 1) and every U_ik, k > i,
  //! in P_ii, where a NaN or an infinity gives NaN or ∞ even with D_k = 0 (∞ · 0 = NaN); the
  //! entries below the diagonal are never written. So no separate finiteness pass over U and D.
  static bool representable(const Factors& f) noexcept {
    for (int i = 0; i < N; ++i) {
      S p_ii = S(0);
      for (int k = i; k < N; ++k) p_ii += f.U(i, k) * f.U(i, k) * f.D(k);
      if (!std::isfinite(p_ii)) return false;
    }
    return true;
  }

  //! G and its weights: B_e's columns with q_i > 0 (weight 4 l q_i, times 1 + 1/θ per step) and
  //! B_d U_s's with d_s,i > 0 (weight d_s,i); all-zero columns (another block's) are left out.
  //! False when more than NG remain.
  bool collect_noise_columns(const UdFactors<NU, S>& Sf) noexcept {
    G_.setZero();
    g_weight_.setZero();
    g_weight_q1_.setZero();
    q1_trace_ = S(0);
    int& m = ng_;
    m = 0;
    for (int i = 0; i < NL; ++i) {
      const S wq = S(4) * static_cast<S>(NL) * p_.q(i);  // Q1 = 4 B_e (l diag q) B_eᵀ
      if (!(wq > S(0)) || p_.B_e.col(i).isZero(S(0))) continue;
      if (m == NG) return false;
      G_.col(m) = p_.B_e.col(i);
      g_weight_q1_(m++) = wq;
      q1_trace_ += wq * p_.B_e.col(i).squaredNorm();
    }
    const Mat<N, NU, S> BU = p_.B_d * Sf.U;  // Q2 = B_d S B_dᵀ = (B_d U_s) D_s (B_d U_s)ᵀ
    for (int i = 0; i < NU; ++i) {
      if (!(Sf.D(i) > S(0)) || BU.col(i).isZero(S(0))) continue;
      if (m == NG) return false;
      G_.col(m) = BU.col(i);
      g_weight_(m++) = Sf.D(i);
    }
    return true;
  }

  Params p_;
  SparseRows<N, N, S> A_nz_;
  SparseRows<N, NU, S> Bd_nz_;
  SparseRows<N, NL, S> Be_nz_;
  SparseRows<NY, N, S> C_nz_;  //!< C̃ = U_R⁻¹ C_d
  std::array<int, NY> first_{};
  int lead_ = N;                  //!< L: rows L.. of A_d upper triangular, nonzero diagonal
  int ng_ = 0;                    //!< noise columns in use (≤ NG)
  UdFactors<NY, S> Rf_ = UdFactors<NY, S>::zero();
  Factors f0_ = Factors::zero();
  Mat<N, NG, S> G_ = Mat<N, NG, S>::Zero();
  Eigen::Matrix<S, 1, NG> g_weight_ = Eigen::Matrix<S, 1, NG>::Zero();     //!< Q2 columns: d_s,i
  Eigen::Matrix<S, 1, NG> g_weight_q1_ = Eigen::Matrix<S, 1, NG>::Zero();  //!< Q1 columns: 4 l q_i
  Vec<NL, S> sqrt_q_ = Vec<NL, S>::Zero();
  S q1_trace_ = S(0);
  S theta_fixed_ = S(0);
  Status status_ = Status::ok;
  State x_ = State::Zero();
  //! The current factors (fb_[cur_]) and the spare one a candidate is written into. Mutable: the
  //! *_candidate functions are const (they do not change the estimate) but write the spare; so
  //! one filter object is not for concurrent candidates from several threads.
  mutable std::array<Factors, 2> fb_{Factors::zero(), Factors::zero()};
  int cur_ = 0;
  mutable unsigned generation_ = 0;  //!< stamps candidates: only the last one made is accepted
  S theta_ = S(0);
};

ADCS_ASSERT_COMPONENT(EskfUd<3, 1, 1, 1>);

}  // namespace adcs
