// Seed 004's U-D kernels (math/ud.hpp) and sparse rows (math/sparse_rows.hpp) in float (issue 19):
// the same operations as in double to float's precision, and the property the factored form is
// chosen for: D >= 0 whatever the rounding, where the float covariance form of the same update
// leaves the PSD cone. The double kernels' own tests are in estimate/test_drag_free_eskf.cpp.
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <cmath>
#include <random>

#include "adcs/math/sparse_rows.hpp"
#include "adcs/math/ud.hpp"

namespace ADCS_UNITY_ID {

using adcs::Mat;
using adcs::UdFactors;
using adcs::Vec;

//! A symmetric PSD N x N matrix with eigenvalues 10^(−decades · u), u uniform in [0, 1], and the
//! last N − rank of them zero.
template <int N>
Mat<N, N> random_psd(std::mt19937_64& gen, int rank, double decades) {
  std::normal_distribution<double> N01;
  std::uniform_real_distribution<double> U01;
  Mat<N, N> G;
  for (int i = 0; i < N * N; ++i) G.data()[i] = N01(gen);
  const Eigen::HouseholderQR<Mat<N, N>> qr(G);
  const Mat<N, N> Q = qr.householderQ();
  Vec<N> ev;
  for (int i = 0; i < N; ++i) ev(i) = i < rank ? std::pow(10.0, -decades * U01(gen)) : 0.0;
  const Mat<N, N> P = Q * ev.asDiagonal() * Q.transpose();
  return (0.5 * (P + P.transpose())).eval();
}

template <int N>
double relative_difference(const Mat<N, N, float>& a, const Mat<N, N>& b) {
  return (a.template cast<double>() - b).norm() / b.norm();
}

}  // namespace ADCS_UNITY_ID
using namespace ADCS_UNITY_ID;  // as an anonymous namespace would (CMakeLists.txt, adcs_unity)

// Factorisation: the float tolerance (64 N ε of float) takes a zero-variance row as exactly zero
// and refuses an indefinite or non-finite P, output untouched, as in double. Full-rank P only: a
// rank-deficient P rounded to float is in general no longer PSD (its zero eigenvalues move by
// ~ε_float |P|), and refusing it is the right answer; an exact zero row stays exact.
TEST(UdFactorsFloat, FactorizeMatchesDoubleAndRefusesIndefiniteMatrices) {
  std::mt19937_64 gen(11);
  for (int trial = 0; trial < 50; ++trial) {
    const Mat<9, 9> P = random_psd<9>(gen, 9, 3.0);
    UdFactors<9, float> f;
    ASSERT_TRUE(adcs::ud_factorize(Mat<9, 9, float>(P.cast<float>()), f)) << trial;
    EXPECT_GE(f.D.minCoeff(), 0.0f);
    EXPECT_TRUE(f.U.isUpperTriangular(0.0f));
    EXPECT_TRUE(f.U.diagonal().isOnes(0.0f));
    // Float rounding of P itself is 6e-8 relative; the factorisation adds a few units of it.
    EXPECT_LE(relative_difference<9>(adcs::ud_covariance(f), P), 2e-6) << trial;
  }
  Mat<9, 9> P = random_psd<9>(gen, 9, 2.0);
  P.row(4).setZero();
  P.col(4).setZero();
  UdFactors<9, float> f;
  ASSERT_TRUE(adcs::ud_factorize(Mat<9, 9, float>(P.cast<float>()), f));
  EXPECT_EQ(f.D(4), 0.0f);
  const UdFactors<9, float> before = f;
  Mat<9, 9, float> bad = P.cast<float>();
  bad(0, 0) = -1e-3f;
  EXPECT_FALSE(adcs::ud_factorize(bad, f));
  bad = P.cast<float>();
  bad(2, 3) = bad(3, 2) = NAN;
  EXPECT_FALSE(adcs::ud_factorize(bad, f));
  EXPECT_EQ(f.U, before.U);
  EXPECT_EQ(f.D, before.D);
}

