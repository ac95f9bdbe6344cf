// Property tests of the matrix exponential and the ZOH discretisation (adcs/math/expm.hpp).
// Truth values come from independent computations done here only: Eigen's unsupported
// MatrixFunctions exp() in double and in long double, std::exp/cos/sin closed forms, Rodrigues'
// formula, a fine RK4 integration and the double-integrator closed form.
//
// Heap freedom of expm<36> (every Padé degree) and zoh_discretize<27, 9> is proved in the
// nomalloc target, which forbids Eigen's heap and removes alloca like the Cortex-M7 build
// (one Eigen configuration for the whole binary; defining it here would differ between TUs).

#include <gtest/gtest.h>

#include <Eigen/Core>
#include <Eigen/LU>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <limits>
#include <random>
#include <unsupported/Eigen/MatrixFunctions>
#include <vector>

#include "adcs/math/expm.hpp"

#if defined(__unix__)

#include <cstdio>
#endif

namespace ADCS_UNITY_ID {

using adcs::Mat;
using adcs::Status;
using Eigen::MatrixXd;
using Eigen::VectorXd;
using MatrixXld = Eigen::Matrix<long double, Eigen::Dynamic, Eigen::Dynamic>;

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kEps = std::numeric_limits<double>::epsilon();
constexpr double kPi = 3.14159265358979323846;

class Rng {
 public:
  explicit Rng(std::uint64_t seed) : gen_(seed) {}
  double uniform(double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(gen_); }
  int index(int n) { return std::uniform_int_distribution<int>(0, n - 1)(gen_); }
  MatrixXd mat(Eigen::Index rows, Eigen::Index cols, double lo = -1.0, double hi = 1.0) {
    MatrixXd m(rows, cols);
    for (Eigen::Index j = 0; j < cols; ++j)
      for (Eigen::Index i = 0; i < rows; ++i) m(i, j) = uniform(lo, hi);
    return m;
  }

