// Property tests of the offline/online linear algebra: right pseudo-inverse (exact and damped),
// continuous Lyapunov solver and the double-integrator pole placement (seed 001 §A.3).
// Truth values come from independent computations done here only: Eigen's JacobiSVD, a
// Kronecker-product Lyapunov solve, the closed-form P of spec §A.3 and Eigen's EigenSolver.
#include <gtest/gtest.h>

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <Eigen/LU>
#include <Eigen/QR>
#include <Eigen/SVD>
#include <cmath>
#include <complex>
#include <limits>
#include <random>
#include <vector>

#include "adcs/math/lyapunov.hpp"
#include "adcs/math/pinv.hpp"
#include "adcs/math/place.hpp"

// Sophus-style explicit instantiation: every template (including sizes no test below uses) is
// compiled in this translation unit under -Werror.
namespace adcs {
template Status right_pinv_solve<3, 3>(const Mat<3, 3>&, const Vec<3>&, Vec<3>&, PinvInfo*) noexcept;
template Status right_pinv<3, 6>(const Mat<3, 6>&, Mat<6, 3>&, PinvInfo*) noexcept;
template Status damped_right_pinv_solve<1, 4>(const Mat<1, 4>&, const Vec<1>&, Vec<4>&, const DampingParams&,
                                              PinvInfo*) noexcept;
template Status solve_continuous_lyapunov<3>(const Mat<3, 3>&, const Mat<3, 3>&, Mat<3, 3>&) noexcept;
template Status place_double_integrator<4>(const AxisPoles<4>&, Mat<4, 8>&) noexcept;
template Mat<4, 8> double_integrator_closed_loop<4>(const Mat<4, 4>&) noexcept;
}  // namespace adcs

namespace {

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
  template <int R, int C>
  Mat<R, C> mat(double lo = -1.0, double hi = 1.0) {
    Mat<R, C> m;
    for (int j = 0; j < C; ++j)
      for (int i = 0; i < R; ++i) m(i, j) = uniform(lo, hi);
    return m;
  }
  //! Random orthogonal n x n matrix (QR of a random matrix).
  MatrixXd orthogonal(int n) {
    MatrixXd m(n, n);
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) m(i, j) = uniform(-1, 1);
    return Eigen::HouseholderQR<MatrixXd>(m).householderQ();
  }
  bool coin() { return uniform(0, 1) < 0.5; }

 private:
  std::mt19937_64 gen_;
};

double max_abs(const Eigen::Ref<const MatrixXd>& m) { return m.cwiseAbs().maxCoeff(); }

//! Fat R x C matrix U diag(s) V^T with prescribed singular values s (size R).
template <int R, int C>
Mat<R, C> with_singular_values(Rng& rng, const VectorXd& s) {
  const MatrixXd U = rng.orthogonal(R), V = rng.orthogonal(C);
  MatrixXd S = MatrixXd::Zero(R, C);
  S.diagonal() = s;
  return Mat<R, C>(U * S * V.transpose());
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
  for (int i = 0; i < d.s.size(); ++i) {
    const double g = d.s(i) / (d.s(i) * d.s(i) + lambda2);
    u += g * d.U.col(i).dot(v) * d.V.col(i);
  }
  return u;
}

// =============================================================================================
// Right pseudo-inverse, typed over the fat shapes used by the allocators.

template <int R_, int C_>
struct Dims {
  static constexpr int R = R_;
  static constexpr int C = C_;
};

template <class D>
class Pinv : public ::testing::Test {};
using PinvShapes = ::testing::Types<Dims<3, 4>, Dims<3, 7>, Dims<2, 5>>;
TYPED_TEST_SUITE(Pinv, PinvShapes);

