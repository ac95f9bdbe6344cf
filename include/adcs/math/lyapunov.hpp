#pragma once
// Continuous Lyapunov equation A^T P + P A = -Q for a fixed n <= 12 (seed 001 §A.3: P from
// A_1^T P + P A_1 = -I_6). Computed once at construction, never in a step().
//
// Method: complex Schur form A = U T U^* (Bartels & Stewart 1972 with a triangular T). With
// Y = U^* P U and C = -U^* Q U the equation becomes T^* Y + Y T = C, solved entry by entry:
//   (conj(T_ii) + T_jj) Y_ij = C_ij - sum_{k<i} conj(T_ki) Y_kj - sum_{k<j} Y_ik T_kj.
// It has a unique solution iff lambda_i + conj(lambda_j) != 0 for all eigenvalue pairs (true
// for any Hurwitz A). Storage is O(n^2) on the stack (a Kronecker solve would need n^4).
#include <Eigen/Eigenvalues>
#include <complex>

#include "adcs/core/status.hpp"
#include "adcs/core/types.hpp"

namespace adcs {

//! Solves A^T P + P A = -Q. Returns non_finite_input, not_converged (Schur iteration limit) or
//! singular (lambda_i + conj(lambda_j) ~ 0) with P untouched; ok otherwise. P is symmetrised
//! when Q is symmetric.
template <int N>
Status solve_continuous_lyapunov(const Mat<N, N>& A, const Mat<N, N>& Q, Mat<N, N>& P) noexcept {
  static_assert(N >= 1 && N <= 12, "fixed-size Lyapunov solver is for 1 <= n <= 12");
  using CMat = Eigen::Matrix<std::complex<double>, N, N>;
  if (!all_finite(A) || !all_finite(Q)) return Status::non_finite_input;

  Eigen::ComplexSchur<Mat<N, N>> schur;
  schur.setMaxIterations(100 * N);  // hard bound on the QR iteration
  schur.compute(A, true);
  if (schur.info() != Eigen::Success) return Status::not_converged;
  const CMat& T = schur.matrixT();
  const CMat& U = schur.matrixU();

  const CMat C = -(U.adjoint() * Q.template cast<std::complex<double>>() * U);
  CMat Y = CMat::Zero();
  const double scale = A.cwiseAbs().maxCoeff() + 1.0;
  for (int i = 0; i < N; ++i) {
    for (int j = 0; j < N; ++j) {
      std::complex<double> rhs = C(i, j);
      for (int k = 0; k < i; ++k) rhs -= std::conj(T(k, i)) * Y(k, j);
      for (int k = 0; k < j; ++k) rhs -= Y(i, k) * T(k, j);
      const std::complex<double> d = std::conj(T(i, i)) + T(j, j);
      if (!(std::abs(d) > 1e-14 * scale)) return Status::singular;
      Y(i, j) = rhs / d;
    }
  }
  const Mat<N, N> Preal = (U * Y * U.adjoint()).real();
  if (!all_finite(Preal)) return Status::singular;
  if ((Q - Q.transpose()).cwiseAbs().maxCoeff() == 0.0) {
    P = 0.5 * (Preal + Preal.transpose());
  } else {
    P = Preal;
  }
  return Status::ok;
}

}  // namespace adcs
