// Property tests of the offline/online linear algebra: right pseudo-inverse (exact and damped),
// continuous Lyapunov solver and the double-integrator pole placement (seed 001 §A.3).
// Truth values come from independent computations done here only: Eigen's JacobiSVD, a
// Kronecker-product Lyapunov solve, the closed-form P of spec §A.3 and Eigen's EigenSolver.
//
// Compile time: fixed-size Eigen code is expensive to instantiate, so each library template is
// instantiated once per size inside a thin adapter (PinvOps / LyapOps, Sophus-style explicit
// coverage of every size we claim) and the checks run on dynamic matrices in ordinary functions
// compiled once for all sizes; the typed tests only pick the adapter.
#include <gtest/gtest.h>

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <Eigen/LU>
#include <Eigen/SVD>
#include <cmath>
#include <complex>
#include <limits>
#include <random>
#include <vector>

#include "adcs/math/lyapunov.hpp"
#include "adcs/math/pinv.hpp"
#include "adcs/math/place.hpp"

namespace ADCS_UNITY_ID {

using adcs::Mat;
using adcs::Status;
using adcs::Vec;
using Eigen::MatrixXd;
using Eigen::VectorXd;
using cplx = std::complex<double>;

constexpr int kSamples = 100;
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kEps = std::numeric_limits<double>::epsilon();

class Rng {
 public:
  explicit Rng(std::uint64_t seed) : gen_(seed) {}
  double uniform(double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(gen_); }
  MatrixXd mat(Eigen::Index rows, Eigen::Index cols, double lo = -1.0, double hi = 1.0) {
    MatrixXd m(rows, cols);
    for (Eigen::Index j = 0; j < cols; ++j)
      for (Eigen::Index i = 0; i < rows; ++i) m(i, j) = uniform(lo, hi);
    return m;
  }
  VectorXd vec(Eigen::Index n, double lo = -1.0, double hi = 1.0) { return mat(n, 1, lo, hi); }
  //! Random orthogonal n x n matrix (left singular vectors of a random matrix).
  MatrixXd orthogonal(Eigen::Index n) { return Eigen::JacobiSVD<MatrixXd>(mat(n, n), Eigen::ComputeFullU).matrixU(); }
  bool coin() { return uniform(0, 1) < 0.5; }

