#pragma once
// Predicates the constructors use to validate their parameter structs (issue 15, "Validation";
// docs/VALIDATION.md lists what each component checks). Each is true only for finite input, so a
// field left at its quiet-NaN default ("no default: set it") fails every one of them.
#include <cmath>
#include <limits>

#include <Eigen/Cholesky>
#include <Eigen/Core>

#include "adcs/core/types.hpp"

namespace adcs {

//! The default of a parameter that has none: quiet NaN, which fails every check below, so a
//! forgotten field makes its component answer invalid_parameter instead of running on a made-up
//! value.
inline constexpr double kUnset = std::numeric_limits<double>::quiet_NaN();

//! x finite and > 0 (periods, masses, widths, limits).
inline bool finite_positive(double x) noexcept { return std::isfinite(x) && x > 0.0; }

//! x finite and >= 0 (gains that may be switched off, variances, leakages).
inline bool finite_nonnegative(double x) noexcept { return std::isfinite(x) && x >= 0.0; }

//! Every coefficient finite and >= 0.
template <class Derived>
bool finite_nonnegative(const Eigen::DenseBase<Derived>& x) noexcept {
  return all_finite(x) && (x.derived().array() >= 0.0).all();
}

//! Every coefficient finite and > 0.
template <class Derived>
bool finite_positive(const Eigen::DenseBase<Derived>& x) noexcept {
  return all_finite(x) && (x.derived().array() > 0.0).all();
}

//! A finite and symmetric to rel_tol of its largest entry. Eigen's factorisations read only the
//! lower triangle, so without this an asymmetric inertia or covariance would pass unnoticed.
template <int N>
bool symmetric(const Mat<N, N>& A, double rel_tol = 1e-12) noexcept {
  return all_finite(A) && (A - A.transpose()).cwiseAbs().maxCoeff() <= rel_tol * A.cwiseAbs().maxCoeff();
}

//! A finite, symmetric and positive definite (its Cholesky factorisation exists): inertias,
//! measurement-noise covariances, Lyapunov weights.
template <int N>
bool symmetric_positive_definite(const Mat<N, N>& A) noexcept {
  return symmetric<N>(A) && Eigen::LLT<Mat<N, N>>(A).info() == Eigen::Success;
}

//! A finite, symmetric and positive semidefinite: the pivots of its (pivoting) LDLᵀ
//! factorisation are >= 0 up to rounding (1e-12 of the largest entry). For covariances that may
//! be singular: process noise of a channel without noise, an initial covariance that knows some
//! states exactly.
template <int N>
bool symmetric_positive_semidefinite(const Mat<N, N>& A) noexcept {
  if (!symmetric<N>(A)) return false;
  const Eigen::LDLT<Mat<N, N>> ldlt(A);
  return ldlt.info() == Eigen::Success &&
         (ldlt.vectorD().array() >= -1e-12 * A.cwiseAbs().maxCoeff()).all();
}

//! Every column of A finite with unit norm within tol (spin and gimbal axes given as directions).
template <int R, int C>
bool unit_columns(const Mat<R, C>& A, double tol = 1e-6) noexcept {
  return all_finite(A) && ((A.colwise().norm().array() - 1.0).abs() <= tol).all();
}

}  // namespace adcs