 private:
  std::mt19937_64 gen_;
};

double norm1(const MatrixXd& m) { return m.cwiseAbs().colwise().sum().maxCoeff(); }
double max_abs(const MatrixXd& m) { return m.cwiseAbs().maxCoeff(); }
double rel_err(const MatrixXd& x, const MatrixXd& ref) { return norm1(x - ref) / norm1(ref); }

//! Independent references: Eigen's MatrixFunctions exp() in double and in long double.
MatrixXd eigen_exp(const MatrixXd& A) { return A.exp(); }
MatrixXd eigen_exp_ld(const MatrixXd& A) {
  const MatrixXld E = MatrixXld(A.cast<long double>()).exp();
  return E.cast<double>();
}

// =============================================================================================
// Adapters: each fixed size instantiated once, the checks run on dynamic matrices. Outputs are
// copied in before and out after the call, so "output left untouched" stays observable.

//! dst = src by coefficients: GCC 12 -O2 -DNDEBUG reports a false -Warray-bounds on Eigen's
//! vectorised copy of a 1 x 1 fixed matrix into a dynamic one.
template <int R, int C>
void copy_out(const Mat<R, C>& src, MatrixXd& dst) {
  dst.resize(R, C);
  for (int j = 0; j < C; ++j)
    for (int i = 0; i < R; ++i) dst(i, j) = src(i, j);
}

struct ExpmOps {
  Eigen::Index n;
  Status (*expm)(const MatrixXd& A, MatrixXd& out);
  Status (*expm_aliased)(MatrixXd& A);  //!< expm(A, A)
};

template <int N>
ExpmOps expm_ops() {
  ExpmOps ops{};
  ops.n = N;
  ops.expm = [](const MatrixXd& A, MatrixXd& out) {
    const Mat<N, N> Af = A;
    Mat<N, N> Of = out;
    const Status s = adcs::expm<N>(Af, Of);
    copy_out(Of, out);
    return s;
  };
  ops.expm_aliased = [](MatrixXd& A) {
    Mat<N, N> Af = A;
    const Status s = adcs::expm<N>(Af, Af);
    copy_out(Af, A);
    return s;
  };
  return ops;
}

struct ZohOps {
  Eigen::Index n, m;
  Status (*zoh)(const MatrixXd& A, const MatrixXd& B, double h, MatrixXd& A_d, MatrixXd& B_d);
  Status (*zoh_aliased)(MatrixXd& A, MatrixXd& B, double h);  //!< zoh(A, B, h, A, B)
};

template <int N, int M>
ZohOps zoh_ops() {
  ZohOps ops{};
  ops.n = N;
  ops.m = M;
  ops.zoh = [](const MatrixXd& A, const MatrixXd& B, double h, MatrixXd& A_d, MatrixXd& B_d) {
    const Mat<N, N> Af = A;
    const Mat<N, M> Bf = B;
    Mat<N, N> Adf = A_d;
    Mat<N, M> Bdf = B_d;
    const Status s = adcs::zoh_discretize<N, M>(Af, Bf, h, Adf, Bdf);
    copy_out(Adf, A_d);
    copy_out(Bdf, B_d);
    return s;
  };
  ops.zoh_aliased = [](MatrixXd& A, MatrixXd& B, double h) {
    Mat<N, N> Af = A;
    Mat<N, M> Bf = B;
    const Status s = adcs::zoh_discretize<N, M>(Af, Bf, h, Af, Bf);
    copy_out(Af, A);
    copy_out(Bf, B);
    return s;
  };
  return ops;
}

// =============================================================================================
// expm

//! Test matrices of 1-norm nu: general dense, skew-symmetric (rotation generators), strictly
//! upper triangular (nilpotent).
enum class Family { general, skew, nilpotent };
const char* name(Family f) {
  return f == Family::general ? "general" : f == Family::skew ? "skew" : "nilpotent";
}
MatrixXd sample(Rng& rng, Eigen::Index n, Family f, double nu) {
  MatrixXd A = rng.mat(n, n);
  if (f == Family::skew) A = (A - A.transpose()).eval();
  if (f == Family::nilpotent) A = A.triangularView<Eigen::StrictlyUpper>().toDenseMatrix();
  const double a = norm1(A);
  return a > 0.0 ? MatrixXd(A * (nu / a)) : A;
}

//! 1-norms covering every branch of Algorithm 2.3: m = 3 (<= theta_3 = 0.015), 5 (<= 0.254),
//! 7 (<= 0.950), 9 (<= 2.098), 13 unscaled (<= 5.372) and 13 with 2..8 squarings, plus the
//! thresholds themselves (the lower degree is used on the threshold) and just above them.
std::vector<double> test_norms() {
  std::vector<double> nus = {1e-6, 1e-3, 1e-2, 0.2, 0.9, 2.0, 5.0, 20.0, 100.0, 1e3};
  for (double th : {adcs::detail::kTheta3, adcs::detail::kTheta5, adcs::detail::kTheta7, adcs::detail::kTheta9,
                    adcs::detail::kTheta13}) {
    nus.push_back(th);
    nus.push_back(th * (1.0 + 1e-12));
  }
  return nus;
}

//! Relative 1-norm error allowed against a reference: 1e-13 up to ||A||_1 = 100, then growing
//! with ||A|| (the relative condition number of exp is >= ||A||). Measured: <= 2e-14 up to
//! ||A|| = 20, ~1.6e-13 at 1e3, for this code and for Eigen's alike.
double tol_for_norm(double nu) { return 1e-13 * std::max(1.0, nu / 100.0); }

//! Relative error allowed for a scalar (or diagonal) exponential e^a, with |a| <= a_max:
//! 64 eps max(1, a_max). Higham 2005 in double reaches ~37 |a| eps near |a| = 42 (the
//! cancellation in q_13 at ||2^-s A|| ~ theta_13); Eigen's exp() measures the same.
double scalar_tol(double a_max) { return 64 * kEps * std::max(1.0, std::abs(a_max)); }

void zero_gives_identity_exactly(const ExpmOps& ops) {
  MatrixXd X = MatrixXd::Constant(ops.n, ops.n, 7.0);
  ASSERT_EQ(ops.expm(MatrixXd::Zero(ops.n, ops.n), X), Status::ok);
  EXPECT_TRUE(X == MatrixXd::Identity(ops.n, ops.n)) << X;
}

void matches_eigen_matrix_functions(const ExpmOps& ops, Rng& rng) {
  const Eigen::Index n = ops.n;
  for (Family f : {Family::general, Family::skew, Family::nilpotent}) {
    for (double nu : test_norms()) {
      for (int k = 0; k < 6; ++k) {
        const MatrixXd A = sample(rng, n, f, nu);
        MatrixXd X = MatrixXd::Zero(n, n);
        const MatrixXd R = eigen_exp(A), T = eigen_exp_ld(A);
        const Status s = ops.expm(A, X);
        if (!adcs::all_finite(T)) {  // e^A beyond DBL_MAX (general family, small n, nu = 1e3)
          EXPECT_EQ(s, Status::out_of_range) << name(f) << " nu=" << nu;
          EXPECT_TRUE(X == MatrixXd::Zero(n, n));
          continue;
        }
        ASSERT_EQ(s, Status::ok) << name(f) << " nu=" << nu;
        if (norm1(T) == 0.0) {  // e^A underflows to 0 (n = 1, a = -1000)
          EXPECT_LE(max_abs(X), 1e-300);
          continue;
        }
        const double tol = tol_for_norm(nu);
        EXPECT_LE(rel_err(X, R), tol) << name(f) << " n=" << n << " nu=" << nu << " k=" << k;
        EXPECT_LE(rel_err(X, T), tol) << name(f) << " n=" << n << " nu=" << nu << " k=" << k;
        if (f == Family::skew) {  // exp of a skew matrix is orthogonal
          EXPECT_LE(max_abs(X.transpose() * X - MatrixXd::Identity(n, n)), 4 * tol);
        }
        if (f == Family::nilpotent) {  // unit upper triangular, exactly
          EXPECT_TRUE(X.diagonal() == VectorXd::Ones(n));
          EXPECT_TRUE(MatrixXd(X.triangularView<Eigen::StrictlyLower>()) == MatrixXd::Zero(n, n));
        }
      }
    }
  }
}

void inverse_property(const ExpmOps& ops, Rng& rng) {
  // exp(A) exp(-A) = I. Rounding in X Y is ~eps ||X|| ||Y||, each factor carries ~||A|| eps.
  const Eigen::Index n = ops.n;
  for (double nu : {1e-6, 0.1, 1.0, 3.0, 10.0, 30.0}) {
    for (int k = 0; k < 10; ++k) {
      const MatrixXd A = sample(rng, n, Family::general, nu);
      MatrixXd X = MatrixXd::Zero(n, n), Y = MatrixXd::Zero(n, n);
      ASSERT_EQ(ops.expm(A, X), Status::ok);
      ASSERT_EQ(ops.expm(-A, Y), Status::ok);
      const double scale = norm1(X) * norm1(Y);
      const MatrixXd I = MatrixXd::Identity(n, n);
      EXPECT_LE(norm1(X * Y - I), 8 * (1.0 + nu) * n * kEps * scale) << "nu=" << nu << " k=" << k;
      EXPECT_LE(norm1(Y * X - I), 8 * (1.0 + nu) * n * kEps * scale) << "nu=" << nu << " k=" << k;
    }
  }
}

void zero_rows_give_unit_rows_exactly(const ExpmOps& ops, Rng& rng) {
  // A zero row i of A gives row i of exp(A) = e_i^T bit for bit (what keeps ZOH disturbance
  // states constant). Each zero-row state drives one other state through a dominant entry
  // (like a disturbance gain), so with scaling some pivot candidates of the Padé denominator
  // exceed b_0: plain partial pivoting would then pick them and lose the exactness.
  const Eigen::Index n = ops.n;
  if (n < 2) return;
  for (double nu : {1e-3, 0.5, 1.5, 4.0, 50.0, 500.0}) {
    for (int k = 0; k < 10; ++k) {
      MatrixXd A = sample(rng, n, Family::general, 1.0);
      std::vector<int> zero_rows, active_rows;  // at least one of each
      const int keep = rng.index(static_cast<int>(n));
      for (int i = 0; i < n; ++i) (i != keep && rng.uniform(0, 1) < 0.3 ? zero_rows : active_rows).push_back(i);
      if (zero_rows.empty()) {
        zero_rows.push_back(active_rows.back() == keep ? active_rows.front() : active_rows.back());
        active_rows.erase(std::find(active_rows.begin(), active_rows.end(), zero_rows.back()));
      }
      for (int i : zero_rows) {
        A.row(i).setZero();
        A(active_rows[static_cast<std::size_t>(rng.index(static_cast<int>(active_rows.size())))], i) =
            (rng.uniform(0, 1) < 0.5 ? -3.0 : 3.0) * static_cast<double>(n);
      }
      A *= nu / norm1(A);
      MatrixXd X = MatrixXd::Zero(n, n);
      const Status s = ops.expm(A, X);
      if (s == Status::out_of_range) continue;  // exp overflowed (large real eigenvalue)
      ASSERT_EQ(s, Status::ok);
      for (int i : zero_rows) {
        EXPECT_TRUE(X.row(i) == MatrixXd::Identity(n, n).row(i)) << "nu=" << nu << " row " << i << ": "
                                                                 << X.row(i);
      }
      EXPECT_LE(rel_err(X, eigen_exp_ld(A)), tol_for_norm(nu)) << "nu=" << nu;
    }
  }
}

void non_finite_and_overflow_leave_out_untouched(const ExpmOps& ops, Rng& rng) {
  const Eigen::Index n = ops.n;
  const MatrixXd sentinel = MatrixXd::Constant(n, n, 3.5);
  for (double bad : {kNaN, kInf, -kInf}) {
    for (Eigen::Index pos = 0; pos < n * n; ++pos) {
      MatrixXd A = rng.mat(n, n);
      A(pos % n, pos / n) = bad;
      MatrixXd X = sentinel;
      EXPECT_EQ(ops.expm(A, X), Status::non_finite_input);
      EXPECT_TRUE(X == sentinel);
    }
  }
  // exp(A) not representable: e^800 overflows; so does a 1-norm beyond DBL_MAX.
  MatrixXd X = sentinel;
  EXPECT_EQ(ops.expm(800.0 * MatrixXd::Identity(n, n), X), Status::out_of_range);
  EXPECT_TRUE(X == sentinel);
  MatrixXd huge = MatrixXd::Zero(n, n);
  huge(0, 0) = 1e308;
  EXPECT_EQ(ops.expm(huge, X), Status::out_of_range);
  EXPECT_TRUE(X == sentinel);
  if (n >= 2) {
    huge(1, 0) = -1e308;  // column sum overflows
    EXPECT_EQ(ops.expm(huge, X), Status::out_of_range);
    EXPECT_TRUE(X == sentinel);
  }
  // Strongly decaying is fine: e^-800 underflows to 0 (1019 squarings, no overflow).
  ASSERT_EQ(ops.expm(-1e308 * MatrixXd::Identity(n, n), X), Status::ok);
  EXPECT_TRUE(X == MatrixXd::Zero(n, n));
  ASSERT_EQ(ops.expm(-700.0 * MatrixXd::Identity(n, n), X), Status::ok);
  EXPECT_LE(max_abs(X - std::exp(-700.0) * MatrixXd::Identity(n, n)), scalar_tol(700.0) * std::exp(-700.0));
}

void aliasing_is_allowed(const ExpmOps& ops, Rng& rng) {
  for (double nu : {0.1, 3.0, 30.0}) {
    const MatrixXd A = sample(rng, ops.n, Family::general, nu);
    MatrixXd X = MatrixXd::Zero(ops.n, ops.n);
    ASSERT_EQ(ops.expm(A, X), Status::ok);
    MatrixXd B = A;
    ASSERT_EQ(ops.expm_aliased(B), Status::ok);
    EXPECT_TRUE(B == X);
  }
}

template <int N_>
struct ExpmSize {
  static constexpr int n = N_;
  static ExpmOps ops() { return expm_ops<N_>(); }
  static constexpr std::uint64_t seed = 0xE000 + N_;
};

template <class S>
class Expm : public ::testing::Test {};
using ExpmSizes = ::testing::Types<ExpmSize<1>, ExpmSize<2>, ExpmSize<3>, ExpmSize<6>, ExpmSize<36>>;
TYPED_TEST_SUITE(Expm, ExpmSizes, );  // trailing empty argument: clang -Wpedantic needs one for "..."

TYPED_TEST(Expm, ZeroGivesIdentityExactly) { zero_gives_identity_exactly(TypeParam::ops()); }
TYPED_TEST(Expm, MatchesEigenMatrixFunctionsOnEveryBranch) {
  Rng rng(TypeParam::seed + 1);
  matches_eigen_matrix_functions(TypeParam::ops(), rng);
}
TYPED_TEST(Expm, TimesExpOfMinusAIsIdentity) {
  Rng rng(TypeParam::seed + 2);
  inverse_property(TypeParam::ops(), rng);
}
TYPED_TEST(Expm, ZeroRowsGiveUnitRowsExactly) {
  Rng rng(TypeParam::seed + 3);
  zero_rows_give_unit_rows_exactly(TypeParam::ops(), rng);
}
TYPED_TEST(Expm, NonFiniteInputAndOverflowLeaveOutputUntouched) {
  Rng rng(TypeParam::seed + 4);
  non_finite_and_overflow_leave_out_untouched(TypeParam::ops(), rng);
}
TYPED_TEST(Expm, OutputMayAliasInput) {
  Rng rng(TypeParam::seed + 5);
  aliasing_is_allowed(TypeParam::ops(), rng);
}

TEST(ExpmClosedForm, ScalarIsStdExp) {
  // n = 1: r_m(a)^(2^s) against std::exp. Relative condition number of e^a is |a|.
  const ExpmOps ops = expm_ops<1>();
  Rng rng(0xE101);
  std::vector<double> as = {0.0, 1e-300, -1e-300, 1e-8, -1e-8, 0.01, 0.5, -0.5, 1.0, -1.0, 2.1, 5.0, -5.0,
                            10.0, -10.0, 100.0, -100.0, 700.0, -700.0, 709.0};
  for (int k = 0; k < 200; ++k) as.push_back(rng.uniform(-700, 700) * std::pow(10.0, -rng.uniform(0, 6)));
  for (double a : as) {
    MatrixXd X(1, 1);
    ASSERT_EQ(ops.expm(MatrixXd::Constant(1, 1, a), X), Status::ok) << a;
    const double e = std::exp(a);
    EXPECT_LE(std::abs(X(0, 0) - e), scalar_tol(a) * e) << "a=" << a;
  }
}

TEST(ExpmClosedForm, RotationGenerator2x2IsTheRotation) {
  const ExpmOps ops = expm_ops<2>();
  for (double th : {0.0, 1e-12, 1e-6, 0.01, 0.3, 1.0, kPi / 2, 2.0, kPi, 4.0, -3.0, 10.0, 100.0, 1e3}) {
    MatrixXd A(2, 2), R(2, 2), X(2, 2);
    A << 0.0, -th, th, 0.0;
    R << std::cos(th), -std::sin(th), std::sin(th), std::cos(th);
    ASSERT_EQ(ops.expm(A, X), Status::ok);
    EXPECT_LE(max_abs(X - R), 4 * kEps * (1.0 + std::abs(th))) << "theta=" << th << "\n" << X;
  }
}

TEST(ExpmClosedForm, So3GeneratorIsRodrigues) {
  const ExpmOps ops = expm_ops<3>();
  Rng rng(0xE103);
  for (int k = 0; k < 200; ++k) {
    Eigen::Vector3d w(rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1));
    w *= std::pow(10.0, rng.uniform(-8, 1.5)) / w.norm();
    const double th = w.norm();
    const Eigen::Vector3d u = w / th;
    MatrixXd K(3, 3);
    K << 0, -u.z(), u.y(), u.z(), 0, -u.x(), -u.y(), u.x(), 0;
    const MatrixXd R = MatrixXd::Identity(3, 3) + std::sin(th) * K + (1 - std::cos(th)) * K * K;
    MatrixXd X(3, 3);
    ASSERT_EQ(ops.expm(th * K, X), Status::ok);
    EXPECT_LE(max_abs(X - R), 8 * kEps * (1.0 + th)) << "theta=" << th;
  }
}