TYPED_TEST(Pinv, ExactInverseIsTheMinimumNormSolution) {
  constexpr int R = TypeParam::R, C = TypeParam::C;
  Rng rng(0xA100 + 16 * R + C);
  int used = 0;
  for (int k = 0; k < 3 * kSamples && used < kSamples; ++k) {
    const Mat<R, C> X = rng.template mat<R, C>();
    const Vec<R> v = rng.template mat<R, 1>(-2, 2);
    const Svd d = svd_of(X);
    const double cond = d.s(0) / d.s(R - 1);
    if (cond > 50.0) continue;  // accuracy claims below are for well-conditioned X
    ++used;

    Vec<C> u = Vec<C>::Zero();
    adcs::PinvInfo info;
    ASSERT_EQ(adcs::right_pinv_solve<R, C>(X, v, u, &info), Status::ok);
    EXPECT_LE((X * u - v).norm(), 1e-12 * v.norm());
    // Minimum-norm solution: equal to the SVD/COD pseudo-inverse solve.
    const VectorXd u_svd = Eigen::JacobiSVD<MatrixXd>(X, Eigen::ComputeThinU | Eigen::ComputeThinV).solve(VectorXd(v));
    const VectorXd u_cod = Eigen::CompleteOrthogonalDecomposition<MatrixXd>(X).solve(VectorXd(v));
    EXPECT_LE((u - u_svd).norm(), 1e-12 * u_svd.norm());
    EXPECT_LE((u - u_cod).norm(), 1e-12 * u_cod.norm());
    // ... so u has no component in null(X): adding one only makes it longer.
    const VectorXd n = d.V.col(C - 1);  // a null-space direction (C > R)
    EXPECT_LE(std::abs(n.dot(u)), 1e-12 * u.norm());

    // Diagnostics agree with the SVD.
    EXPECT_LE(std::abs(info.sigma_max - d.s(0)), 1e-14 * d.s(0));
    EXPECT_LE(std::abs(info.sigma_min - d.s(R - 1)), 10 * kEps * d.s(0) * d.s(0) / d.s(R - 1));
    EXPECT_NEAR(info.condition, cond * cond, 1e-10 * cond * cond);
    EXPECT_EQ(info.damping, 0.0);
    EXPECT_FALSE(info.damped);

    // The matrix form: X X+ = I and the Moore-Penrose conditions.
    Mat<C, R> Xp = Mat<C, R>::Zero();
    ASSERT_EQ(adcs::right_pinv<R, C>(X, Xp), Status::ok);
    EXPECT_LE(max_abs(X * Xp - Mat<R, R>::Identity()), 1e-12);
    const Mat<C, C> XpX = Xp * X;
    EXPECT_LE(max_abs(XpX - XpX.transpose()), 1e-12);
    EXPECT_LE(max_abs(Xp * X * Xp - Xp), 1e-12 * max_abs(Xp));
    EXPECT_LE((Xp * v - u).norm(), 1e-12 * u.norm());
    // The info pointer is optional and does not change the answer.
    Vec<C> u2 = Vec<C>::Zero();
    ASSERT_EQ(adcs::right_pinv_solve<R, C>(X, v, u2), Status::ok);
    EXPECT_EQ(u2, u);
  }
  EXPECT_GE(used, kSamples / 2);
}

TYPED_TEST(Pinv, ConditionThresholdIsHonoured) {
  // cond(X X^T) = (s_max/s_min)^2: 1e10 is accepted, 1e14 refused (kPinvMaxCondition = 1e12).
  constexpr int R = TypeParam::R, C = TypeParam::C;
  Rng rng(0xA200 + 16 * R + C);
  for (int k = 0; k < 20; ++k) {
    VectorXd s = VectorXd::LinSpaced(R, 1.0, 0.5);
    s(R - 1) = 1e-5;
    const Mat<R, C> X_ok = with_singular_values<R, C>(rng, s);
    s(R - 1) = 1e-7;
    const Mat<R, C> X_bad = with_singular_values<R, C>(rng, s);
    const Vec<R> v = rng.template mat<R, 1>();
    Vec<C> u = Vec<C>::Zero();
    adcs::PinvInfo info;
    EXPECT_EQ(adcs::right_pinv_solve<R, C>(X_ok, v, u, &info), Status::ok);
    EXPECT_NEAR(info.condition, 1e10, 1e6);
    EXPECT_LE((X_ok * u - v).norm(), 1e-5 * v.norm());
    const Vec<C> sentinel = Vec<C>::Constant(123.0);
    u = sentinel;
    EXPECT_EQ(adcs::right_pinv_solve<R, C>(X_bad, v, u, &info), Status::singular);
    EXPECT_EQ(u, sentinel);
    EXPECT_GT(info.condition, adcs::kPinvMaxCondition);
  }
}

