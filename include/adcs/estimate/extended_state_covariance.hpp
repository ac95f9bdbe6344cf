#pragma once
// The covariance machinery seed 004's extended-state filters share (Algorithms 1 and 2, spec
// §B.4-§B.5): the bounded-increment time update with the Young-inequality weight θ, and keeping a
// covariance symmetric positive semidefinite.
//
//   P⁻ = (1+θ) A P Aᵀ + (1 + 1/θ) Q1 + Q2,   Q1 = 4 B_e (l diag q) B_eᵀ,  Q2 = B_d S B_dᵀ
//
// θ policy (spec §B.4): trace_optimal (default [D]) θ_k = √(tr Q1 / tr(A P Aᵀ)), the minimiser of
// tr(θ APAᵀ + Q1/θ) at the current P; fixed_initial (literal [P]) θ* = √(tr Q1 / tr P_0).
#include <cmath>
#include <limits>

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>

#include "adcs/core/types.hpp"

namespace adcs {

enum class ThetaPolicy {
  trace_optimal,  //!< θ_k = √(tr Q1 / tr(A P Aᵀ)) every step (spec §B.4 default [D])
  fixed_initial,  //!< θ* = √(tr Q1 / tr P_0) for ever (the paper's literal choice)
};

//! (1+θ) APA + (1 + 1/θ) Q1 + Q2 with the limits θ → 0 (no increment bound: young_weight gives
//! θ = 0 only when tr Q1 = 0, so Q1 = 0) and θ → ∞ (APA = 0) taken exactly, so q = 0 channels
//! (spec §B.8: T_Dtm) never produce 0·∞. θ alone decides, so a block of a partitioned filter
//! whose own Q1 is zero is still inflated by the θ of the whole filter (PartitionedEskf).
//! Every helper of this file takes the filter's scalar S from its matrix argument (issue 19).
template <int N, class S = double>
Mat<N, N, S> bounded_increment_prediction(const Mat<N, N, S>& APA, const Mat<N, N, S>& Q1, const Mat<N, N, S>& Q2,
                                          identity_t<S> theta) noexcept {
  if (!(theta > S(0))) return APA + Q2;                 // no increment bound: the plain Kalman prediction
  if (!std::isfinite(theta)) return APA + Q1 + Q2;      // APA = 0: no inflation
  return (S(1) + theta) * APA + (S(1) + S(1) / theta) * Q1 + Q2;
}

//! θ for this step: θ_k from the current A P Aᵀ, or the fixed θ*. 0 when tr Q1 = 0.
//! The same from the traces tr(A P Aᵀ) and tr Q1 (a filter split into blocks sums them).
//! In the filter's scalar S (issue 19: the U-D form also runs in float).
template <class S>
S young_weight(ThetaPolicy policy, S theta_fixed, identity_t<S> trace_APA, identity_t<S> trace_Q1) noexcept {
  if (!(trace_Q1 > S(0))) return S(0);
  if (policy == ThetaPolicy::fixed_initial) return theta_fixed;
  return trace_APA > S(0) ? std::sqrt(trace_Q1 / trace_APA) : std::numeric_limits<S>::infinity();
}
template <int N, class S = double>
S young_weight(ThetaPolicy policy, identity_t<S> theta_fixed, const Mat<N, N, S>& APA, const Mat<N, N, S>& Q1) noexcept {
  return young_weight<S>(policy, theta_fixed, APA.trace(), Q1.trace());
}

//! Entries below kCovarianceFlush · tr(P) are set to zero: cross-covariances that decay
//! geometrically otherwise end in the subnormal range, where every product costs ~100x (measured:
//! the 27-state ESKF went from 40 µs to 400 µs per step). 1e-150 of the trace is far below any
//! meaningful correlation, so nothing observable changes.
inline constexpr double kCovarianceFlush = 1e-150;
//! The same floor in float: float's subnormal range starts at 1.2e-38, so 1e-150 would flush
//! nothing; 1e-20 of the trace is still far below what float resolves of a correlation (ε² =
//! 3.6e-15 of the trace) and keeps the entries it leaves in the normal range for tr P > 1e-18.
template <class S>
inline constexpr S covariance_flush_v = S(kCovarianceFlush);
template <>
inline constexpr float covariance_flush_v<float> = 1e-20f;

//! Sets entries below covariance_flush_v · |tr P| to zero (one vectorised pass).
template <int N, class S = double>
void flush_negligible(Mat<N, N, S>& P) noexcept {
  const S floor = covariance_flush_v<S> * std::abs(P.trace());
  P = (P.array().abs() < floor).select(S(0), P);
}

//! Symmetrises P and flushes negligible entries (the cheap half of keep_psd, for a sum of PSD
//! terms such as the time update, which cannot leave the cone except by rounding).
template <int N, class S = double>
void symmetrize_and_flush(Mat<N, N, S>& P) noexcept {
  P = S(0.5) * (P + P.transpose()).eval();
  flush_negligible<N, S>(P);
}

//! True when the LDLᵀ factorisation of the symmetric P without pivoting has only positive pivots
//! (P positive definite up to rounding; Sylvester). Square-root free and right-looking on a copy
//! of the lower triangle: about N³/6 multiply-adds and N divisions, the cheap proof for the usual
//! case (sqrt and divide latencies dominated the Cholesky variant at N = 18).
//! (S is not deduced, so an expression such as Mat3::Zero() converts; the filters name theirs.)
template <int N, class S = double>
bool positive_pivots(const identity_t<Mat<N, N, S>>& P) noexcept {
  Mat<N, N, S> L = P;
  S* a = L.data();  // column-major: a[i + N j] = L(i, j)
  for (int k = 0; k < N; ++k) {
    const S* __restrict ck = a + N * k;
    const S d = ck[k];
    if (!(d > S(0))) return false;
    const S inv = S(1) / d;
    for (int j = k + 1; j < N; ++j) {
      S* __restrict cj = a + N * j;  // column j != column k: no overlap
      const S ljk = ck[j] * inv;
      for (int i = j; i < N; ++i) cj[i] -= ljk * ck[i];  // A(i,j) −= A(i,k) A(j,k) / d_k
    }
  }
  return true;
}

//! For a symmetric P: if an LDLᵀ factorisation shows a negative pivot, projects P onto the PSD
//! cone by clipping eigenvalues at 0 (spec §B.4 numerics). Returns true when it projected. For a
//! PSD matrix the projection is the identity, so doing it only when needed changes nothing but
//! the cost. positive_pivots proves the usual positive definite case; LDLT settles the
//! semidefinite boundary. A P whose projection is not representable (entries near 1e308 with an
//! eigenvalue beyond DBL_MAX, or a failed decomposition) is set to NaN, so that the callers'
//! finiteness check refuses the step instead of committing a made-up covariance.
template <int N, class S = double>
bool project_if_not_psd(Mat<N, N, S>& P) noexcept {
  if (positive_pivots<N, S>(P)) return false;
  const Eigen::LDLT<Mat<N, N, S>> ldlt(P);
  if (ldlt.info() == Eigen::Success && (ldlt.vectorD().array() >= S(0)).all()) return false;
  const Eigen::SelfAdjointEigenSolver<Mat<N, N, S>> es(P);
  // Found by tests/fuzz: NaN/Inf eigenvalues went through cwiseMax(0) as 0 and gave P = 0.
  if (es.info() != Eigen::Success || !all_finite(es.eigenvalues())) {
    P.setConstant(std::numeric_limits<S>::quiet_NaN());
    return true;
  }
  const Vec<N, S> ev = es.eigenvalues().cwiseMax(S(0));
  P = es.eigenvectors() * ev.asDiagonal() * es.eigenvectors().transpose();
  P = S(0.5) * (P + P.transpose()).eval();
  return true;
}

//! Symmetrises P, flushes negligible entries and projects it onto the PSD cone when needed.
template <int N, class S = double>
bool keep_psd(Mat<N, N, S>& P) noexcept {
  symmetrize_and_flush<N, S>(P);
  return project_if_not_psd<N, S>(P);
}

}  // namespace adcs