TEST(ExpmClosedForm, DiagonalIsElementwiseExp) {
  const ExpmOps ops = expm_ops<6>();
  Rng rng(0xE104);
  for (int k = 0; k < 100; ++k) {
    VectorXd d(6);
    for (int i = 0; i < 6; ++i) d(i) = rng.uniform(-50, 50) * std::pow(10.0, -rng.uniform(0, 8));
    MatrixXd X(6, 6);
    ASSERT_EQ(ops.expm(MatrixXd(d.asDiagonal()), X), Status::ok);
    for (int i = 0; i < 6; ++i) {
      const double e = std::exp(d(i));
      EXPECT_LE(std::abs(X(i, i) - e), scalar_tol(d.cwiseAbs().maxCoeff()) * e) << d.transpose();
    }
    EXPECT_TRUE(MatrixXd(X.triangularView<Eigen::StrictlyLower>()) == MatrixXd::Zero(6, 6));
    EXPECT_TRUE(MatrixXd(X.triangularView<Eigen::StrictlyUpper>()) == MatrixXd::Zero(6, 6));
  }
}

// The denominator solve on its own (internal, but it carries the no-heap and zero-row claims).
TEST(ExpmPadeSolve, MatchesEigenLuAndRefusesSingular) {
  Rng rng(0xE105);
  for (int k = 0; k < 200; ++k) {
    Mat<6, 6> Q = rng.mat(6, 6);
    if (k % 2 == 0) {  // singleton rows with a tiny diagonal: taken as pivots, still accurate
      const int i = rng.index(6);
      Q.row(i).setZero();
      Q(i, i) = 1e-6;
    }
    Mat<6, 6> P = rng.mat(6, 6);
    const Eigen::FullPivLU<MatrixXd> full(Q);
    const MatrixXd ref = full.solve(MatrixXd(P));
    Mat<6, 6> LU = Q, X = P;
    ASSERT_EQ(adcs::detail::lu_solve_in_place<6>(LU, X), Status::ok);
    // Backward stable (small residual) and forward error within eps * condition number.
    EXPECT_LE(norm1(MatrixXd(Q * X - P)), 1e-14 * norm1(MatrixXd(Q)) * norm1(MatrixXd(X))) << k;
    EXPECT_LE(rel_err(X, ref), 1e-14 / full.rcond()) << k;
  }
  Mat<6, 6> Q = rng.mat(6, 6);
  Q.row(4) = 2.0 * Q.row(1);  // exactly singular after one elimination step
  Q.col(2).setZero();
  Mat<6, 6> P = rng.mat(6, 6);
  EXPECT_EQ(adcs::detail::lu_solve_in_place<6>(Q, P), Status::singular);
}