TYPED_TEST(Pinv, ExactlySingularIsRefusedWithOutputsUntouched) {
  constexpr int R = TypeParam::R, C = TypeParam::C;
  Rng rng(0xA300 + 16 * R + C);
  const Vec<C> sentinel = Vec<C>::Constant(-7.0);
  const Mat<C, R> sentinel_m = Mat<C, R>::Constant(5.0);
  for (int k = 0; k < kSamples; ++k) {
    Mat<R, C> X = rng.template mat<R, C>();
    if (k == 0) {
      X.setZero();
    } else {
      X.row(R - 1) = rng.uniform(-3, 3) * X.row(0);  // rank R - 1
    }
    const Vec<R> v = rng.template mat<R, 1>();
    Vec<C> u = sentinel;
    adcs::PinvInfo info;
    EXPECT_EQ(adcs::right_pinv_solve<R, C>(X, v, u, &info), Status::singular);
    EXPECT_EQ(u, sentinel);
    EXPECT_LE(info.sigma_min, 1e-7 * std::max(info.sigma_max, 1.0));
    EXPECT_GT(info.condition, adcs::kPinvMaxCondition);  // inf for X = 0
    Mat<C, R> Xp = sentinel_m;
    EXPECT_EQ(adcs::right_pinv<R, C>(X, Xp), Status::singular);
    EXPECT_EQ(Xp, sentinel_m);
  }
}

TYPED_TEST(Pinv, DampedInverseAtExactSingularityIsBoundedAndReproducesTheRange) {
  constexpr int R = TypeParam::R, C = TypeParam::C;
  Rng rng(0xA400 + 16 * R + C);
  for (const adcs::DampingParams params : {adcs::DampingParams{}, adcs::DampingParams{0.05, 0.1}}) {
    for (int k = 0; k < kSamples; ++k) {
      Mat<R, C> X = rng.template mat<R, C>();
      X.row(R - 1) = rng.uniform(-3, 3) * X.row(0);  // rank R - 1
      const Vec<R> v = rng.template mat<R, 1>(-2, 2);
      Vec<C> u = Vec<C>::Constant(kNaN);
      adcs::PinvInfo info;
      ASSERT_EQ(adcs::damped_right_pinv_solve<R, C>(X, v, u, params, &info), Status::ill_conditioned);
      ASSERT_TRUE(adcs::all_finite(u));
      EXPECT_TRUE(info.damped);
      const double r = info.sigma_min / params.sigma_threshold;
      EXPECT_NEAR(info.damping, params.lambda_max * params.lambda_max * (1.0 - r * r), 1e-15);
      EXPECT_GT(info.damping, 0.99 * params.lambda_max * params.lambda_max);
      const double lambda = std::sqrt(info.damping);

      // Gain along every singular direction is s/(s^2 + lambda^2) <= 1/(2 lambda).
      EXPECT_LE(u.norm(), v.norm() / (2.0 * lambda) * (1.0 + 1e-12));
      // Exactly the damped least-squares solution.
      const Svd d = svd_of(X);
      const VectorXd u_ref = damped_truth(d, VectorXd(v), info.damping);
      EXPECT_LE((VectorXd(u) - u_ref).norm(), 1e-9 * u_ref.norm());
      // X u reproduces the part of v in range(X) up to the damping error lambda^2/(s^2+lambda^2).
      const MatrixXd Ur = d.U.leftCols(R - 1);
      const VectorXd v_range = Ur * (Ur.transpose() * VectorXd(v));
      const double s_r = d.s(R - 2);
      const double damping_error = info.damping / (s_r * s_r + info.damping);
      EXPECT_LE((VectorXd(X * u) - v_range).norm(), damping_error * v_range.norm() + 1e-10 * v.norm());
      // Nothing leaks into the lost direction.
      EXPECT_LE(std::abs(d.U.col(R - 1).dot(VectorXd(X * u))), 1e-10 * v.norm());
    }
    // X = 0: damped to u = 0.
    Vec<C> u = Vec<C>::Constant(1.0);
    EXPECT_EQ(adcs::damped_right_pinv_solve<R, C>(Mat<R, C>::Zero(), Vec<R>::Ones(), u, params), Status::ill_conditioned);
    EXPECT_EQ(u, Vec<C>::Zero());
  }
  // Damping disabled: an exactly singular X cannot be inverted; u untouched.
  Vec<C> u = Vec<C>::Constant(3.0);
  EXPECT_EQ(adcs::damped_right_pinv_solve<R, C>(Mat<R, C>::Zero(), Vec<R>::Ones(), u, adcs::DampingParams{1e-3, 0.0}),
            Status::singular);
  EXPECT_EQ(u, Vec<C>::Constant(3.0));
}

