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

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>

#include "adcs/core/types.hpp"

namespace adcs {

enum class ThetaPolicy {
  trace_optimal,  //!< θ_k = √(tr Q1 / tr(A P Aᵀ)) every step (spec §B.4 default [D])
  fixed_initial,  //!< θ* = √(tr Q1 / tr P_0) for ever (the paper's literal choice)
};

//! (1+θ) APA + (1 + 1/θ) Q1 + Q2 with the limits θ → 0 (Q1 = 0) and θ → ∞ (APA = 0) taken
//! exactly, so q = 0 channels (spec §B.8: T_Dtm) never produce 0·∞.
template <int N>
Mat<N, N> bounded_increment_prediction(const Mat<N, N>& APA, const Mat<N, N>& Q1, const Mat<N, N>& Q2,
                                       double theta) noexcept {
  const double tQ1 = Q1.trace();
  if (!(tQ1 > 0.0)) return APA + Q2;        // no increment bound: the plain Kalman prediction
  if (!(theta > 0.0) || !std::isfinite(theta)) return APA + Q1 + Q2;  // degenerate θ: no inflation
  return (1.0 + theta) * APA + (1.0 + 1.0 / theta) * Q1 + Q2;
}

//! θ for this step: θ_k from the current A P Aᵀ, or the fixed θ*. 0 when tr Q1 = 0.
template <int N>
double young_weight(ThetaPolicy policy, double theta_fixed, const Mat<N, N>& APA, const Mat<N, N>& Q1) noexcept {
  const double tQ1 = Q1.trace();
  if (!(tQ1 > 0.0)) return 0.0;
  if (policy == ThetaPolicy::fixed_initial) return theta_fixed;
  const double tAPA = APA.trace();
  return tAPA > 0.0 ? std::sqrt(tQ1 / tAPA) : INFINITY;
}

//! Symmetrises P, flushes negligible entries (see kCovarianceFlush) and, only if an LDLᵀ factorisation shows a negative pivot, projects it onto the
//! PSD cone by clipping eigenvalues at 0 (spec §B.4 numerics). Returns true when it projected.
//! For a PSD matrix the projection is the identity, so doing it only when needed changes
//! nothing but the cost (O(n³/3) instead of an eigen-decomposition every step).
//! Entries below kCovarianceFlush · tr(P) are set to zero: cross-covariances that decay
//! geometrically otherwise end in the subnormal range, where every product costs ~100x (measured:
//! the 27-state ESKF went from 40 µs to 400 µs per step). 1e-150 of the trace is far below any
//! meaningful correlation, so nothing observable changes.
inline constexpr double kCovarianceFlush = 1e-150;

//! Symmetrises P and flushes negligible entries (the cheap half of keep_psd, for a sum of PSD
//! terms such as the time update, which cannot leave the cone except by rounding).
template <int N>
void symmetrize_and_flush(Mat<N, N>& P) noexcept {
  P = 0.5 * (P + P.transpose()).eval();
  const double floor = kCovarianceFlush * std::abs(P.trace());
  P = (P.array().abs() < floor).select(0.0, P);
}

template <int N>
bool keep_psd(Mat<N, N>& P) noexcept {
  symmetrize_and_flush<N>(P);
  const Eigen::LDLT<Mat<N, N>> ldlt(P);
  if (ldlt.info() == Eigen::Success && (ldlt.vectorD().array() >= 0.0).all()) return false;
  const Eigen::SelfAdjointEigenSolver<Mat<N, N>> es(P);
  const Vec<N> ev = es.eigenvalues().cwiseMax(0.0);
  P = es.eigenvectors() * ev.asDiagonal() * es.eigenvectors().transpose();
  P = 0.5 * (P + P.transpose()).eval();
  return true;
}

}  // namespace adcs