// Thornton's MWGS, Bierman's update and Agee–Turner in float against the same sequence in double,
// on the data of the double test (random W, weights over six decades, sparse h and a).
TEST(UdFactorsFloat, MwgsBiermanAndAgeeTurnerFollowTheDoubleKernels) {
  std::mt19937_64 gen(4);
  std::normal_distribution<double> N01;
  double worst = 0.0;
  for (int trial = 0; trial < 50; ++trial) {
    Mat<6, 10> W;
    Eigen::Matrix<double, 1, 10> w;
    for (int i = 0; i < 60; ++i) W.data()[i] = N01(gen);
    for (int i = 0; i < 10; ++i) w(i) = trial % 3 == 0 && i > 4 ? 0.0 : std::exp(3.0 * N01(gen));
    UdFactors<6> fd;
    UdFactors<6, float> ff;
    Mat<6, 10> Wd = W;
    Mat<6, 10, float> Wf = W.cast<float>();
    adcs::mwgs_ud(Wd, w, fd);
    adcs::mwgs_ud(Wf, Eigen::Matrix<float, 1, 10>(w.cast<float>()), ff);
    EXPECT_GE(ff.D.minCoeff(), 0.0f);
    worst = std::max(worst, relative_difference<6>(adcs::ud_covariance(ff), adcs::ud_covariance(fd)));

    Vec<6> h = Vec<6>::Zero();
    const int first = trial % 6;
    for (int i = first; i < 6; ++i) h(i) = i == first ? 1.0 : (trial % 2 ? N01(gen) : 0.0);
    const double r = std::exp(N01(gen));
    Vec<6> kd;
    Vec<6, float> kf;
    const double alpha_d = adcs::bierman_update(fd, Vec<6>(fd.U.transpose() * h), r, first, kd);
    const Vec<6, float> hf = h.cast<float>();
    const float alpha_f = adcs::bierman_update(ff, Vec<6, float>(ff.U.transpose() * hf), static_cast<float>(r), first, kf);
    EXPECT_NEAR(static_cast<double>(alpha_f), alpha_d, 1e-5 * alpha_d) << trial;
    EXPECT_LE((kf.cast<double>() - kd).norm(), 1e-4 * kd.norm() + 1e-30) << trial;
    EXPECT_GE(ff.D.minCoeff(), 0.0f);
    worst = std::max(worst, relative_difference<6>(adcs::ud_covariance(ff), adcs::ud_covariance(fd)));

    Vec<6> a;
    for (int i = 0; i < 6; ++i) a(i) = (trial % 4 == 3 && i > 2) ? 0.0 : N01(gen);
    const double c = trial % 5 == 0 ? 0.0 : std::exp(2.0 * N01(gen));
    Vec<6> ad = a;
    Vec<6, float> af = a.cast<float>();
    adcs::agee_turner_update(fd, c, ad);
    adcs::agee_turner_update(ff, static_cast<float>(c), af);
    EXPECT_GE(ff.D.minCoeff(), 0.0f);
    EXPECT_TRUE(ff.U.isUpperTriangular(0.0f));
    worst = std::max(worst, relative_difference<6>(adcs::ud_covariance(ff), adcs::ud_covariance(fd)));
  }
  // Relative to the covariance's norm (measured 4.0e-7, a few float rounding units).
  EXPECT_LE(worst, 2e-6);
}

// The reason for the factored form in float: a precise measurement of a state whose covariance
// spans ten decades (beyond float's seven digits). Bierman's update keeps D >= 0 in every trial;
// the float covariance form P − K h P of the same update (the Joseph form's difference without its
// symmetric completion) has a negative eigenvalue in some of them (measured: 23 of 40), which is
// what seed 004's dense filter needed its eigen projection for.
TEST(UdFactorsFloat, BiermanStaysPsdWhereTheFloatCovarianceFormDoesNot) {
  std::mt19937_64 gen(17);
  int covariance_form_indefinite = 0;
  for (int trial = 0; trial < 40; ++trial) {
    const Mat<9, 9> P = random_psd<9>(gen, 9, 10.0);
    const Mat<9, 9, float> Pf = P.cast<float>();
    UdFactors<9, float> f;
    if (!adcs::ud_factorize(Pf, f)) continue;  // float P itself may round out of the cone
    Vec<9, float> h = Vec<9, float>::Zero();
    h(trial % 9) = 1.0f;
    const float r = 1e-12f;
    Vec<9, float> k;
    (void)adcs::bierman_update(f, Vec<9, float>(f.U.transpose() * h), r, 0, k);
    EXPECT_TRUE(f.D.allFinite()) << trial;
    EXPECT_GE(f.D.minCoeff(), 0.0f) << trial;
    EXPECT_TRUE(k.allFinite()) << trial;

    const Vec<9, float> Ph = Pf * h;
    const float s = h.dot(Ph) + r;
    const Mat<9, 9, float> P_plus = Pf - (Ph / s) * Ph.transpose();
    const Eigen::SelfAdjointEigenSolver<Mat<9, 9, float>> es(P_plus, Eigen::EigenvaluesOnly);
    if (es.eigenvalues()(0) < 0.0f) ++covariance_form_indefinite;
  }
  EXPECT_GT(covariance_form_indefinite, 0);
}

// Sparse rows in float: Y Xᵀ from X's nonzeros equals the dense product to float rounding, and
// row_dot / first_col read the same structure.
TEST(SparseRowsFloat, ProductsMatchTheDenseForm) {
  std::mt19937_64 gen(5);
  std::normal_distribution<float> N01;
  Mat<7, 9, float> X = Mat<7, 9, float>::Zero();
  for (int i = 0; i < 7; ++i)
    for (int j = 0; j < 9; ++j)
      if ((i + 2 * j) % 3 == 0) X(i, j) = N01(gen);
  adcs::SparseRows<7, 9, float> sp;
  sp.assign(X);
  Mat<5, 9, float> Y;
  for (int i = 0; i < 45; ++i) Y.data()[i] = N01(gen);
  const Mat<5, 7, float> dense = Y * X.transpose();
  EXPECT_LE((sp.mul_by_transpose(Y) - dense).norm(), 1e-5f * dense.norm());
  const Vec<9, float> v = Y.row(0).transpose();
  for (int i = 0; i < 7; ++i) {
    EXPECT_NEAR(sp.row_dot(i, v), X.row(i).dot(v), 1e-5f * (1.0f + std::abs(X.row(i).dot(v))));
    int first = 9;
    for (int j = 8; j >= 0; --j)
      if (X(i, j) != 0.0f) first = j;
    EXPECT_EQ(sp.first_col(i), first);
  }
}