TYPED_TEST(Pinv, DampedEqualsExactAboveThreshold) {
  constexpr int R = TypeParam::R, C = TypeParam::C;
  Rng rng(0xA500 + 16 * R + C);
  for (int k = 0; k < kSamples; ++k) {
    const Mat<R, C> X = rng.template mat<R, C>();
    const Vec<R> v = rng.template mat<R, 1>();
    adcs::PinvInfo info_exact, info_damped;
    Vec<C> u_exact = Vec<C>::Zero(), u_damped = Vec<C>::Zero();
    ASSERT_EQ(adcs::right_pinv_solve<R, C>(X, v, u_exact, &info_exact), Status::ok);
    adcs::DampingParams params;
    params.sigma_threshold = 0.999 * info_exact.sigma_min;  // just above: never damped
    params.lambda_max = 0.5;
    ASSERT_EQ(adcs::damped_right_pinv_solve<R, C>(X, v, u_damped, params, &info_damped), Status::ok);
    EXPECT_FALSE(info_damped.damped);
    EXPECT_EQ(info_damped.damping, 0.0);
    EXPECT_LE((u_damped - u_exact).norm(), 1e-14 * u_exact.norm());
    EXPECT_EQ(info_damped.sigma_min, info_exact.sigma_min);
    EXPECT_EQ(info_damped.sigma_max, info_exact.sigma_max);
    // ... and with the default (tiny) threshold too.
    ASSERT_EQ(adcs::damped_right_pinv_solve<R, C>(X, v, u_damped, adcs::DampingParams{}), Status::ok);
    EXPECT_LE((u_damped - u_exact).norm(), 1e-14 * u_exact.norm());
  }
}