// =============================================================================================
// zoh_discretize

TEST(Zoh, DoubleIntegratorClosedForm) {
  const ZohOps ops = zoh_ops<2, 1>();
  MatrixXd A(2, 2), B(2, 1);
  A << 0, 1, 0, 0;
  B << 0, 1;
  for (double h : {1e-6, 1e-3, 0.01, 0.1, 0.5, 1.0, 2.0, 5.0, 10.0, 100.0}) {
    MatrixXd A_d = MatrixXd::Zero(2, 2), B_d = MatrixXd::Zero(2, 1);
    ASSERT_EQ(ops.zoh(A, B, h, A_d, B_d), Status::ok) << h;
    MatrixXd A_ref(2, 2), B_ref(2, 1);
    A_ref << 1, h, 0, 1;
    B_ref << h * h / 2, h;
    for (int i = 0; i < 2; ++i) {  // 1e-15 relative to max(1, |entry|)
      for (int j = 0; j < 2; ++j)
        EXPECT_NEAR(A_d(i, j), A_ref(i, j), 1e-15 * std::max(1.0, std::abs(A_ref(i, j)))) << h;
      EXPECT_NEAR(B_d(i), B_ref(i), 1e-15 * std::max(1.0, std::abs(B_ref(i)))) << h;
    }
    EXPECT_TRUE(A_d.row(1) == A_ref.row(1)) << h;  // the zero row of A: exact
  }
}

