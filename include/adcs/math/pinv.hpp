#pragma once
// Right pseudo-inverse of a fat, full-row-rank matrix X (R <= C): u = X^T (X X^T)^-1 v, the
// minimum-norm solution of X u = v (seed 001 §A.3 step 10), and a singularity-robust (damped
// least-squares) variant u = X^T (X X^T + lambda^2 I)^-1 v for steering near singular geometry.
// Every call reports the conditioning it saw: an inversion whose status is ignored is the bug
// Basilisk's rwMotorTorque has; here the status is [[nodiscard]].
#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <limits>
#include <type_traits>

#include "adcs/core/status.hpp"
#include "adcs/core/types.hpp"

namespace adcs {

//! Diagnostics of one inversion. Singular values are those of X (sqrt of eig(X X^T)).
template <class S = double>
struct PinvInfoT {
  S sigma_min = S(0);    //!< [-] smallest singular value of X
  S sigma_max = S(0);    //!< [-] largest singular value of X
  S condition = S(0);    //!< [-] cond(X X^T) = (sigma_max / sigma_min)^2 (inf if singular)
  S damping = S(0);      //!< [-] lambda^2 added to X X^T (0 for the exact inverse)
  bool damped = false;   //!< true if the damped (singularity-robust) inverse was used
};
using PinvInfo = PinvInfoT<double>;

//! Threshold on cond(X X^T) beyond which the exact inverse is refused (seed 001 §A.3 step 10
//! flags cond(M) > 1e12).
inline constexpr double kPinvMaxCondition = 1e12;
//! The same threshold per scalar: 1e12 in double; 1e5 in float, whose LDLT solve loses
//! ~cond · 1.2e-7 of relative accuracy (≤ ~1 % at 1e5; at 1e12 the answer would be noise).
template <class S>
inline constexpr S pinv_max_condition_v = std::is_same_v<S, double> ? S(kPinvMaxCondition) : S(1e5);

namespace detail {
template <int R, int C, class S>
inline void fill_singular_values(const Mat<R, R, S>& M, PinvInfoT<S>& info) noexcept {
  Eigen::SelfAdjointEigenSolver<Mat<R, R, S>> eig;
  if constexpr (R == 3) {
    // Closed-form (trigonometric) eigenvalues: ~5x faster than the QR iteration, absolute error
    // ~eps * lambda_max, so the condition number stays meaningful up to ~1e13 (> our 1e12 cap).
    eig.computeDirect(M, Eigen::EigenvaluesOnly);
  } else {
    eig.compute(M, Eigen::EigenvaluesOnly);
  }
  const S lmin = std::max(eig.eigenvalues()(0), S(0));
  const S lmax = std::max(eig.eigenvalues()(R - 1), S(0));
  info.sigma_min = std::sqrt(lmin);
  info.sigma_max = std::sqrt(lmax);
  info.condition = lmin > S(0) ? lmax / lmin : std::numeric_limits<S>::infinity();
}
}  // namespace detail

namespace detail {
//! Shared front end of the exact inverses: finiteness, conditioning report and refusal, LDLT of
//! X X^T. Returns ok with `ldlt` factored, or the status to return (outputs untouched).
template <int R, int C, class S>
inline Status factor_gram(const Mat<R, C, S>& X, Eigen::LDLT<Mat<R, R, S>>& ldlt,
                          PinvInfoT<S>* info) noexcept {
  static_assert(R <= C, "right pseudo-inverse needs a fat matrix (rows <= cols)");
  if (!all_finite(X)) return Status::non_finite_input;
  const Mat<R, R, S> M = X * X.transpose();
  PinvInfoT<S> local;
  fill_singular_values<R, C, S>(M, local);
  if (info) *info = local;
  if (!(local.condition <= pinv_max_condition_v<S>)) return Status::singular;
  ldlt.compute(M);
  return ldlt.info() == Eigen::Success ? Status::ok : Status::singular;
}
}  // namespace detail

//! u = X^T (X X^T)^-1 v through an LDLT of the SPD matrix X X^T.
//! Returns non_finite_input, singular (cond(X X^T) > kPinvMaxCondition) or out_of_range (finite
//! inputs whose solution overflows, e.g. |v| ~ 1e300) with u untouched.
template <int R, int C, class S>
Status right_pinv_solve(const Mat<R, C, S>& X, const identity_t<Vec<R, S>>& v, Vec<C, S>& u,
                        PinvInfoT<S>* info = nullptr) noexcept {
  if (!all_finite(v)) return Status::non_finite_input;
  Eigen::LDLT<Mat<R, R, S>> ldlt;
  const Status s = detail::factor_gram<R, C, S>(X, ldlt, info);
  if (s != Status::ok) return s;
  const Vec<R, S> y = ldlt.solve(v);
  const Vec<C, S> result = X.transpose() * y;
  if (!all_finite(result)) return Status::out_of_range;  // never hand out Inf/NaN as a solution
  u = result;
  return Status::ok;
}

//! The matrix X^+ = X^T (X X^T)^-1 itself (for tests and offline allocation matrices).
template <int R, int C, class S>
Status right_pinv(const Mat<R, C, S>& X, Mat<C, R, S>& X_pinv, PinvInfoT<S>* info = nullptr) noexcept {
  Eigen::LDLT<Mat<R, R, S>> ldlt;
  const Status s = detail::factor_gram<R, C, S>(X, ldlt, info);
  if (s != Status::ok) return s;
  const Mat<C, R, S> result = X.transpose() * ldlt.solve(Mat<R, R, S>::Identity());
  if (!all_finite(result)) return Status::out_of_range;  // X X^T finite but its inverse overflowed
  X_pinv = result;
  return Status::ok;
}

//! Parameters of the singularity-robust inverse. Damping follows the classic "variable
//! damping" rule (Nakamura & Hanafusa 1986; Maciejewski & Klein 1988): no damping while
//! sigma_min >= sigma_threshold, then lambda^2 = lambda_max^2 (1 - (sigma_min/sigma_threshold)^2),
//! so the inverse is continuous in X and bounded at an exactly singular X:
//! |u| <= |v| / (2 lambda) along the lost direction.
template <class S = double>
struct DampingParamsT {
  S sigma_threshold = S(1e-3);  //!< [-] sigma_min below which damping starts
  S lambda_max = S(1e-2);       //!< [-] damping at sigma_min = 0 (lambda, not squared)
};
using DampingParams = DampingParamsT<double>;

//! u = X^T (X X^T + lambda^2 I)^-1 v. Returns ok (no damping needed), ill_conditioned (damped,
//! u usable), or non_finite_input / singular / out_of_range (finite inputs whose solution
//! overflows, e.g. |v| ~ 1e300 through a damped inverse) with u untouched. singular means the damped Gram
//! matrix is numerically singular (LDLT rcond <= 1e-16): possible only with lambda_max = 0 near
//! rank loss, or when sigma_max^2 / lambda^2 exceeds ~1e16 (e.g. sigma_max >~ 1e6 with the
//! default damping) -- scale X or raise lambda_max then.
template <int R, int C, class S>
Status damped_right_pinv_solve(const Mat<R, C, S>& X, const identity_t<Vec<R, S>>& v, Vec<C, S>& u,
                               const DampingParamsT<S>& params, PinvInfoT<S>* info = nullptr) noexcept {
  static_assert(R <= C, "right pseudo-inverse needs a fat matrix (rows <= cols)");
  if (!all_finite(X) || !all_finite(v)) return Status::non_finite_input;
  Mat<R, R, S> M = X * X.transpose();
  PinvInfoT<S> local;
  detail::fill_singular_values<R, C, S>(M, local);
  if (local.sigma_min < params.sigma_threshold) {
    const S r = local.sigma_min / params.sigma_threshold;
    local.damping = params.lambda_max * params.lambda_max * (S(1) - r * r);
    local.damped = local.damping > S(0);
    M.diagonal().array() += local.damping;
  }
  if (info) *info = local;
  const Eigen::LDLT<Mat<R, R, S>> ldlt(M);
  if (ldlt.info() != Eigen::Success || !(ldlt.rcond() > S(1) / (S(1e4) * pinv_max_condition_v<S>)))
    return Status::singular;
  const Vec<R, S> y = ldlt.solve(v);
  const Vec<C, S> result = X.transpose() * y;
  if (!all_finite(result)) return Status::out_of_range;  // a usable status promises a finite u
  u = result;
  return local.damped ? Status::ill_conditioned : Status::ok;
}

}  // namespace adcs