TYPED_TEST(Pinv, DampedInverseIsContinuousThroughSingularity) {
  // X(eps) = U diag(1, 0.6, ..., eps) V^T: rank-deficient at eps = 0. Sweep eps -> 0 through the
  // damping threshold: u(eps) follows the damped-least-squares formula, stays bounded, and has no
  // jump at the threshold.
  constexpr int R = TypeParam::R, C = TypeParam::C;
  Rng rng(0xA600 + 16 * R + C);
  const adcs::DampingParams params;  // sigma_threshold 1e-3, lambda_max 1e-2
  for (int trial = 0; trial < 10; ++trial) {
    const MatrixXd U = rng.orthogonal(R), V = rng.orthogonal(C);
    const Vec<R> v = rng.template mat<R, 1>();
    auto X_of = [&](double eps) {
      MatrixXd S = MatrixXd::Zero(R, C);
      S.diagonal() = VectorXd::LinSpaced(R, 1.0, 0.6);
      S(R - 1, R - 1) = eps;
      return Mat<R, C>(U * S * V.transpose());
    };
    // sup over eps of the gain s/(s^2 + lambda(s)^2) is 1/sigma_threshold for these params
    // (it grows to 1/sigma_threshold as s rises to the threshold, then falls as 1/s).
    const double bound = v.norm() * std::max(1.0 / 0.6, 1.0 / params.sigma_threshold) * (1.0 + 1e-6);
    std::vector<double> sweep;
    for (double eps = 0.1; eps > 1e-12; eps *= 0.8) sweep.push_back(eps);
    sweep.push_back(0.0);
    for (double eps : sweep) {
      const Mat<R, C> X = X_of(eps);
      Vec<C> u = Vec<C>::Zero();
      adcs::PinvInfo info;
      const Status st = adcs::damped_right_pinv_solve<R, C>(X, v, u, params, &info);
      ASSERT_TRUE(st == Status::ok || st == Status::ill_conditioned) << adcs::to_string(st);
      EXPECT_EQ(st == Status::ill_conditioned, info.damped);
      ASSERT_TRUE(adcs::all_finite(u));
      EXPECT_LE(u.norm(), bound) << "eps = " << eps;
      // Follows the analytic damped solution with lambda^2 = lambda_max^2 (1 - (eps/t)^2).
      const double r = std::min(eps / params.sigma_threshold, 1.0);
      const double lambda2 = params.lambda_max * params.lambda_max * (1.0 - r * r);
      EXPECT_NEAR(info.damping, lambda2, 1e-6 * params.lambda_max * params.lambda_max) << "eps = " << eps;
      Svd d;
      d.U = U;
      d.V = V;
      d.s = VectorXd::LinSpaced(R, 1.0, 0.6);
      d.s(R - 1) = eps;
      const VectorXd u_ref = damped_truth(d, VectorXd(v), info.damping);
      EXPECT_LE((VectorXd(u) - u_ref).norm(), 1e-7 * u_ref.norm() + 1e-9) << "eps = " << eps;
    }
    // No jump at the threshold.
    const double t = params.sigma_threshold;
    Vec<C> below = Vec<C>::Zero(), above = Vec<C>::Zero();
    EXPECT_EQ(adcs::damped_right_pinv_solve<R, C>(X_of(t * (1 - 1e-9)), v, below, params), Status::ill_conditioned);
    EXPECT_EQ(adcs::damped_right_pinv_solve<R, C>(X_of(t * (1 + 1e-9)), v, above, params), Status::ok);
    EXPECT_LE((below - above).norm(), 1e-6 * above.norm());
  }
}

TYPED_TEST(Pinv, NonFiniteInputsLeaveOutputsUntouched) {
  constexpr int R = TypeParam::R, C = TypeParam::C;
  Rng rng(0xA700 + 16 * R + C);
  const Vec<C> sentinel = Vec<C>::Constant(9.0);
  const Mat<C, R> sentinel_m = Mat<C, R>::Constant(9.0);
  for (double bad : {kNaN, kInf, -kInf}) {
    for (int pos = 0; pos < R * C; ++pos) {
      Mat<R, C> X = rng.template mat<R, C>();
      const Vec<R> v = rng.template mat<R, 1>();
      X(pos % R, pos / R) = bad;
      Vec<C> u = sentinel;
      EXPECT_EQ(adcs::right_pinv_solve<R, C>(X, v, u), Status::non_finite_input);
      EXPECT_EQ(u, sentinel);
      EXPECT_EQ(adcs::damped_right_pinv_solve<R, C>(X, v, u, adcs::DampingParams{}), Status::non_finite_input);
      EXPECT_EQ(u, sentinel);
      Mat<C, R> Xp = sentinel_m;
      EXPECT_EQ(adcs::right_pinv<R, C>(X, Xp), Status::non_finite_input);
      EXPECT_EQ(Xp, sentinel_m);
    }
    for (int pos = 0; pos < R; ++pos) {
      const Mat<R, C> X = rng.template mat<R, C>();
      Vec<R> v = rng.template mat<R, 1>();
      v(pos) = bad;
      Vec<C> u = sentinel;
      EXPECT_EQ(adcs::right_pinv_solve<R, C>(X, v, u), Status::non_finite_input);
      EXPECT_EQ(u, sentinel);
      EXPECT_EQ(adcs::damped_right_pinv_solve<R, C>(X, v, u, adcs::DampingParams{}), Status::non_finite_input);
      EXPECT_EQ(u, sentinel);
    }
  }
}

