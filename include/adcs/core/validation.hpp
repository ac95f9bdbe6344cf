#pragma once
// Predicates the constructors use to validate their parameter structs (issue 15, "Validation";
// docs/VALIDATION.md lists what each component checks). Each is true only for finite input, so a
// field left at its quiet-NaN default ("no default: set it") fails every one of them.
#include <cmath>
#include <limits>
#include <type_traits>

#include <Eigen/Cholesky>
#include <Eigen/Core>

#include "adcs/core/types.hpp"

namespace adcs {

//! The default of a parameter that has none: quiet NaN, which fails every check below, so a
//! forgotten field makes its component answer invalid_parameter instead of running on a made-up
//! value.
inline constexpr double kUnset = std::numeric_limits<double>::quiet_NaN();
//! The same in the scalar S (the parameter structs of the float instantiations).
template <class S>
inline constexpr S unset_v = std::numeric_limits<S>::quiet_NaN();

//! Relative tolerance of the symmetry and semidefiniteness checks: 1e-12 in double (~4500
//! rounding units, the value these checks always had), 4096 rounding units (~4.9e-4) in float,
//! where a covariance assembled from products is symmetric only to a few hundred units.
template <class S>
inline constexpr S validation_rel_tol_v =
    std::is_same_v<S, double> ? S(1e-12) : S(4096) * std::numeric_limits<S>::epsilon();

//! x finite and > 0 (periods, masses, widths, limits).
template <class S, std::enable_if_t<std::is_floating_point_v<S>, int> = 0>
inline bool finite_positive(S x) noexcept { return std::isfinite(x) && x > S(0); }

//! x finite and >= 0 (gains that may be switched off, variances, leakages).
template <class S, std::enable_if_t<std::is_floating_point_v<S>, int> = 0>
inline bool finite_nonnegative(S x) noexcept { return std::isfinite(x) && x >= S(0); }

//! Every coefficient finite and >= 0.
template <class Derived>
bool finite_nonnegative(const Eigen::DenseBase<Derived>& x) noexcept {
  using S = typename Derived::Scalar;
  return all_finite(x) && (x.derived().array() >= S(0)).all();
}

//! Every coefficient finite and > 0.
template <class Derived>
bool finite_positive(const Eigen::DenseBase<Derived>& x) noexcept {
  using S = typename Derived::Scalar;
  return all_finite(x) && (x.derived().array() > S(0)).all();
}

// The matrix checks take the size and the scalar explicitly (`symmetric_positive_definite<3>(J)`
// for double, `<3, float>` for float), so any Eigen expression of that size is accepted.

//! A finite and symmetric to rel_tol of its largest entry. Eigen's factorisations read only the
//! lower triangle, so without this an asymmetric inertia or covariance would pass unnoticed.
template <int N, class S = double>
bool symmetric(const identity_t<Mat<N, N, S>>& A, identity_t<S> rel_tol = validation_rel_tol_v<S>) noexcept {
  return all_finite(A) && (A - A.transpose()).cwiseAbs().maxCoeff() <= rel_tol * A.cwiseAbs().maxCoeff();
}

//! A finite, symmetric and positive definite (its Cholesky factorisation exists): inertias,
//! measurement-noise covariances, Lyapunov weights.
template <int N, class S = double>
bool symmetric_positive_definite(const identity_t<Mat<N, N, S>>& A) noexcept {
  return symmetric<N, S>(A) && Eigen::LLT<Mat<N, N, S>>(A).info() == Eigen::Success;
}

//! A finite, symmetric and positive semidefinite: the pivots of its (pivoting) LDLᵀ
//! factorisation are >= 0 up to rounding (validation_rel_tol_v of the largest entry). For
//! covariances that may be singular: process noise of a channel without noise, an initial
//! covariance that knows some states exactly.
template <int N, class S = double>
bool symmetric_positive_semidefinite(const identity_t<Mat<N, N, S>>& A) noexcept {
  if (!symmetric<N, S>(A)) return false;
  const Eigen::LDLT<Mat<N, N, S>> ldlt(A);
  return ldlt.info() == Eigen::Success &&
         (ldlt.vectorD().array() >= -validation_rel_tol_v<S> * A.cwiseAbs().maxCoeff()).all();
}

//! Every column of A finite with unit norm within tol (spin and gimbal axes given as directions).
template <int R, int C, class S = double>
bool unit_columns(const identity_t<Mat<R, C, S>>& A, identity_t<S> tol = S(1e-6)) noexcept {
  return all_finite(A) && ((A.colwise().norm().array() - S(1)).abs() <= tol).all();
}

}  // namespace adcs