//! [A_d, B_d] by RK4 on x_dot = A x + B u with u held, `steps` substeps over h.
MatrixXd rk4_zoh(const MatrixXd& A, const MatrixXd& B, double h, int steps) {
  const Eigen::Index n = A.rows(), m = B.cols();
  MatrixXd S = MatrixXd::Zero(n, n + m);  // columns: x0 = e_i, u = 0 | x0 = 0, u = e_j
  S.leftCols(n).setIdentity();
  MatrixXd Bu = MatrixXd::Zero(n, n + m);
  Bu.rightCols(m) = B;
  auto f = [&](const MatrixXd& s) { return MatrixXd(A * s + Bu); };
  const double dt = h / steps;
  for (int k = 0; k < steps; ++k) {
    const MatrixXd k1 = f(S), k2 = f(S + 0.5 * dt * k1), k3 = f(S + 0.5 * dt * k2), k4 = f(S + dt * k3);
    S += dt / 6.0 * (k1 + 2 * k2 + 2 * k3 + k4);
  }
  return S;
}

TEST(Zoh, StiffDampedOscillatorMatchesFineRk4) {
  // Lightly damped 20 rad/s oscillator driven through a 100 rad/s actuator lag (stiffness ratio
  // 5 with eigenvalues -2 +- 19.9i and -100): x_dot = v, v_dot = -w0^2 x - 2 z w0 v + a,
  // a_dot = -100 a + 100 u; a second input enters the velocity directly.
  const ZohOps ops = zoh_ops<3, 2>();
  const double w0 = 20.0, z = 0.1;
  MatrixXd A(3, 3), B(3, 2);
  A << 0, 1, 0, -w0 * w0, -2 * z * w0, 1, 0, 0, -100;
  B << 0, 0, 0, 0.5, 100, 0;
  for (double h : {0.002, 0.01, 0.05}) {
    MatrixXd A_d = MatrixXd::Zero(3, 3), B_d = MatrixXd::Zero(3, 2);
    ASSERT_EQ(ops.zoh(A, B, h, A_d, B_d), Status::ok);
    const MatrixXd S = rk4_zoh(A, B, h, 1000);
    EXPECT_LE(max_abs(A_d - S.leftCols(3)), 1e-10 * max_abs(S.leftCols(3))) << "h=" << h << "\n" << A_d;
    EXPECT_LE(max_abs(B_d - S.rightCols(2)), 1e-10 * max_abs(S.rightCols(2))) << "h=" << h << "\n" << B_d;
    // Each column of B_d on its own (the small-input column must not hide in the large one).
    for (int j = 0; j < 2; ++j)
      EXPECT_LE(max_abs(B_d.col(j) - S.col(3 + j)), 1e-10 * max_abs(S.col(3 + j))) << "h=" << h << " col " << j;
  }
}