TEST(PinvSquare, SquareInvertibleMatrixGivesTheInverse) {
  Rng rng(0xA800);
  for (int k = 0; k < kSamples; ++k) {
    const Mat<3, 3> X = rng.mat<3, 3>() + 3.0 * Mat<3, 3>::Identity();  // diagonally dominant
    const Vec<3> v = rng.mat<3, 1>();
    Vec<3> u = Vec<3>::Zero();
    ASSERT_EQ(adcs::right_pinv_solve<3, 3>(X, v, u), Status::ok);
    EXPECT_LE((u - X.inverse() * v).norm(), 1e-13 * u.norm());
  }
}

// =============================================================================================
// Continuous Lyapunov equation A^T P + P A = -Q

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
  const VectorXd p = L.fullPivLu().solve(-q);
  return Eigen::Map<const MatrixXd>(p.data(), n, n);
}

double residual(const MatrixXd& A, const MatrixXd& P, const MatrixXd& Q) {
  return (A.transpose() * P + P * A + Q).norm() / Q.norm();
}

TEST(Lyapunov, Seed001ClosedFormP) {
  // spec §A.3: A_1 = [[0, I3], [-Kp, -Kd]], Q = I6, P block-diagonal per axis.
  const Vec<3> kp(0.08, 0.18, 0.12), kd(0.4, 0.6, 0.5 * std::sqrt(2.0));
  Mat<6, 6> A1 = Mat<6, 6>::Zero();
  A1.topRightCorner<3, 3>().setIdentity();
  A1.bottomLeftCorner<3, 3>() = Vec<3>(-kp).asDiagonal();
  A1.bottomRightCorner<3, 3>() = Vec<3>(-kd).asDiagonal();
  Mat<6, 6> P = Mat<6, 6>::Zero();
  ASSERT_EQ(adcs::solve_continuous_lyapunov<6>(A1, Mat<6, 6>::Identity(), P), Status::ok);

  const Vec<3> p12 = (0.5 * kp.cwiseInverse()).eval();
  const Vec<3> p22 = ((Vec<3>::Ones() + kp).cwiseQuotient(2.0 * kp.cwiseProduct(kd))).eval();
  const Vec<3> p11 = ((Vec<3>::Ones() + kp).cwiseQuotient(2.0 * kd) + kd.cwiseQuotient(2.0 * kp)).eval();
  for (int i = 0; i < 3; ++i) {
    EXPECT_NEAR(P(i, i), p11(i), 1e-12 * p11(i));
    EXPECT_NEAR(P(i, i + 3), p12(i), 1e-12 * p12(i));
    EXPECT_NEAR(P(i + 3, i), p12(i), 1e-12 * p12(i));
    EXPECT_NEAR(P(i + 3, i + 3), p22(i), 1e-12 * p22(i));
  }
  // Off-diagonal entries within each block vanish.
  Mat<6, 6> structure = P;
  for (int i = 0; i < 3; ++i) {
    structure(i, i) = structure(i, i + 3) = structure(i + 3, i) = structure(i + 3, i + 3) = 0.0;
  }
  EXPECT_LE(max_abs(structure), 1e-12 * max_abs(P));
  // The numbers printed in the spec (8 significant digits).
  const Vec<3> p11_spec(3.85, 2.65, 3.73823785), p12_spec(6.25, 2.77777778, 4.16666667),
      p22_spec(16.875, 5.46296296, 6.59966329);
  for (int i = 0; i < 3; ++i) {
    EXPECT_NEAR(P(i, i), p11_spec(i), 5e-9);
    EXPECT_NEAR(P(i, i + 3), p12_spec(i), 5e-9);
    EXPECT_NEAR(P(i + 3, i + 3), p22_spec(i), 5e-9);
  }
  EXPECT_LE(residual(A1, P, MatrixXd::Identity(6, 6)), 1e-14);
  EXPECT_EQ(P, P.transpose());
}