 private:
  std::mt19937_64 gen_;
};

double max_abs(const MatrixXd& m) { return m.cwiseAbs().maxCoeff(); }

template <int N>
struct Size {
  static constexpr int n = N;
};

// =============================================================================================
// Right pseudo-inverse, typed over the fat shapes used by the allocators.

//! The three pinv entry points of one fixed shape behind a dynamic-size interface. Outputs are
//! copied in before and out after the call, so "output left untouched" stays observable.
struct PinvOps {
  Eigen::Index R, C;
  Status (*solve)(const MatrixXd& X, const VectorXd& v, VectorXd& u, adcs::PinvInfo* info);
  Status (*pinv)(const MatrixXd& X, MatrixXd& X_pinv);
  Status (*damped)(const MatrixXd& X, const VectorXd& v, VectorXd& u, const adcs::DampingParams& p,
                   adcs::PinvInfo* info);
};

template <int R, int C>
PinvOps pinv_ops() {
  PinvOps ops{};
  ops.R = R;
  ops.C = C;
  ops.solve = [](const MatrixXd& X, const VectorXd& v, VectorXd& u, adcs::PinvInfo* info) {
    const Mat<R, C> Xf = X;
    const Vec<R> vf = v;
    Vec<C> uf = u;
    const Status s = info ? adcs::right_pinv_solve(Xf, vf, uf, info) : adcs::right_pinv_solve(Xf, vf, uf);
    u = uf;
    return s;
  };
  ops.pinv = [](const MatrixXd& X, MatrixXd& X_pinv) {
    const Mat<R, C> Xf = X;
    Mat<C, R> Pf = X_pinv;
    const Status s = adcs::right_pinv(Xf, Pf);
    X_pinv = Pf;
    return s;
  };
  ops.damped = [](const MatrixXd& X, const VectorXd& v, VectorXd& u, const adcs::DampingParams& p,
                  adcs::PinvInfo* info) {
    const Mat<R, C> Xf = X;
    const Vec<R> vf = v;
    Vec<C> uf = u;
    const Status s = adcs::damped_right_pinv_solve(Xf, vf, uf, p, info);
    u = uf;
    return s;
  };
  return ops;
}

//! Fat R x C matrix U diag(s) V^T with prescribed singular values s (size R).
MatrixXd with_singular_values(Rng& rng, Eigen::Index C, const VectorXd& s) {
  const Eigen::Index R = s.size();
  MatrixXd S = MatrixXd::Zero(R, C);
  S.diagonal() = s;
  return rng.orthogonal(R) * S * rng.orthogonal(C).transpose();
}

//! Singular value decomposition computed in the test (truth).
struct Svd {
  MatrixXd U, V;
  VectorXd s;  // descending
};
Svd svd_of(const MatrixXd& X) {
  Eigen::JacobiSVD<MatrixXd> svd(X, Eigen::ComputeFullU | Eigen::ComputeFullV);
  return {svd.matrixU(), svd.matrixV(), svd.singularValues()};
}

//! Truth for the damped inverse: u = sum_i sigma_i/(sigma_i^2 + lambda^2) (u_i^T v) v_i.
VectorXd damped_truth(const Svd& d, const VectorXd& v, double lambda2) {
  VectorXd u = VectorXd::Zero(d.V.rows());
  for (Eigen::Index i = 0; i < d.s.size(); ++i) {
    const double g = d.s(i) / (d.s(i) * d.s(i) + lambda2);
    u += g * d.U.col(i).dot(v) * d.V.col(i);
  }
  return u;
}

//! X whose last row is proportional to its first: rank R - 1 exactly.
MatrixXd rank_deficient(Rng& rng, Eigen::Index R, Eigen::Index C) {
  MatrixXd X = rng.mat(R, C);
  X.row(R - 1) = rng.uniform(-3, 3) * X.row(0);
  return X;
}

void exact_inverse_is_minimum_norm(const PinvOps& ops, Rng& rng) {
  const Eigen::Index R = ops.R, C = ops.C;
  int used = 0;
  for (int k = 0; k < 3 * kSamples && used < kSamples; ++k) {
    const MatrixXd X = rng.mat(R, C);
    const VectorXd v = rng.vec(R, -2, 2);
    const Svd d = svd_of(X);
    const double cond = d.s(0) / d.s(R - 1);
    if (cond > 50.0) continue;  // the accuracy claims below are for well-conditioned X
    ++used;

    VectorXd u = VectorXd::Zero(C);
    adcs::PinvInfo info;
    ASSERT_EQ(ops.solve(X, v, u, &info), Status::ok);
    EXPECT_LE((X * u - v).norm(), 1e-12 * v.norm());
    // Minimum-norm solution: equal to the SVD pseudo-inverse solve ...
    const VectorXd u_svd = Eigen::JacobiSVD<MatrixXd>(X, Eigen::ComputeThinU | Eigen::ComputeThinV).solve(v);
    EXPECT_LE((u - u_svd).norm(), 1e-12 * u_svd.norm());
    // ... i.e. u has no component in null(X).
    EXPECT_LE((d.V.rightCols(C - R).transpose() * u).norm(), 1e-12 * u.norm());

    // Diagnostics agree with the SVD (sigma_min through eig(X X^T) loses eps cond^2 relative).
    EXPECT_LE(std::abs(info.sigma_max - d.s(0)), 1e-14 * d.s(0));
    EXPECT_LE(std::abs(info.sigma_min - d.s(R - 1)), 10 * kEps * d.s(0) * d.s(0) / d.s(R - 1));
    EXPECT_NEAR(info.condition, cond * cond, 1e-10 * cond * cond);
    EXPECT_EQ(info.damping, 0.0);
    EXPECT_FALSE(info.damped);

    // The matrix form: X X+ = I and the Moore-Penrose conditions.
    MatrixXd Xp = MatrixXd::Zero(C, R);
    ASSERT_EQ(ops.pinv(X, Xp), Status::ok);
    EXPECT_LE(max_abs(X * Xp - MatrixXd::Identity(R, R)), 1e-12);
    const MatrixXd XpX = Xp * X;
    EXPECT_LE(max_abs(XpX - XpX.transpose()), 1e-12);
    EXPECT_LE(max_abs(Xp * X * Xp - Xp), 1e-12 * max_abs(Xp));
    EXPECT_LE((Xp * v - u).norm(), 1e-12 * u.norm());
    // The info pointer is optional and does not change the answer.
    VectorXd u2 = VectorXd::Zero(C);
    ASSERT_EQ(ops.solve(X, v, u2, nullptr), Status::ok);
    EXPECT_TRUE(u2 == u);
  }
  EXPECT_GE(used, kSamples / 2);
}

void condition_threshold_is_honoured(const PinvOps& ops, Rng& rng) {
  // cond(X X^T) = (s_max/s_min)^2: 1e10 is accepted, 1e14 refused (kPinvMaxCondition = 1e12).
  const Eigen::Index R = ops.R, C = ops.C;
  for (int k = 0; k < 20; ++k) {
    VectorXd s = VectorXd::LinSpaced(R, 1.0, 0.5);
    s(R - 1) = 1e-5;
    const MatrixXd X_ok = with_singular_values(rng, C, s);
    s(R - 1) = 1e-7;
    const MatrixXd X_bad = with_singular_values(rng, C, s);
    const VectorXd v = rng.vec(R);
    VectorXd u = VectorXd::Zero(C);
    adcs::PinvInfo info;
    EXPECT_EQ(ops.solve(X_ok, v, u, &info), Status::ok);
    EXPECT_NEAR(info.condition, 1e10, 1e6);
    EXPECT_LE((X_ok * u - v).norm(), 1e-5 * v.norm());
    const VectorXd sentinel = VectorXd::Constant(C, 123.0);
    u = sentinel;
    EXPECT_EQ(ops.solve(X_bad, v, u, &info), Status::singular);
    EXPECT_TRUE(u == sentinel);
    EXPECT_GT(info.condition, adcs::kPinvMaxCondition);
  }
}

void exactly_singular_is_refused(const PinvOps& ops, Rng& rng) {
  const Eigen::Index R = ops.R, C = ops.C;
  const VectorXd sentinel = VectorXd::Constant(C, -7.0);
  const MatrixXd sentinel_m = MatrixXd::Constant(C, R, 5.0);
  for (int k = 0; k < kSamples; ++k) {
    const MatrixXd X = (k == 0) ? MatrixXd(MatrixXd::Zero(R, C)) : rank_deficient(rng, R, C);
    const VectorXd v = rng.vec(R);
    VectorXd u = sentinel;
    adcs::PinvInfo info;
    EXPECT_EQ(ops.solve(X, v, u, &info), Status::singular);
    EXPECT_TRUE(u == sentinel);
    EXPECT_LE(info.sigma_min, 1e-7 * std::max(info.sigma_max, 1.0));
    EXPECT_GT(info.condition, adcs::kPinvMaxCondition);  // inf for X = 0
    MatrixXd Xp = sentinel_m;
    EXPECT_EQ(ops.pinv(X, Xp), Status::singular);
    EXPECT_TRUE(Xp == sentinel_m);
  }
}

void damped_at_exact_singularity(const PinvOps& ops, Rng& rng) {
  const Eigen::Index R = ops.R, C = ops.C;
  for (const adcs::DampingParams params : {adcs::DampingParams{}, adcs::DampingParams{0.05, 0.1}}) {
    for (int k = 0; k < kSamples; ++k) {
      const MatrixXd X = rank_deficient(rng, R, C);
      const VectorXd v = rng.vec(R, -2, 2);
      VectorXd u = VectorXd::Constant(C, kNaN);
      adcs::PinvInfo info;
      ASSERT_EQ(ops.damped(X, v, u, params, &info), Status::ill_conditioned);
      ASSERT_TRUE(adcs::all_finite(u));
      EXPECT_TRUE(info.damped);
      const double r = info.sigma_min / params.sigma_threshold;
      EXPECT_NEAR(info.damping, params.lambda_max * params.lambda_max * (1.0 - r * r), 1e-15);
      EXPECT_GT(info.damping, 0.99 * params.lambda_max * params.lambda_max);
      const double lambda = std::sqrt(info.damping);

      // The gain along every singular direction is s/(s^2 + lambda^2) <= 1/(2 lambda).
      EXPECT_LE(u.norm(), v.norm() / (2.0 * lambda) * (1.0 + 1e-12));
      // Exactly the damped least-squares solution.
      const Svd d = svd_of(X);
      const VectorXd u_ref = damped_truth(d, v, info.damping);
      EXPECT_LE((u - u_ref).norm(), 1e-9 * u_ref.norm());
      // X u reproduces the part of v in range(X) up to the damping error lambda^2/(s^2+lambda^2).
      const MatrixXd Ur = d.U.leftCols(R - 1);
      const VectorXd v_range = Ur * (Ur.transpose() * v);
      const double s_r = d.s(R - 2);
      const double damping_error = info.damping / (s_r * s_r + info.damping);
      EXPECT_LE((X * u - v_range).norm(), damping_error * v_range.norm() + 1e-10 * v.norm());
    }
    // X = 0: damped to u = 0.
    VectorXd u = VectorXd::Constant(C, 1.0);
    EXPECT_EQ(ops.damped(MatrixXd::Zero(R, C), VectorXd::Ones(R), u, params, nullptr), Status::ill_conditioned);
    EXPECT_TRUE(u == VectorXd::Zero(C));
  }
  // Damping disabled: an exactly singular X cannot be inverted; u untouched.
  VectorXd u = VectorXd::Constant(C, 3.0);
  EXPECT_EQ(ops.damped(MatrixXd::Zero(R, C), VectorXd::Ones(R), u, adcs::DampingParams{1e-3, 0.0}, nullptr),
            Status::singular);
  EXPECT_TRUE(u == VectorXd::Constant(C, 3.0));
}

void damped_equals_exact_above_threshold(const PinvOps& ops, Rng& rng) {
  const Eigen::Index R = ops.R, C = ops.C;
  for (int k = 0; k < kSamples; ++k) {
    const MatrixXd X = rng.mat(R, C);
    const VectorXd v = rng.vec(R);
    adcs::PinvInfo info_exact, info_damped;
    VectorXd u_exact = VectorXd::Zero(C), u_damped = VectorXd::Zero(C);
    ASSERT_EQ(ops.solve(X, v, u_exact, &info_exact), Status::ok);
    adcs::DampingParams params;
    params.sigma_threshold = 0.999 * info_exact.sigma_min;  // just below sigma_min: never damped
    params.lambda_max = 0.5;
    ASSERT_EQ(ops.damped(X, v, u_damped, params, &info_damped), Status::ok);
    EXPECT_FALSE(info_damped.damped);
    EXPECT_EQ(info_damped.damping, 0.0);
    EXPECT_LE((u_damped - u_exact).norm(), 1e-14 * u_exact.norm());
    EXPECT_EQ(info_damped.sigma_min, info_exact.sigma_min);
    EXPECT_EQ(info_damped.sigma_max, info_exact.sigma_max);
    // ... and with the default (small) threshold.
    ASSERT_EQ(ops.damped(X, v, u_damped, adcs::DampingParams{}, nullptr), Status::ok);
    EXPECT_LE((u_damped - u_exact).norm(), 1e-14 * u_exact.norm());
  }
}

void damped_is_continuous_through_singularity(const PinvOps& ops, Rng& rng) {
  // X(eps) = U diag(1, ..., 0.6, eps) V^T is rank-deficient at eps = 0. Sweep eps -> 0 through the
  // damping threshold: u(eps) follows the damped-least-squares formula, stays bounded, and has no
  // jump at the threshold.
  const Eigen::Index R = ops.R, C = ops.C;
  const adcs::DampingParams params;  // sigma_threshold 1e-3, lambda_max 1e-2
  for (int trial = 0; trial < 10; ++trial) {
    Svd d;
    d.U = rng.orthogonal(R);
    d.V = rng.orthogonal(C);
    const VectorXd v = rng.vec(R);
    auto X_of = [&](double eps) {
      d.s = VectorXd::LinSpaced(R, 1.0, 0.6);
      d.s(R - 1) = eps;
      MatrixXd S = MatrixXd::Zero(R, C);
      S.diagonal() = d.s;
      return MatrixXd(d.U * S * d.V.transpose());
    };
    // sup over eps of the gain s/(s^2 + lambda(s)^2) is 1/sigma_threshold for these params (it
    // grows to 1/sigma_threshold as s rises to the threshold, then falls as 1/s).
    const double bound = v.norm() * std::max(1.0 / 0.6, 1.0 / params.sigma_threshold) * (1.0 + 1e-6);
    std::vector<double> sweep;
    for (double eps = 0.1; eps > 1e-12; eps *= 0.8) sweep.push_back(eps);
    sweep.push_back(0.0);
    for (double eps : sweep) {
      const MatrixXd X = X_of(eps);
      VectorXd u = VectorXd::Zero(C);
      adcs::PinvInfo info;
      const Status st = ops.damped(X, v, u, params, &info);
      ASSERT_TRUE(st == Status::ok || st == Status::ill_conditioned) << adcs::to_string(st);
      EXPECT_EQ(st == Status::ill_conditioned, info.damped);
      ASSERT_TRUE(adcs::all_finite(u));
      EXPECT_LE(u.norm(), bound) << "eps = " << eps;
      // lambda^2 = lambda_max^2 (1 - (eps/t)^2) below the threshold, 0 above.
      const double r = std::min(eps / params.sigma_threshold, 1.0);
      const double lambda2 = params.lambda_max * params.lambda_max * (1.0 - r * r);
      EXPECT_NEAR(info.damping, lambda2, 1e-6 * params.lambda_max * params.lambda_max) << "eps = " << eps;
      const VectorXd u_ref = damped_truth(d, v, info.damping);
      EXPECT_LE((u - u_ref).norm(), 1e-7 * u_ref.norm() + 1e-9) << "eps = " << eps;
    }
    // No jump at the threshold.
    const double t = params.sigma_threshold;
    VectorXd below = VectorXd::Zero(C), above = VectorXd::Zero(C);
    EXPECT_EQ(ops.damped(X_of(t * (1 - 1e-9)), v, below, params, nullptr), Status::ill_conditioned);
    EXPECT_EQ(ops.damped(X_of(t * (1 + 1e-9)), v, above, params, nullptr), Status::ok);
    EXPECT_LE((below - above).norm(), 1e-6 * above.norm());
  }
}

void non_finite_inputs_leave_outputs_untouched(const PinvOps& ops, Rng& rng) {
  const Eigen::Index R = ops.R, C = ops.C;
  const VectorXd sentinel = VectorXd::Constant(C, 9.0);
  const MatrixXd sentinel_m = MatrixXd::Constant(C, R, 9.0);
  for (double bad : {kNaN, kInf, -kInf}) {
    for (Eigen::Index pos = 0; pos < R * C; ++pos) {
      MatrixXd X = rng.mat(R, C);
      const VectorXd v = rng.vec(R);
      X(pos % R, pos / R) = bad;
      VectorXd u = sentinel;
      EXPECT_EQ(ops.solve(X, v, u, nullptr), Status::non_finite_input);
      EXPECT_TRUE(u == sentinel);
      EXPECT_EQ(ops.damped(X, v, u, adcs::DampingParams{}, nullptr), Status::non_finite_input);
      EXPECT_TRUE(u == sentinel);
      MatrixXd Xp = sentinel_m;
      EXPECT_EQ(ops.pinv(X, Xp), Status::non_finite_input);
      EXPECT_TRUE(Xp == sentinel_m);
    }
    for (Eigen::Index pos = 0; pos < R; ++pos) {
      const MatrixXd X = rng.mat(R, C);
      VectorXd v = rng.vec(R);
      v(pos) = bad;
      VectorXd u = sentinel;
      EXPECT_EQ(ops.solve(X, v, u, nullptr), Status::non_finite_input);
      EXPECT_TRUE(u == sentinel);
      EXPECT_EQ(ops.damped(X, v, u, adcs::DampingParams{}, nullptr), Status::non_finite_input);
      EXPECT_TRUE(u == sentinel);
    }
  }
}

// Found by tests/fuzz (fuzz_seed001, steering): finite X and v whose solution overflows used to
// come back as Inf/NaN with status ok / ill_conditioned. Now out_of_range, outputs untouched.
void overflowing_solution_is_refused(const PinvOps& ops, Rng& rng) {
  const Eigen::Index R = ops.R, C = ops.C;
  const VectorXd sentinel = VectorXd::Constant(C, 9.0);
  // Well conditioned (cond 1) but tiny: X X^T = 1e-6 I, so y = v / 1e-6 overflows for |v| ~ 1e307.
  const MatrixXd X = with_singular_values(rng, C, VectorXd::Constant(R, 1e-3));
  const VectorXd v = VectorXd::Constant(R, 1e307);
  VectorXd u = sentinel;
  EXPECT_EQ(ops.solve(X, v, u, nullptr), Status::out_of_range);
  EXPECT_TRUE(u == sentinel);
  EXPECT_EQ(ops.damped(X, v, u, adcs::DampingParams{}, nullptr), Status::out_of_range);
  EXPECT_TRUE(u == sentinel);
  // The damped branch too: X exactly singular, lambda^2 = 1e-4, |v| = 1e305.
  MatrixXd Xs = X;
  Xs.row(0).setZero();
  EXPECT_EQ(ops.damped(Xs, VectorXd::Constant(R, 1e305), u, adcs::DampingParams{}, nullptr), Status::out_of_range);
  EXPECT_TRUE(u == sentinel);
}

template <int R_, int C_>
struct Shape {
  static PinvOps ops() { return pinv_ops<R_, C_>(); }
  static constexpr std::uint64_t seed = 0xA000 + 16 * R_ + C_;
};

template <class S>
class Pinv : public ::testing::Test {};
using PinvShapes = ::testing::Types<Shape<3, 4>, Shape<3, 7>, Shape<2, 5>>;
TYPED_TEST_SUITE(Pinv, PinvShapes, );  // trailing empty argument: clang -Wpedantic needs one for "..."

TYPED_TEST(Pinv, ExactInverseIsTheMinimumNormSolution) {
  Rng rng(TypeParam::seed + 1);
  exact_inverse_is_minimum_norm(TypeParam::ops(), rng);
}
TYPED_TEST(Pinv, ConditionThresholdIsHonoured) {
  Rng rng(TypeParam::seed + 2);
  condition_threshold_is_honoured(TypeParam::ops(), rng);
}
TYPED_TEST(Pinv, ExactlySingularIsRefusedWithOutputsUntouched) {
  Rng rng(TypeParam::seed + 3);
  exactly_singular_is_refused(TypeParam::ops(), rng);
}
TYPED_TEST(Pinv, DampedInverseAtExactSingularityIsBoundedAndReproducesTheRange) {
  Rng rng(TypeParam::seed + 4);
  damped_at_exact_singularity(TypeParam::ops(), rng);
}
TYPED_TEST(Pinv, DampedEqualsExactAboveThreshold) {
  Rng rng(TypeParam::seed + 5);
  damped_equals_exact_above_threshold(TypeParam::ops(), rng);
}
TYPED_TEST(Pinv, DampedInverseIsContinuousThroughSingularity) {
  Rng rng(TypeParam::seed + 6);
  damped_is_continuous_through_singularity(TypeParam::ops(), rng);
}
TYPED_TEST(Pinv, NonFiniteInputsLeaveOutputsUntouched) {
  Rng rng(TypeParam::seed + 7);
  non_finite_inputs_leave_outputs_untouched(TypeParam::ops(), rng);
}
TYPED_TEST(Pinv, OverflowingSolutionIsRefusedWithOutputsUntouched) {
  Rng rng(TypeParam::seed + 8);
  overflowing_solution_is_refused(TypeParam::ops(), rng);
}

// =============================================================================================
// Continuous Lyapunov equation A^T P + P A = -Q

//! solve_continuous_lyapunov<N> behind a dynamic-size interface (P copied in and out).
using LyapFn = Status (*)(const MatrixXd& A, const MatrixXd& Q, MatrixXd& P);
template <int N>
LyapFn lyap_fn() {
  return [](const MatrixXd& A, const MatrixXd& Q, MatrixXd& P) {
    const Mat<N, N> Af = A, Qf = Q;
    Mat<N, N> Pf = P;
    const Status s = adcs::solve_continuous_lyapunov<N>(Af, Qf, Pf);
    P = Pf;
    return s;
  };
}

//! Kronecker-product truth: (I (x) A^T + A^T (x) I) vec(P) = -vec(Q).
MatrixXd lyapunov_kron(const MatrixXd& A, const MatrixXd& Q) {
  const Eigen::Index n = A.rows();
  MatrixXd L = MatrixXd::Zero(n * n, n * n);
  const MatrixXd I = MatrixXd::Identity(n, n);
  for (Eigen::Index i = 0; i < n; ++i)
    for (Eigen::Index j = 0; j < n; ++j) {
      L.block(i * n, j * n, n, n) += I(i, j) * A.transpose();
      L.block(i * n, j * n, n, n) += A(j, i) * I;
    }
  const VectorXd q = Eigen::Map<const VectorXd>(Q.data(), n * n);
  const VectorXd p = L.partialPivLu().solve(-q);
  return Eigen::Map<const MatrixXd>(p.data(), n, n);
}

double residual(const MatrixXd& A, const MatrixXd& P, const MatrixXd& Q) {
  return (A.transpose() * P + P * A + Q).norm() / Q.norm();
}

double spectral_abscissa(const MatrixXd& M) {
  return Eigen::EigenSolver<MatrixXd>(M, false).eigenvalues().real().maxCoeff();
}

TEST(Lyapunov, Seed001ClosedFormP) {
  // spec §A.3: A_1 = [[0, I3], [-Kp, -Kd]], Q = I6, P block-structured per axis.
  const VectorXd kp = Eigen::Vector3d(0.08, 0.18, 0.12), kd = Eigen::Vector3d(0.4, 0.6, 0.5 * std::sqrt(2.0));
  MatrixXd A1 = MatrixXd::Zero(6, 6);
  A1.topRightCorner(3, 3).setIdentity();
  A1.bottomLeftCorner(3, 3) = (-kp).asDiagonal();
  A1.bottomRightCorner(3, 3) = (-kd).asDiagonal();
  MatrixXd P = MatrixXd::Zero(6, 6);
  ASSERT_EQ(lyap_fn<6>()(A1, MatrixXd::Identity(6, 6), P), Status::ok);

  MatrixXd P_closed = MatrixXd::Zero(6, 6);
  for (int i = 0; i < 3; ++i) {
    P_closed(i, i) = (1 + kp(i)) / (2 * kd(i)) + kd(i) / (2 * kp(i));          // p11
    P_closed(i, i + 3) = P_closed(i + 3, i) = 1.0 / (2 * kp(i));               // p12
    P_closed(i + 3, i + 3) = (1 + kp(i)) / (2 * kp(i) * kd(i));                // p22
  }
  for (int i = 0; i < 6; ++i)
    for (int j = 0; j < 6; ++j) {
      // 1e-12 relative per nonzero entry; the structural zeros to 1e-12 of the largest entry.
      const double tol = 1e-12 * (P_closed(i, j) != 0.0 ? std::abs(P_closed(i, j)) : max_abs(P_closed));
      EXPECT_NEAR(P(i, j), P_closed(i, j), tol) << "(" << i << "," << j << ")";
    }
  // The numbers printed in the spec (8 decimals).
  const double p11_spec[3] = {3.85, 2.65, 3.73823785}, p12_spec[3] = {6.25, 2.77777778, 4.16666667},
               p22_spec[3] = {16.875, 5.46296296, 6.59966329};
  for (int i = 0; i < 3; ++i) {
    EXPECT_NEAR(P(i, i), p11_spec[i], 5e-9);
    EXPECT_NEAR(P(i, i + 3), p12_spec[i], 5e-9);
    EXPECT_NEAR(P(i + 3, i + 3), p22_spec[i], 5e-9);
  }
  EXPECT_LE(residual(A1, P, MatrixXd::Identity(6, 6)), 1e-14);
  EXPECT_TRUE(P == P.transpose());
}

void random_hurwitz_residual_spd(LyapFn solve, Eigen::Index n, Rng& rng) {
  for (int k = 0; k < kSamples; ++k) {
    MatrixXd A;
    if (k % 2 == 0) {
      // -(M M^T + I) plus a skew part: eigenvalue real parts <= -1.
      const MatrixXd M = rng.mat(n, n), S = rng.mat(n, n, -2, 2);
      A = -(M * M.transpose() + MatrixXd::Identity(n, n)) + (S - S.transpose());
    } else {
      // A random (non-normal) matrix shifted left of the imaginary axis by its spectral abscissa.
      const MatrixXd M = rng.mat(n, n);
      A = M - (spectral_abscissa(M) + rng.uniform(0.1, 1.0)) * MatrixXd::Identity(n, n);
    }
    MatrixXd Q = MatrixXd::Identity(n, n);
    if (k % 3 == 1) {
      const MatrixXd W = rng.mat(n, n);
      Q = W * W.transpose() + 0.1 * MatrixXd::Identity(n, n);
      Q = (0.5 * (Q + Q.transpose())).eval();  // exactly symmetric, so P is symmetrised
    }
    MatrixXd P = MatrixXd::Zero(n, n);
    ASSERT_EQ(solve(A, Q, P), Status::ok);
    EXPECT_LE(residual(A, P, Q), 1e-12) << "sample " << k;
    EXPECT_TRUE(P == P.transpose()) << "sample " << k;
    EXPECT_EQ(Eigen::LLT<MatrixXd>(P).info(), Eigen::Success) << "sample " << k;  // P > 0
  }
}

template <class S>
class LyapunovRandom : public ::testing::Test {};
using LyapunovSizes = ::testing::Types<Size<2>, Size<6>, Size<12>>;
TYPED_TEST_SUITE(LyapunovRandom, LyapunovSizes, );  // trailing empty argument: clang -Wpedantic needs one for "..."

TYPED_TEST(LyapunovRandom, ResidualSymmetryAndPositiveDefiniteness) {
  Rng rng(0xB100 + TypeParam::n);
  random_hurwitz_residual_spd(lyap_fn<TypeParam::n>(), TypeParam::n, rng);
}

void matches_kronecker_solve(LyapFn solve, Eigen::Index n, Rng& rng) {
  for (int k = 0; k < kSamples; ++k) {
    const MatrixXd M = rng.mat(n, n);
    const MatrixXd A = M - (spectral_abscissa(M) + 0.2) * MatrixXd::Identity(n, n);
    // Non-symmetric Q too: the solver must not assume a symmetry it was not given.
    const MatrixXd Q = (k % 2 == 0) ? rng.mat(n, n) : MatrixXd(MatrixXd::Identity(n, n));
    MatrixXd P = MatrixXd::Zero(n, n);
    ASSERT_EQ(solve(A, Q, P), Status::ok);
    const MatrixXd P_ref = lyapunov_kron(A, Q);
    EXPECT_LE(max_abs(P - P_ref), 1e-10 * max_abs(P_ref)) << "sample " << k;
    EXPECT_LE(residual(A, P, Q), 1e-12) << "sample " << k;
  }
}

// (The Kronecker check runs at the sizes already instantiated: each extra N of the fixed-size
// Schur solver costs ~12 s of compile time.)
TYPED_TEST(LyapunovRandom, MatchesKroneckerSolve) {
  Rng rng(0xB200 + TypeParam::n);
  matches_kronecker_solve(lyap_fn<TypeParam::n>(), TypeParam::n, rng);
}

TEST(Lyapunov, DiagonalAClosedFormIncludingUnstable) {
  // Diagonal A: P_ij = -Q_ij / (a_i + a_j); unique whenever no a_i + a_j = 0, stable or not.
  const LyapFn solve = lyap_fn<6>();
  Rng rng(0xB300);
  for (int k = 0; k < kSamples; ++k) {
    VectorXd a(6);
    for (int i = 0; i < 6; ++i) a(i) = (rng.coin() ? 1.0 : -1.0) * rng.uniform(0.5, 2.0);
    bool resonant = false;
    for (int i = 0; i < 6; ++i)
      for (int j = 0; j < 6; ++j) resonant = resonant || std::abs(a(i) + a(j)) < 0.05;
    if (resonant) continue;
    const MatrixXd W = rng.mat(6, 6);
    const MatrixXd Q = W + W.transpose();
    MatrixXd P = MatrixXd::Zero(6, 6);
    ASSERT_EQ(solve(a.asDiagonal(), Q, P), Status::ok);
    for (int i = 0; i < 6; ++i)
      for (int j = 0; j < 6; ++j) EXPECT_NEAR(P(i, j), -Q(i, j) / (a(i) + a(j)), 1e-13);
  }
}

TEST(Lyapunov, ResonantSpectrumIsSingularAndNonFiniteIsRejected) {
  const LyapFn solve2 = lyap_fn<2>();
  const MatrixXd I2 = MatrixXd::Identity(2, 2);
  const MatrixXd sentinel = MatrixXd::Constant(2, 2, -1.0);
  MatrixXd rot(2, 2), saddle(2, 2), jordan(2, 2), T(2, 2);
  rot << 0, 1, -1, 0;     // eigenvalues +-i: lambda + conj(lambda) = 0
  saddle << 1, 0, 0, -1;  // lambda_1 + lambda_2 = 0
  jordan << 0, 1, 0, 0;   // double eigenvalue 0
  T << 2, 1, 0.5, 3;
  const MatrixXd similar = T * saddle * T.inverse();  // a saddle in a skewed basis
  for (const MatrixXd& A : {rot, MatrixXd(3.7 * rot), saddle, jordan, MatrixXd(MatrixXd::Zero(2, 2)), similar}) {
    MatrixXd P = sentinel;
    EXPECT_EQ(solve2(A, I2, P), Status::singular) << A;
    EXPECT_TRUE(P == sentinel);
  }
  // The seed-001 structure with Kd = 0 (undamped oscillators) is resonant as well.
  MatrixXd A_undamped = MatrixXd::Zero(6, 6);
  A_undamped.topRightCorner(3, 3).setIdentity();
  A_undamped.bottomLeftCorner(3, 3) = Eigen::Vector3d(-0.08, -0.18, -0.12).asDiagonal();
  MatrixXd P6 = MatrixXd::Constant(6, 6, 2.0);
  EXPECT_EQ(lyap_fn<6>()(A_undamped, MatrixXd::Identity(6, 6), P6), Status::singular);
  EXPECT_TRUE(P6 == MatrixXd::Constant(6, 6, 2.0));

  for (double bad : {kNaN, kInf, -kInf}) {
    MatrixXd A = -I2;
    A(1, 0) = bad;
    MatrixXd P = sentinel;
    EXPECT_EQ(solve2(A, I2, P), Status::non_finite_input);
    EXPECT_TRUE(P == sentinel);
    MatrixXd Q = I2;
    Q(0, 1) = bad;
    EXPECT_EQ(solve2(-I2, Q, P), Status::non_finite_input);
    EXPECT_TRUE(P == sentinel);
  }
}

// =============================================================================================
// Pole placement for the block double integrator (seed 001 §A.3)

//! Matches two eigenvalue multisets greedily; returns the largest distance of a matched pair.
double multiset_distance(std::vector<cplx> expected, std::vector<cplx> actual) {
  if (expected.size() != actual.size()) return kInf;
  double worst = 0.0;
  for (const cplx& e : expected) {
    std::size_t best = 0;
    for (std::size_t i = 1; i < actual.size(); ++i)
      if (std::abs(actual[i] - e) < std::abs(actual[best] - e)) best = i;
    worst = std::max(worst, std::abs(actual[best] - e));
    actual.erase(actual.begin() + static_cast<std::ptrdiff_t>(best));
  }
  return worst;
}

template <int Axes>
std::vector<cplx> closed_loop_eigenvalues(const Mat<Axes, 2 * Axes>& K) {
  const Mat<2 * Axes, 2 * Axes> A1 = adcs::double_integrator_closed_loop<Axes>(K);
  const Eigen::EigenSolver<MatrixXd> es(MatrixXd(A1), false);
  std::vector<cplx> out;
  for (int i = 0; i < 2 * Axes; ++i) out.push_back(es.eigenvalues()(i));
  return out;
}

template <int Axes>
std::vector<cplx> flatten(const adcs::AxisPoles<Axes>& poles) {
  std::vector<cplx> out;
  for (const auto& pair : poles) out.insert(out.end(), pair.begin(), pair.end());
  return out;
}

TEST(Place, Seed001GainsEigenvaluesAndP) {
  const double r2 = std::sqrt(2.0);
  const adcs::AxisPoles<3> poles = {{{cplx(-0.2, 0.2), cplx(-0.2, -0.2)},
                                     {cplx(-0.3, 0.3), cplx(-0.3, -0.3)},
                                     {cplx(-0.2 * r2, 0.0), cplx(-0.3 * r2, 0.0)}}};
  Mat<3, 6> K = Mat<3, 6>::Constant(kNaN);
  ASSERT_EQ(adcs::place_double_integrator<3>(poles, K), Status::ok);
  Mat<3, 6> K_spec = Mat<3, 6>::Zero();
  K_spec.leftCols<3>().diagonal() = Vec<3>(0.08, 0.18, 0.12);
  K_spec.rightCols<3>().diagonal() = Vec<3>(0.4, 0.6, 0.70710678118654752);
  EXPECT_LE(max_abs(K - K_spec), 1e-15);
  EXPECT_LE(multiset_distance(flatten<3>(poles), closed_loop_eigenvalues<3>(K)), 1e-9);

  const Mat<6, 6> A1 = adcs::double_integrator_closed_loop<3>(K);
  Mat<6, 6> A1_spec = Mat<6, 6>::Zero();
  A1_spec.topRightCorner<3, 3>().setIdentity();
  A1_spec.bottomRows<3>() = -K;
  EXPECT_EQ(A1, A1_spec);

  // The full precompute chain of §A.3: poles -> K -> A_1 -> P.
  Mat<6, 6> P = Mat<6, 6>::Zero();
  ASSERT_EQ(adcs::solve_continuous_lyapunov<6>(A1, Mat<6, 6>::Identity(), P), Status::ok);
  EXPECT_NEAR(P(2, 2), 3.73823785, 5e-9);
  EXPECT_NEAR(P(1, 4), 2.77777778, 5e-9);
  EXPECT_NEAR(P(5, 5), 6.59966329, 5e-9);
}

template <class S>
class PlaceRandom : public ::testing::Test {};
using PlaceAxes = ::testing::Types<Size<1>, Size<2>, Size<3>>;
TYPED_TEST_SUITE(PlaceRandom, PlaceAxes, );  // trailing empty argument: clang -Wpedantic needs one for "..."

TYPED_TEST(PlaceRandom, ClosedLoopHasTheRequestedEigenvalues) {
  constexpr int Axes = TypeParam::n;
  Rng rng(0xC100 + Axes);
  for (int k = 0; k < kSamples; ++k) {
    adcs::AxisPoles<Axes> poles;
    for (int i = 0; i < Axes; ++i) {
      if (rng.coin()) {  // complex-conjugate pair, either order
        const cplx p(rng.uniform(-3.0, -0.05), rng.uniform(0.05, 3.0));
        poles[i] = rng.coin() ? std::array<cplx, 2>{p, std::conj(p)} : std::array<cplx, 2>{std::conj(p), p};
      } else {  // two distinct real poles (unstable ones are placeable too)
        const double a = rng.uniform(-3.0, 1.0);
        const double b = a - rng.uniform(0.05, 2.0);
        poles[i] = rng.coin() ? std::array<cplx, 2>{cplx(a, 0), cplx(b, 0)} : std::array<cplx, 2>{cplx(b, 0), cplx(a, 0)};
      }
    }
    Mat<Axes, 2 * Axes> K = Mat<Axes, 2 * Axes>::Constant(kNaN);
    ASSERT_EQ(adcs::place_double_integrator<Axes>(poles, K), Status::ok);
    const std::vector<cplx> expected = flatten<Axes>(poles);
    const double scale = 1.0 + std::abs(expected.front());
    EXPECT_LE(multiset_distance(expected, closed_loop_eigenvalues<Axes>(K)), 1e-9 * scale) << "sample " << k;
    // Per-axis diagonal structure: s^2 + kd s + kp with kp = a b, kd = -(a + b).
    for (int i = 0; i < Axes; ++i) {
      for (int j = 0; j < Axes; ++j) {
        const cplx a = poles[i][0], b = poles[i][1];
        EXPECT_NEAR(K(i, j), i == j ? (a * b).real() : 0.0, 1e-14 * (1 + std::abs(a * b)));
        EXPECT_NEAR(K(i, Axes + j), i == j ? -(a + b).real() : 0.0, 1e-14 * (1 + std::abs(a + b)));
      }
    }
  }
}

TYPED_TEST(PlaceRandom, NonConjugateOrNonFinitePolesLeaveKUntouched) {
  constexpr int Axes = TypeParam::n;
  const Mat<Axes, 2 * Axes> sentinel = Mat<Axes, 2 * Axes>::Constant(4.0);
  for (int bad_axis = 0; bad_axis < Axes; ++bad_axis) {
    adcs::AxisPoles<Axes> poles;
    for (int i = 0; i < Axes; ++i) poles[i] = {cplx(-1.0, 0.5), cplx(-1.0, -0.5)};
    poles[bad_axis] = {cplx(-1.0, 1.0), cplx(-2.0, 0.5)};
    Mat<Axes, 2 * Axes> K = sentinel;
    EXPECT_EQ(adcs::place_double_integrator<Axes>(poles, K), Status::out_of_range);
    EXPECT_EQ(K, sentinel);
    // Complex but not conjugate: same real part, unequal imaginary parts.
    poles[bad_axis] = {cplx(-1.0, 1.0), cplx(-1.0, -1.1)};
    EXPECT_EQ(adcs::place_double_integrator<Axes>(poles, K), Status::out_of_range);
    EXPECT_EQ(K, sentinel);
    // A lone complex pole with a real partner.
    poles[bad_axis] = {cplx(-1.0, 1.0), cplx(-1.0, 0.0)};
    EXPECT_EQ(adcs::place_double_integrator<Axes>(poles, K), Status::out_of_range);
    EXPECT_EQ(K, sentinel);
    // Real product, complex sum: (-1+i)(-2-2i) = 4 but the sum is -3 - i.
    poles[bad_axis] = {cplx(-1.0, 1.0), cplx(-2.0, -2.0)};
    EXPECT_EQ(adcs::place_double_integrator<Axes>(poles, K), Status::out_of_range);
    EXPECT_EQ(K, sentinel);
    // Real sum, complex product: (-1+i) + (-2-i) = -3 but the product is 3 - i.
    poles[bad_axis] = {cplx(-1.0, 1.0), cplx(-2.0, -1.0)};
    EXPECT_EQ(adcs::place_double_integrator<Axes>(poles, K), Status::out_of_range);
    EXPECT_EQ(K, sentinel);
    for (const cplx bad : {cplx(kNaN, 0.0), cplx(-1.0, kInf), cplx(-kInf, 0.0)}) {
      poles[bad_axis] = {cplx(-1.0, 0.0), bad};
      EXPECT_EQ(adcs::place_double_integrator<Axes>(poles, K), Status::non_finite_input);
      EXPECT_EQ(K, sentinel);
    }
  }
}

}  // namespace

using namespace ADCS_UNITY_ID;  // as an anonymous namespace would (CMakeLists.txt, adcs_unity)