//! 27 states in nine 3-blocks [x1 v1 f1 | x2 v2 f2 | x3 v3 f3] (three loops, per loop a 3-axis
//! double integrator plus a constant disturbance), inputs 9 = three per loop:
//!   x_i_dot = v_i,  v_i_dot = K_i x_i + D_i v_i + G_i f_i + C_i f_(i-1) + B_i u,  f_i_dot = 0.
//! Gains span the drag-free magnitudes (1e-9 .. 4e3) so that A h has a large 1-norm.
//! (adcs/plant/drag_free.hpp has this layout; it is not used here so the test stays independent.)
//! With disturbances_first the states are reordered [f1 f2 f3 | x1 v1 | x2 v2 | x3 v3]: then
//! the v rows holding the large f gains come after the f columns in the elimination order.
struct Chained27 {
  MatrixXd A = MatrixXd::Zero(27, 27), B = MatrixXd::Zero(27, 9);
  std::vector<int> f_rows;
};
Chained27 chained27(Rng& rng, double gain, bool disturbances_first = false) {
  Chained27 s;
  for (int loop = 0; loop < 3; ++loop) {
    const int x = 9 * loop, v = x + 3, f = x + 6;
    s.A.block(x, v, 3, 3).setIdentity();
    s.A.block(v, x, 3, 3) = 1e-6 * rng.mat(3, 3);
    s.A.block(v, v, 3, 3) = -1e-3 * MatrixXd::Identity(3, 3) + 1e-9 * rng.mat(3, 3);
    // Per-axis disturbance gain (diagonal, as an inverse inertia) with weak cross terms: each
    // f column has one dominant entry, which is what defeats plain partial pivoting.
    s.A.block(v, f, 3, 3) = gain * (MatrixXd(rng.mat(3, 1, 0.5, 1.0).asDiagonal()) + 1e-3 * rng.mat(3, 3));
    if (loop > 0) s.A.block(v, f - 9, 3, 3) = -gain * 1e-3 * rng.mat(3, 3, 0.5, 1.0);
    s.B.block(v, 3 * loop, 3, 3) = rng.mat(3, 3, -1e-2, 1e-2);
    if (loop == 2) s.B.block(v, 0, 3, 3) = rng.mat(3, 3, -1e-2, 1e-2);
    for (int i = 0; i < 3; ++i) s.f_rows.push_back(f + i);
  }
  if (!disturbances_first) return s;
  std::vector<int> order = s.f_rows;  // new index -> old index
  for (int i = 0; i < 27; ++i)
    if (std::find(s.f_rows.begin(), s.f_rows.end(), i) == s.f_rows.end()) order.push_back(i);
  Chained27 p;
  for (int i = 0; i < 27; ++i) {
    for (int j = 0; j < 27; ++j) p.A(i, j) = s.A(order[i], order[j]);
    p.B.row(i) = s.B.row(order[i]);
  }
  for (int i = 0; i < 9; ++i) p.f_rows.push_back(i);
  return p;
}