template <int N>
struct Size {
  static constexpr int n = N;
};
template <class S>
class LyapunovRandom : public ::testing::Test {};
using LyapunovSizes = ::testing::Types<Size<2>, Size<6>, Size<12>>;
TYPED_TEST_SUITE(LyapunovRandom, LyapunovSizes);

TYPED_TEST(LyapunovRandom, ResidualSymmetryAndPositiveDefiniteness) {
  constexpr int N = TypeParam::n;
  Rng rng(0xB100 + N);
  for (int k = 0; k < kSamples; ++k) {
    Mat<N, N> A;
    if (k % 2 == 0) {
      // -(M M^T + I) plus a skew part: eigenvalue real parts <= -1.
      const Mat<N, N> M = rng.template mat<N, N>(), S = rng.template mat<N, N>(-2, 2);
      A = -(M * M.transpose() + Mat<N, N>::Identity()) + (S - S.transpose());
    } else {
      // A random (non-normal) matrix shifted by its spectral abscissa.
      const Mat<N, N> M = rng.template mat<N, N>();
      const double abscissa = Eigen::EigenSolver<MatrixXd>(MatrixXd(M)).eigenvalues().real().maxCoeff();
      A = M - (abscissa + rng.uniform(0.1, 1.0)) * Mat<N, N>::Identity();
    }
    Mat<N, N> Q = Mat<N, N>::Identity();
    if (k % 3 == 1) {
      const Mat<N, N> W = rng.template mat<N, N>();
      Q = W * W.transpose() + 0.1 * Mat<N, N>::Identity();
      Q = (0.5 * (Q + Q.transpose())).eval();  // exactly symmetric, so P is symmetrised
    }
    Mat<N, N> P = Mat<N, N>::Zero();
    ASSERT_EQ(adcs::solve_continuous_lyapunov<N>(A, Q, P), Status::ok);
    EXPECT_LE(residual(A, P, Q), 1e-12) << "sample " << k;
    EXPECT_EQ(P, P.transpose());
    const Eigen::SelfAdjointEigenSolver<MatrixXd> eig(P);
    EXPECT_GT(eig.eigenvalues().minCoeff(), 0.0) << "sample " << k;
    EXPECT_EQ(Eigen::LLT<Mat<N, N>>(P).info(), Eigen::Success);
  }
}

TEST(Lyapunov, MatchesKroneckerSolve) {
  constexpr int N = 5;
  Rng rng(0xB200);
  for (int k = 0; k < kSamples; ++k) {
    const Mat<N, N> M = rng.mat<N, N>();
    const double abscissa = Eigen::EigenSolver<MatrixXd>(MatrixXd(M)).eigenvalues().real().maxCoeff();
    const Mat<N, N> A = M - (abscissa + 0.2) * Mat<N, N>::Identity();
    // Non-symmetric Q too: the solver must not assume symmetry it was not given.
    const Mat<N, N> Q = (k % 2 == 0) ? Mat<N, N>(rng.mat<N, N>()) : Mat<N, N>::Identity();
    Mat<N, N> P = Mat<N, N>::Zero();
    ASSERT_EQ(adcs::solve_continuous_lyapunov<N>(A, Q, P), Status::ok);
    const MatrixXd P_ref = lyapunov_kron(A, Q);
    EXPECT_LE(max_abs(MatrixXd(P) - P_ref), 1e-10 * max_abs(P_ref)) << "sample " << k;
    EXPECT_LE(residual(A, P, Q), 1e-12);
  }
}

