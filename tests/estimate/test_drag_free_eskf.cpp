// seed 004 Algorithm 1 (spec §B.4) — sanity checks B.11: 4 (covariances symmetric and PSD over a
// long closed-loop-like run, after fusion too) and 7 (fusion), the two-block filter against the
// 27-state filter, the PSD test and projection, and bad input. One of three files of the drag-free
// estimator tests, split so that two cores share them.
#include <gtest/gtest.h>

#include <Eigen/Cholesky>
#include <cmath>
#include <limits>
#include <random>

#include "adcs/estimate/eskf.hpp"
#include "adcs/estimate/fusion.hpp"
#include "adcs/math/pinv.hpp"
#include "drag_free_test_params.hpp"

namespace ADCS_UNITY_ID {
using namespace adcs::test::drag_free;  // discrete(), eskf_params(), esf_params(), Status, Vec3, Mat3, Ix

TEST(DragFreeEskf, CovarianceStaysSymmetricPsdThroughFusionB11_4AndFusionB11_7) {
  const adcs::DragFreeParams p;
  const adcs::DragFreeDiscrete d = discrete();
  adcs::DragFreeEskf alg1(eskf_params(d));
  ASSERT_EQ(alg1.status(), Status::ok);
  std::vector<adcs::SaturatedEsf> alg2;
  for (int j = 0; j < 3; ++j) alg2.emplace_back(esf_params(j));
  std::mt19937_64 gen(7);
  std::normal_distribution<double> N01;
  adcs::Vec<27> X = adcs::Vec<27>::Zero();
  X.segment<3>(Ix::F_Dsc).setConstant(-12.8e-3);
  X.segment<3>(Ix::T_Dsc).setConstant(-12.8e-3);
  const adcs::DragFreeNoise n = adcs::drag_free_noise(p);
  for (int k = 0; k < 3000; ++k) {
    const adcs::Vec<9> u = adcs::Vec<9>::Zero();
    if (k > 0) {
      ASSERT_EQ(alg1.predict(u), Status::ok);
      for (auto& a : alg2) ASSERT_EQ(a.predict(0.0), Status::ok);
    }
    adcs::Vec<9> Y = d.C_d * X;
    for (int i = 0; i < 9; ++i) Y(i) += n.sigma_pos * N01(gen);
    ASSERT_EQ(alg1.update(Y), Status::ok);
    for (int j = 0; j < 3; ++j) {
      const double y = adcs::drag_free_accelerometer(p, X, Vec3::Zero(), j) + n.sigma_acc * N01(gen);
      ASSERT_TRUE(adcs::usable(alg2[j].update(adcs::saturate_accelerometer(p, y), 0.0)));
      ASSERT_EQ(adcs::fuse_axis(alg1, alg2[j], j), Status::ok);
      // B.11-7: Algorithm 1's fused entries equal X̂_o, Algorithm 2 holds X̂_o.
      EXPECT_EQ(alg1.state()(Ix::r + j), alg2[j].state()(0));
      EXPECT_EQ(alg1.state()(Ix::F_Dsc + j), alg2[j].state()(2));
    }
    if (k % 100 == 0 || k == 2999) {  // B.11-4
      const adcs::Mat<27, 27>& P = alg1.covariance();
      EXPECT_LE((P - P.transpose()).norm(), 1e-15 * P.norm()) << k;
      const Eigen::SelfAdjointEigenSolver<adcs::Mat<27, 27>> es(P);
      EXPECT_GE(es.eigenvalues().minCoeff(), -1e-12 * P.norm()) << k;
      for (auto& a : alg2) {
        const Eigen::SelfAdjointEigenSolver<Mat3> e3(a.covariance());
        EXPECT_GE(e3.eigenvalues().minCoeff(), -1e-12 * a.covariance().norm()) << k;
      }
    }
    X = (d.A_d * X).eval();
  }
  EXPECT_GT(alg1.theta(), 0.0);
  // Fusion equals the matrix form (40)-(41) with Γ⁺ = pinv(Γ) = Γᵀ.
  const adcs::Mat<3, 27> G = adcs::fusion_selector(1);
  adcs::Mat<27, 3> G_pinv;
  ASSERT_EQ((adcs::right_pinv<3, 27>(G, G_pinv)), Status::ok);
  EXPECT_LT((G_pinv - G.transpose()).norm(), 1e-15);
  const adcs::Vec<27> x1 = alg1.state();
  const adcs::Mat<27, 27> P1 = alg1.covariance();
  const Vec3 xo(x1(Ix::r + 1), x1(Ix::r_dot + 1), alg2[1].state()(2) + 1e-4);
  Mat3 Po = Mat3::Zero();
  Po.topLeftCorner<2, 2>() = (G * P1 * G.transpose()).topLeftCorner<2, 2>();
  Po(2, 2) = alg2[1].covariance()(2, 2);
  adcs::Vec3 x2 = alg2[1].state();
  x2(2) += 1e-4;
  ASSERT_EQ(alg2[1].set_estimate(x2, alg2[1].covariance()), Status::ok);
  ASSERT_EQ(adcs::fuse_axis(alg1, alg2[1], 1), Status::ok);
  const adcs::Mat<27, 27> I_GG = adcs::Mat<27, 27>::Identity() - G.transpose() * G;
  EXPECT_LT((alg1.state() - (I_GG * x1 + G_pinv * xo)).norm(), 1e-18);
  EXPECT_LT((alg1.covariance() - (I_GG * P1 * I_GG.transpose() + G_pinv * Po * G_pinv.transpose())).norm(), 1e-20);
}

// The two-block filter is Algorithm 1 on the 27-state matrices, up to the order of sums: same
// estimate, covariance and θ as Eskf<27> over a noisy run, with either θ policy. P_0 = 1e-12 I
// here: with the spec's 0.01 I the first updates shrink variances by 13 orders, so the last-bit
// differences of any two summation orders grow to 1e-2 relative for a few hundred steps before
// both filters forget P_0 (measured; the scenario metrics agree to 15 digits).
TEST(DragFreeEskf, TwoBlockFilterEqualsThe27StateFilter) {
  const adcs::DragFreeDiscrete d = discrete();
  for (const adcs::ThetaPolicy policy : {adcs::ThetaPolicy::trace_optimal, adcs::ThetaPolicy::fixed_initial}) {
    adcs::DragFreeEskf::Params e = eskf_params(d);
    e.theta_policy = policy;
    e.P0 = 1e-12 * adcs::Mat<27, 27>::Identity();
    adcs::DragFreeEskf split(e);
    adcs::Eskf<27, 9, 9, 9> full(e);
    ASSERT_EQ(split.status(), Status::ok);
    std::mt19937_64 gen(11);
    std::normal_distribution<double> N01;
    for (int k = 0; k < 400; ++k) {
      adcs::Vec<9> u, Y;
      for (int i = 0; i < 9; ++i) {
        u(i) = 1e-4 * N01(gen);
        Y(i) = 1e-8 * N01(gen);
      }
      ASSERT_EQ(split.predict(u), Status::ok);
      ASSERT_EQ(full.predict(u), Status::ok);
      EXPECT_NEAR(split.theta(), full.theta(), 1e-12 * full.theta()) << k;
      ASSERT_EQ(split.update(Y), Status::ok);
      ASSERT_EQ(full.update(Y), Status::ok);
      const adcs::Mat<27, 27> Ps = split.covariance(), Pf = full.covariance();
      for (int i = 0; i < 27; ++i) {
        const double sd_i = std::sqrt(Pf(i, i));
        ASSERT_NEAR(split.state()(i), full.state()(i), 1e-9 * std::abs(full.state()(i)) + 1e-5 * sd_i) << k << " " << i;
        for (int j = 0; j < 27; ++j)
          ASSERT_NEAR(Ps(i, j), Pf(i, j), 1e-9 * sd_i * std::sqrt(Pf(j, j))) << k << " " << i << " " << j;
      }
    }
    EXPECT_EQ(split.psd_projections(), full.psd_projections());
  }
}

TEST(DragFreeEskf, CouplingBetweenTheBlocksIsRejectedNotDropped) {
  const adcs::DragFreeDiscrete d = discrete();
  const adcs::DragFreeEskf::Params good = eskf_params(d);
  adcs::DragFreeEskf::Params a = good, r = good, p0 = good, c = good;
  a.A_d(Ix::r, Ix::phi_sc) = 1e-9;            // translation driven by attitude
  r.R(0, 3) = r.R(3, 0) = 1e-18;              // correlated φ_sc and r sensors
  p0.P0(Ix::phi_rel, Ix::F_Dsc) = p0.P0(Ix::F_Dsc, Ix::phi_rel) = 1e-4;
  c.C_d(3, Ix::phi_sc) = 1.0;                 // the r output sees φ_sc
  for (const auto& bad : {a, r, p0, c}) EXPECT_EQ(adcs::DragFreeEskf(bad).status(), Status::invalid_parameter);
  adcs::DragFreeEskfBase::Partition dup = adcs::drag_free_attitude_partition();
  dup.states[1] = dup.states[0];
  EXPECT_EQ(adcs::DragFreeEskfBase(good, dup).status(), Status::invalid_parameter);

  adcs::DragFreeEskf f(good);
  ASSERT_EQ(f.predict(adcs::Vec<9>::Zero()), Status::ok);
  const adcs::Vec<27> x = f.state();
  const adcs::Mat<27, 27> P = f.covariance();
  adcs::Mat<27, 27> coupled = P;
  coupled(Ix::r, Ix::phi_sc) = coupled(Ix::phi_sc, Ix::r) = 1e-20;
  EXPECT_EQ(f.set_estimate(x, coupled), Status::invalid_parameter);
  EXPECT_EQ(f.replace_substate<2>({Ix::r, Ix::phi_sc}, adcs::Vec<2>::Zero(), adcs::Mat<2, 2>::Identity()),
            Status::invalid_parameter);
  EXPECT_EQ(f.replace_substate<2>({Ix::r, 27}, adcs::Vec<2>::Zero(), adcs::Mat<2, 2>::Identity()),
            Status::invalid_parameter);
  EXPECT_EQ(f.replace_substate<2>({Ix::r, Ix::r_dot}, adcs::Vec<2>::Constant(NAN), adcs::Mat<2, 2>::Identity()),
            Status::non_finite_input);
  EXPECT_EQ(f.state(), x);
  EXPECT_EQ(f.covariance(), P);
  // A failure in the second block leaves the first one untouched too.
  adcs::Vec<9> Y = adcs::Vec<9>::Zero();
  Y(3) = INFINITY;  // an r output: block 2
  EXPECT_EQ(f.update(Y), Status::non_finite_input);
  EXPECT_EQ(f.state(), x);
  EXPECT_EQ(f.covariance(), P);
  ASSERT_EQ(f.set_estimate(x, P), Status::ok);
  EXPECT_EQ(f.covariance(), P);
}

// The cheap positive-definiteness proof agrees with Eigen's LDLT, and keep_psd leaves PSD
// matrices alone (semidefinite included) while projecting indefinite ones.
TEST(Covariance, PositivePivotsAgreesWithLdltAndKeepPsdOnlyProjectsIndefinite) {
  std::mt19937_64 gen(5);
  std::normal_distribution<double> N01;
  for (int trial = 0; trial < 200; ++trial) {
    adcs::Mat<18, 18> B;
    for (int i = 0; i < 18 * 18; ++i) B.data()[i] = N01(gen);
    const int rank = trial % 3 == 0 ? 12 : 18;
    const adcs::Mat<18, 18> Bl = B.leftCols(rank) * B.leftCols(rank).transpose();
    adcs::Mat<18, 18> P = 1e-12 * Bl;
    P = (0.5 * (P + P.transpose())).eval();
    if (trial % 3 == 1) {  // shift so that two eigenvalues are negative
      const adcs::Vec<18> ev = Eigen::SelfAdjointEigenSolver<adcs::Mat<18, 18>>(P).eigenvalues();
      P -= 0.5 * (ev(1) + ev(2)) * adcs::Mat<18, 18>::Identity();
    }
    const Eigen::SelfAdjointEigenSolver<adcs::Mat<18, 18>> es(P);
    const double lmin = es.eigenvalues().minCoeff(), lmax = es.eigenvalues().maxCoeff();
    if (lmin > 1e-8 * lmax) {
      EXPECT_TRUE(adcs::positive_pivots<18>(P)) << trial;
    }
    if (lmin < -1e-8 * lmax) {
      EXPECT_FALSE(adcs::positive_pivots<18>(P)) << trial;
      adcs::Mat<18, 18> Q = P;
      EXPECT_TRUE(adcs::keep_psd<18>(Q)) << trial;
      const Eigen::SelfAdjointEigenSolver<adcs::Mat<18, 18>> projected(Q);
      EXPECT_GE(projected.eigenvalues().minCoeff(), -1e-12 * lmax) << trial;
    }
    if (rank < 18) {  // exactly semidefinite by construction: no projection needed beyond rounding
      adcs::Mat<18, 18> Q = P;
      adcs::keep_psd<18>(Q);
      EXPECT_LE((Q - P).norm(), 1e-9 * P.norm()) << trial;
    }
  }
  EXPECT_FALSE(adcs::positive_pivots<3>(Mat3::Zero()));
  EXPECT_FALSE(adcs::positive_pivots<3>(Mat3(Vec3(1.0, NAN, 1.0).asDiagonal())));
  EXPECT_TRUE(adcs::positive_pivots<3>(Mat3::Identity()));
}

// Found by tests/fuzz (fuzz_seed004): a non-finite output of block 2 was reported as block 1's
// failure (singular here) instead of non_finite_input.
TEST(DragFreeEskf, NonFiniteMeasurementIsReportedAsSuchWhateverTheBlocks) {
  const adcs::DragFreeDiscrete d = discrete();
  adcs::DragFreeEskf f(eskf_params(d));
  const adcs::Mat<27, 27> minus_I = -adcs::Mat<27, 27>::Identity();  // C P Cᵀ + R < 0 in block 1
  ASSERT_EQ(f.set_estimate(adcs::Vec<27>::Zero(), minus_I), Status::ok);
  adcs::Vec<9> Y = adcs::Vec<9>::Zero();
  EXPECT_EQ(f.update(Y), Status::singular);  // block 1 cannot factor its innovation
  Y(4) = std::numeric_limits<double>::quiet_NaN();  // r_y: an output of block 2
  EXPECT_EQ(f.update(Y), Status::non_finite_input);
  EXPECT_EQ(f.covariance(), minus_I);
}
}  // namespace

using namespace ADCS_UNITY_ID;  // as an anonymous namespace would (CMakeLists.txt, adcs_unity)