TEST(Zoh, Chained27DisturbanceRowsAreExactlyConstant) {
  const ZohOps ops = zoh_ops<27, 9>();
  Rng rng(0xE201);
  for (bool disturbances_first : {false, true}) {
    for (double gain : {1.0, 1e2, 3750.0}) {
      for (double h : {0.001, 0.1, 1.0, 10.0}) {
        const Chained27 s = chained27(rng, gain, disturbances_first);
        MatrixXd A_d = MatrixXd::Zero(27, 27), B_d = MatrixXd::Zero(27, 9);
        ASSERT_EQ(ops.zoh(s.A, s.B, h, A_d, B_d), Status::ok) << gain << " " << h;
        for (int r : s.f_rows) {
          EXPECT_TRUE(A_d.row(r) == MatrixXd::Identity(27, 27).row(r))
              << "f first=" << disturbances_first << " gain=" << gain << " h=" << h << " row " << r;
          EXPECT_TRUE(B_d.row(r) == MatrixXd::Zero(1, 9))
              << "f first=" << disturbances_first << " gain=" << gain << " h=" << h << " row " << r;
        }
        // And the rest is the exponential of the augmented matrix (long-double truth).
        MatrixXd aug = MatrixXd::Zero(36, 36);
        aug.topLeftCorner(27, 27) = s.A * h;
        aug.topRightCorner(27, 9) = s.B * h;
        const MatrixXd T = eigen_exp_ld(aug);
        const double tol = tol_for_norm(norm1(aug));
        EXPECT_LE(norm1(A_d - T.topLeftCorner(27, 27)), tol * norm1(T)) << "gain=" << gain << " h=" << h;
        EXPECT_LE(norm1(B_d - T.topRightCorner(27, 9)), tol * norm1(T)) << "gain=" << gain << " h=" << h;
      }
    }
  }
}