TEST(Lyapunov, DiagonalAClosedFormIncludingUnstable) {
  // Diagonal A: P_ij = -Q_ij / (a_i + a_j); unique whenever no a_i + a_j = 0, stable or not.
  Rng rng(0xB300);
  for (int k = 0; k < kSamples; ++k) {
    Vec<4> a;
    for (int i = 0; i < 4; ++i) a(i) = (rng.coin() ? 1.0 : -1.0) * rng.uniform(0.5, 2.0);
    bool resonant = false;
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j) resonant = resonant || std::abs(a(i) + a(j)) < 0.05;
    if (resonant) continue;
    const Mat<4, 4> A = a.asDiagonal();
    const Mat<4, 4> W = rng.mat<4, 4>();
    const Mat<4, 4> Q = W + W.transpose();
    Mat<4, 4> P = Mat<4, 4>::Zero();
    ASSERT_EQ(adcs::solve_continuous_lyapunov<4>(A, Q, P), Status::ok);
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j) EXPECT_NEAR(P(i, j), -Q(i, j) / (a(i) + a(j)), 1e-13);
  }
  // n = 1: p = -q / (2 a).
  Mat<1, 1> P1 = Mat<1, 1>::Zero();
  ASSERT_EQ(adcs::solve_continuous_lyapunov<1>(Mat<1, 1>::Constant(-0.25), Mat<1, 1>::Constant(3.0), P1), Status::ok);
  EXPECT_NEAR(P1(0, 0), 6.0, 1e-15);
}

TEST(Lyapunov, ResonantSpectrumIsSingularAndNonFiniteIsRejected) {
  const Mat<2, 2> sentinel = Mat<2, 2>::Constant(-1.0);
  Mat<2, 2> rot;
  rot << 0, 1, -1, 0;  // eigenvalues +-i: lambda + conj(lambda) = 0
  Mat<2, 2> saddle;
  saddle << 1, 0, 0, -1;  // lambda_1 + lambda_2 = 0
  Mat<2, 2> jordan;
  jordan << 0, 1, 0, 0;  // double eigenvalue 0
  Mat<2, 2> rot_scaled = 3.7 * rot;
  Mat<2, 2> similar;  // saddle in a skewed basis: still lambda_1 + lambda_2 = 0
  Mat<2, 2> T;
  T << 2, 1, 0.5, 3;
  similar = T * saddle * T.inverse();
  for (const Mat<2, 2>& A : {rot, saddle, jordan, rot_scaled, Mat<2, 2>(Mat<2, 2>::Zero()), similar}) {
    Mat<2, 2> P = sentinel;
    EXPECT_EQ(adcs::solve_continuous_lyapunov<2>(A, Mat<2, 2>::Identity(), P), Status::singular) << A;
    EXPECT_EQ(P, sentinel);
  }
  // The seed-001 structure with Kd = 0 (undamped oscillators) is resonant as well.
  Mat<6, 6> A_undamped = Mat<6, 6>::Zero();
  A_undamped.topRightCorner<3, 3>().setIdentity();
  A_undamped.bottomLeftCorner<3, 3>() = Vec<3>(-0.08, -0.18, -0.12).asDiagonal();
  Mat<6, 6> P6 = Mat<6, 6>::Constant(2.0);
  EXPECT_EQ(adcs::solve_continuous_lyapunov<6>(A_undamped, Mat<6, 6>::Identity(), P6), Status::singular);
  EXPECT_EQ(P6, Mat<6, 6>::Constant(2.0));

  for (double bad : {kNaN, kInf}) {
    Mat<2, 2> A = -Mat<2, 2>::Identity();
    A(1, 0) = bad;
    Mat<2, 2> P = sentinel;
    EXPECT_EQ(adcs::solve_continuous_lyapunov<2>(A, Mat<2, 2>::Identity(), P), Status::non_finite_input);
    EXPECT_EQ(P, sentinel);
    Mat<2, 2> Q = Mat<2, 2>::Identity();
    Q(0, 1) = bad;
    EXPECT_EQ(adcs::solve_continuous_lyapunov<2>(Mat<2, 2>(-Mat<2, 2>::Identity()), Q, P), Status::non_finite_input);
    EXPECT_EQ(P, sentinel);
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
TYPED_TEST_SUITE(PlaceRandom, PlaceAxes);

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
    for (const cplx bad : {cplx(kNaN, 0.0), cplx(-1.0, kInf), cplx(-kInf, 0.0)}) {
      poles[bad_axis] = {cplx(-1.0, 0.0), bad};
      EXPECT_EQ(adcs::place_double_integrator<Axes>(poles, K), Status::non_finite_input);
      EXPECT_EQ(K, sentinel);
    }
  }
}

}  // namespace