TEST(Zoh, InvalidInputsLeaveOutputsUntouched) {
  const ZohOps ops = zoh_ops<3, 2>();
  Rng rng(0xE202);
  const MatrixXd A = rng.mat(3, 3), B = rng.mat(3, 2);
  const MatrixXd Ad0 = MatrixXd::Constant(3, 3, 4.25), Bd0 = MatrixXd::Constant(3, 2, -1.5);
  auto check = [&](const MatrixXd& a, const MatrixXd& b, double h, Status expected) {
    MatrixXd A_d = Ad0, B_d = Bd0;
    EXPECT_EQ(ops.zoh(a, b, h, A_d, B_d), expected) << "h=" << h;
    EXPECT_TRUE(A_d == Ad0) << "h=" << h;
    EXPECT_TRUE(B_d == Bd0) << "h=" << h;
  };
  for (double bad : {kNaN, kInf, -kInf}) {
    for (int pos = 0; pos < 9; ++pos) {
      MatrixXd a = A;
      a(pos % 3, pos / 3) = bad;
      check(a, B, 0.1, Status::non_finite_input);
      check(a, B, -1.0, Status::non_finite_input);  // finiteness is checked first
    }
    for (int pos = 0; pos < 6; ++pos) {
      MatrixXd b = B;
      b(pos % 3, pos / 3) = bad;
      check(A, b, 0.1, Status::non_finite_input);
    }
    check(A, B, bad, Status::non_finite_input);  // a NaN/Inf step is a non-finite input
  }
  for (double h : {0.0, -0.0, -1e-300, -0.1, -1e300}) check(A, B, h, Status::invalid_parameter);
  check(1e300 * A, B, 1e10, Status::out_of_range);                         // A h overflows
  check(A, 1e300 * B, 1e10, Status::out_of_range);                         // B h overflows
  check(1000.0 * MatrixXd::Identity(3, 3), B, 1.0, Status::out_of_range);  // e^1000 overflows
  // A tiny positive step is valid: A_d = I + A h, B_d = B h (to rounding).
  MatrixXd A_d = Ad0, B_d = Bd0;
  ASSERT_EQ(ops.zoh(A, B, 1e-200, A_d, B_d), Status::ok);
  const MatrixXd I_plus_Ah = MatrixXd::Identity(3, 3) + 1e-200 * A;  // diagonal rounds to 1
  EXPECT_LE(max_abs(A_d - I_plus_Ah), 1e-215);
  EXPECT_LE(max_abs(B_d - 1e-200 * B), 1e-215);
}

TEST(Zoh, OutputsMayAliasInputs) {
  const ZohOps ops = zoh_ops<3, 2>();
  Rng rng(0xE203);
  const MatrixXd A = rng.mat(3, 3), B = rng.mat(3, 2);
  MatrixXd A_d = MatrixXd::Zero(3, 3), B_d = MatrixXd::Zero(3, 2);
  ASSERT_EQ(ops.zoh(A, B, 0.7, A_d, B_d), Status::ok);
  MatrixXd A2 = A, B2 = B;
  ASSERT_EQ(ops.zoh_aliased(A2, B2, 0.7), Status::ok);
  EXPECT_TRUE(A2 == A_d);
  EXPECT_TRUE(B2 == B_d);
}

}  // namespace

using namespace ADCS_UNITY_ID;  // as an anonymous namespace would (CMakeLists.txt, adcs_unity)
