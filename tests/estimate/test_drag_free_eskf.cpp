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
#include "adcs/estimate/eskf_ud.hpp"
#include "adcs/estimate/fusion.hpp"
#include "adcs/math/pinv.hpp"
#include "adcs/math/sparse_rows.hpp"
#include "adcs/math/ud.hpp"
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
  // The U-D filter re-factors the fused covariance (EskfUd::replace_substate): equal to rounding.
  const adcs::Mat<27, 27> P_fused = I_GG * P1 * I_GG.transpose() + G_pinv * Po * G_pinv.transpose();
  for (int i = 0; i < 27; ++i)
    for (int j = 0; j < 27; ++j)
      EXPECT_NEAR(alg1.covariance()(i, j), P_fused(i, j), 1e-13 * std::sqrt(P_fused(i, i) * P_fused(j, j))) << i << " " << j;
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
  EXPECT_LE((f.covariance() - P).norm(), 1e-14 * P.norm());  // re-factored
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
// failure instead of non_finite_input (then in the Joseph form, whose block 1 could fail first).
TEST(DragFreeEskf, NonFiniteMeasurementIsReportedAsSuchWhateverTheBlocks) {
  const adcs::DragFreeDiscrete d = discrete();
  adcs::DragFreeEskf f(eskf_params(d));
  ASSERT_EQ(f.predict(adcs::Vec<9>::Zero()), Status::ok);
  const adcs::Mat<27, 27> P = f.covariance();
  adcs::Vec<9> Y = adcs::Vec<9>::Zero();
  Y(4) = std::numeric_limits<double>::quiet_NaN();  // r_y: an output of block 2
  EXPECT_EQ(f.update(Y), Status::non_finite_input);
  EXPECT_EQ(f.covariance(), P);
}
}  // namespace

namespace ADCS_UNITY_ID {
// ---- issue 20: the U-D form (math/ud.hpp, EskfUd, DragFreeEskf) --------------------------------

//! A random orthogonal n x n matrix (Q of the QR of a Gaussian matrix). Dynamic size: one
//! HouseholderQR for every n the tests use (fixed sizes compiled one per n, ~10 CPU-s of this
//! file under ASan); below Eigen's blocking size both run the same unblocked loops.
Eigen::MatrixXd random_orthogonal(std::mt19937_64& gen, int n) {
  std::normal_distribution<double> N01;
  Eigen::MatrixXd B(n, n);
  for (int i = 0; i < n * n; ++i) B.data()[i] = N01(gen);
  const Eigen::HouseholderQR<Eigen::MatrixXd> qr(B);
  return qr.householderQ();
}

//! A random symmetric PSD n x n matrix of the given rank with eigenvalues spread over
//! `decades` decades (condition number 10^decades on its range).
template <int N>
adcs::Mat<N, N> random_psd(std::mt19937_64& gen, int rank, double decades) {
  const adcs::Mat<N, N> Q = random_orthogonal(gen, N);
  adcs::Vec<N> ev = adcs::Vec<N>::Zero();
  for (int i = 0; i < rank; ++i) ev(i) = std::pow(10.0, -decades * i / std::max(rank - 1, 1));
  adcs::Mat<N, N> P = Q * ev.asDiagonal() * Q.transpose();
  return (0.5 * (P + P.transpose())).eval();
}

TEST(UdFactors, FactorizeRoundTripsPsdMatricesAndRefusesIndefiniteOnes) {
  std::mt19937_64 gen(3);
  for (int trial = 0; trial < 100; ++trial) {
    const int rank = trial % 4 == 0 ? 5 : 9;
    const adcs::Mat<9, 9> P = random_psd<9>(gen, rank, trial % 2 ? 8.0 : 2.0);
    adcs::UdFactors<9> f;
    ASSERT_TRUE(adcs::ud_factorize<9>(P, f)) << trial;
    EXPECT_GE(f.D.minCoeff(), 0.0);
    EXPECT_TRUE(f.U.isUpperTriangular(0.0));
    EXPECT_TRUE(f.U.diagonal().isOnes(0.0));
    EXPECT_LE((adcs::ud_covariance<9>(f) - P).norm(), 1e-12 * P.norm()) << trial;
    EXPECT_NEAR(adcs::ud_covariance_entry<9>(f, 2, 7), adcs::ud_covariance<9>(f)(2, 7), 1e-15);
  }
  // Exact zero rows (the fusion's E P E) factor exactly, with D = 0 there.
  adcs::Mat<9, 9> P = random_psd<9>(gen, 9, 3.0);
  P.row(4).setZero();
  P.col(4).setZero();
  adcs::UdFactors<9> f;
  ASSERT_TRUE(adcs::ud_factorize<9>(P, f));
  EXPECT_EQ(f.D(4), 0.0);
  EXPECT_LE((adcs::ud_covariance<9>(f) - P).norm(), 1e-14 * P.norm());
  // Indefinite and non-finite: refused, output untouched.
  const adcs::UdFactors<9> before = f;
  adcs::Mat<9, 9> bad = P;
  bad(0, 0) = -1e-3;
  EXPECT_FALSE(adcs::ud_factorize<9>(bad, f));
  bad = P;
  bad(2, 3) = bad(3, 2) = NAN;
  EXPECT_FALSE(adcs::ud_factorize<9>(bad, f));
  EXPECT_EQ(f.U, before.U);
  EXPECT_EQ(f.D, before.D);
}

// Thornton's MWGS gives W diag(w) Wᵀ, Bierman's update the Kalman gain and covariance of the
// standard form, and Agee–Turner the rank-one sum, on random data.
TEST(UdFactors, MwgsBiermanAndAgeeTurnerMatchTheCovarianceForm) {
  std::mt19937_64 gen(4);
  std::normal_distribution<double> N01;
  for (int trial = 0; trial < 50; ++trial) {
    adcs::Mat<6, 10> W;
    Eigen::Matrix<double, 1, 10> w;
    for (int i = 0; i < 60; ++i) W.data()[i] = N01(gen);
    for (int i = 0; i < 10; ++i) w(i) = trial % 3 == 0 && i > 4 ? 0.0 : std::exp(3.0 * N01(gen));
    const adcs::Mat<6, 6> P = W * w.asDiagonal() * W.transpose();
    adcs::UdFactors<6> f;
    auto Wc = W;
    adcs::mwgs_ud<6, 10>(Wc, w, f);
    EXPECT_GE(f.D.minCoeff(), 0.0);
    EXPECT_LE((adcs::ud_covariance<6>(f) - P).norm(), 1e-12 * P.norm()) << trial;

    adcs::Vec<6> h = adcs::Vec<6>::Zero();
    const int first = trial % 6;
    for (int i = first; i < 6; ++i) h(i) = i == first ? 1.0 : (trial % 2 ? N01(gen) : 0.0);
    const double r = std::exp(N01(gen));
    const adcs::Vec<6> fv = f.U.transpose() * h;
    adcs::Vec<6> k;
    const double alpha = adcs::bierman_update<6>(f, fv, r, first, k);
    const double s = h.dot(P * h) + r;
    const adcs::Vec<6> K = P * h / s;
    const adcs::Mat<6, 6> P_plus = P - K * h.transpose() * P;
    EXPECT_NEAR(alpha, s, 1e-12 * s);
    EXPECT_LE((k - K).norm(), 1e-11 * K.norm() + 1e-300) << trial;
    EXPECT_LE((adcs::ud_covariance<6>(f) - P_plus).norm(), 1e-11 * P.norm()) << trial;
    EXPECT_GE(f.D.minCoeff(), 0.0);

    // Agee–Turner: P⁺ + c a aᵀ, with a sparse a too (leading zeros skip columns).
    adcs::Vec<6> a;
    for (int i = 0; i < 6; ++i) a(i) = (trial % 4 == 3 && i > 2) ? 0.0 : N01(gen);
    const double c = trial % 5 == 0 ? 0.0 : std::exp(2.0 * N01(gen));
    const adcs::Mat<6, 6> P_rank1 = P_plus + c * a * a.transpose();
    adcs::Vec<6> scratch = a;
    adcs::agee_turner_update<6>(f, c, scratch);
    EXPECT_LE((adcs::ud_covariance<6>(f) - P_rank1).norm(), 1e-11 * P_rank1.norm()) << trial;
    EXPECT_GE(f.D.minCoeff(), 0.0);
    EXPECT_TRUE(f.U.isUpperTriangular(0.0));
    EXPECT_TRUE(f.U.diagonal().isOnes(0.0));
  }
}

//! A random 8-state model with correlated R and S (the U-D filter decorrelates both), dense C.
adcs::EskfParams<8, 3, 2, 3> random_eskf_model(std::mt19937_64& gen) {
  std::normal_distribution<double> N01;
  adcs::EskfParams<8, 3, 2, 3> p;
  p.A_d = adcs::Mat<8, 8>::Identity();
  for (int i = 0; i < 8; ++i)
    for (int j = 0; j < 8; ++j)
      if ((i + 2 * j) % 3 == 0) p.A_d(i, j) += 0.05 * N01(gen);  // sparse, as A_d is
  for (int i = 0; i < 24; ++i) p.B_d.data()[i] = N01(gen);
  p.B_e.setZero();
  p.B_e(6, 0) = p.B_e(7, 1) = 1.0;
  for (int i = 0; i < 24; ++i) p.C_d.data()[i] = (i % 4 == 1) ? 0.0 : N01(gen);
  p.q << 1e-3, 2e-4;
  p.S = 1e-4 * random_psd<3>(gen, 3, 1.0);
  p.R = 1e-2 * random_psd<3>(gen, 3, 2.0);
  p.P0 = random_psd<8>(gen, 8, 2.0);
  p.period_s = 0.1;
  return p;
}

// EskfUd is Algorithm 1: the same estimate, covariance and θ as the Joseph-form Eskf, with
// correlated R and S, either θ policy, and a rejected step changes nothing.
TEST(EskfUd, EqualsTheJosephFormOnARandomModel) {
  std::mt19937_64 gen(8);
  std::normal_distribution<double> N01;
  for (int model = 0; model < 6; ++model) {
    adcs::EskfParams<8, 3, 2, 3> p = random_eskf_model(gen);
    p.theta_policy = model % 2 ? adcs::ThetaPolicy::fixed_initial : adcs::ThetaPolicy::trace_optimal;
    adcs::EskfUd<8, 3, 2, 3> ud(p);
    adcs::Eskf<8, 3, 2, 3> jo(p);
    ASSERT_EQ(ud.status(), Status::ok);
    for (int k = 0; k < 300; ++k) {
      adcs::EskfUd<8, 3, 2, 3>::Input in;
      for (int i = 0; i < 3; ++i) in.u(i) = N01(gen), in.y(i) = N01(gen);
      in.delta_f_nominal << 0.1 * N01(gen), 0.1 * N01(gen);
      adcs::EskfOutput<8> out_ud, out_jo;
      adcs::EskfDiagnostics diag;
      ASSERT_EQ(ud.step(in, out_ud, &diag), Status::ok);
      ASSERT_EQ(jo.step(in, out_jo), Status::ok);
      EXPECT_NEAR(ud.theta(), jo.theta(), 1e-12 * jo.theta());
      const adcs::Mat<8, 8> Pj = jo.covariance();
      EXPECT_LE((out_ud.x_hat - out_jo.x_hat).norm(), 1e-11 * (1.0 + out_jo.x_hat.norm())) << model << " " << k;
      EXPECT_LE((ud.covariance() - Pj).norm(), 1e-11 * Pj.norm()) << model << " " << k;
    }
    // Bad input: a status, and nothing changes.
    const adcs::Vec<8> x = ud.state();
    const adcs::Mat<8, 8> U = ud.factors().U;
    EXPECT_EQ(ud.predict(adcs::Vec<3>::Constant(NAN)), Status::non_finite_input);
    EXPECT_EQ(ud.update(adcs::Vec<3>(0.0, INFINITY, 0.0)), Status::non_finite_input);
    EXPECT_EQ(ud.state(), x);
    EXPECT_EQ(ud.factors().U, U);
    // An estimate beyond double's range after the update: out_of_range, nothing applied.
    adcs::Mat<8, 8> P_huge = ud.covariance();
    ASSERT_EQ(ud.set_estimate(adcs::Vec<8>::Constant(1.5e308), P_huge), Status::ok);
    const adcs::Vec<8> x_huge = ud.state();
    EXPECT_EQ(ud.update(adcs::Vec<3>::Constant(-1.7e308)), Status::out_of_range);
    EXPECT_EQ(ud.state(), x_huge);
  }
}

TEST(EskfUd, RefusesWhatHasNoUdFactorsAndKeepsItsEstimate) {
  std::mt19937_64 gen(9);
  adcs::EskfParams<8, 3, 2, 3> p = random_eskf_model(gen);
  adcs::EskfParams<8, 3, 2, 3> bad = p;
  bad.R(0, 0) = -1.0;
  EXPECT_EQ((adcs::EskfUd<8, 3, 2, 3>(bad).status()), Status::invalid_parameter);
  bad = p;
  bad.P0(1, 2) = bad.P0(2, 1) = 10.0;  // not PSD
  EXPECT_EQ((adcs::EskfUd<8, 3, 2, 3>(bad).status()), Status::invalid_parameter);
  EXPECT_EQ((adcs::EskfUd<8, 3, 2, 3, 4>(p).status()), Status::invalid_parameter);  // 2 + 3 noise columns > 4
  adcs::EskfUd<8, 3, 2, 3> f(p);
  ASSERT_EQ(f.predict(adcs::Vec<3>::Zero()), Status::ok);
  const adcs::Vec<8> x = f.state();
  const adcs::Mat<8, 8> P = f.covariance();
  adcs::Mat<8, 8> indefinite = P;
  indefinite(3, 3) = -indefinite(3, 3);
  EXPECT_EQ(f.set_estimate(x, indefinite), Status::invalid_parameter);
  adcs::Mat<8, 8> asymmetric = P;
  asymmetric(0, 5) += 1e-3 * P.norm();
  EXPECT_EQ(f.set_estimate(x, asymmetric), Status::invalid_parameter);
  EXPECT_EQ(f.replace_substate<2>({1, 3}, adcs::Vec<2>::Zero(), (adcs::Mat<2, 2>() << 1, 2, 2, 1).finished()),
            Status::invalid_parameter);
  EXPECT_EQ(f.replace_substate<2>({1, 1}, adcs::Vec<2>::Zero(), adcs::Mat<2, 2>::Identity()), Status::invalid_parameter);
  EXPECT_EQ(f.replace_substate<2>({1, 3}, adcs::Vec<2>::Constant(NAN), adcs::Mat<2, 2>::Identity()),
            Status::non_finite_input);
  EXPECT_EQ(f.state(), x);
  EXPECT_EQ(f.covariance(), P);
  // replace_substate is seed 004 eqs. (40)-(41): rows and columns zeroed, the block set.
  const adcs::Mat<2, 2> Po = (adcs::Mat<2, 2>() << 2e-3, 1e-4, 1e-4, 5e-4).finished();
  ASSERT_EQ(f.replace_substate<2>({6, 2}, adcs::Vec<2>(1.0, 2.0), Po), Status::ok);
  adcs::Mat<8, 8> expected = P;
  for (int i : {6, 2}) expected.row(i).setZero(), expected.col(i).setZero();
  expected(6, 6) = Po(0, 0), expected(2, 2) = Po(1, 1), expected(6, 2) = expected(2, 6) = Po(0, 1);
  EXPECT_LE((f.covariance() - expected).norm(), 1e-14 * expected.norm());
  EXPECT_EQ(f.state()(6), 1.0);
  EXPECT_EQ(f.state()(2), 2.0);
}

// The factors of a step are written into the filter's spare buffer (issue 20), so a filter holds
// one candidate at a time: accepting an older one changes nothing, the last one is accepted once,
// and the result is the one-phase step's, bit for bit.
TEST(EskfUd, OnlyItsLastCandidateIsAcceptedAndOnlyOnce) {
  std::mt19937_64 gen(10);
  std::normal_distribution<double> N01;
  using F = adcs::EskfUd<8, 3, 2, 3>;
  F f(random_eskf_model(gen));
  ASSERT_EQ(f.status(), Status::ok);
  ASSERT_EQ(f.predict(adcs::Vec<3>(0.1, -0.2, 0.3)), Status::ok);
  const F reference_start = f;
  const adcs::Vec<3> Y1(N01(gen), N01(gen), N01(gen)), Y2(N01(gen), N01(gen), N01(gen));
  F::Candidate c1, c2;
  ASSERT_EQ(f.update_candidate(Y1, c1), Status::ok);
  ASSERT_EQ(f.update_candidate(Y2, c2), Status::ok);
  const adcs::Vec<8> x0 = reference_start.state();
  const adcs::UdFactors<8> f0 = reference_start.factors();
  f.accept(c1);  // replaced by c2: nothing changes
  EXPECT_EQ(f.state(), x0);
  EXPECT_EQ(f.factors().U, f0.U);
  EXPECT_EQ(f.factors().D, f0.D);
  f.accept(c2);
  F reference = reference_start;
  ASSERT_EQ(reference.update(Y2), Status::ok);
  EXPECT_EQ(f.state(), reference.state());
  EXPECT_EQ(f.factors().U, reference.factors().U);
  EXPECT_EQ(f.factors().D, reference.factors().D);
  f.accept(c2);  // accepted already: nothing changes (the spare now holds the old factors)
  EXPECT_EQ(f.factors().U, reference.factors().U);
  EXPECT_EQ(f.factors().D, reference.factors().D);
  // A fusion in between overwrites the spare: the candidate made before it is not accepted.
  F::Candidate c3;
  ASSERT_EQ(f.update_candidate(Y1, c3), Status::ok);
  const adcs::Mat<2, 2> Po = (adcs::Mat<2, 2>() << 2e-3, 1e-4, 1e-4, 5e-4).finished();
  ASSERT_EQ(f.replace_substate<2>({6, 2}, adcs::Vec<2>(1.0, 2.0), Po), Status::ok);
  const adcs::Vec<8> x_fused = f.state();
  const adcs::Mat<8, 8> P_fused = f.covariance();
  f.accept(c3);
  EXPECT_EQ(f.state(), x_fused);
  EXPECT_EQ(f.covariance(), P_fused);
  // reset() too.
  F::Candidate c4;
  ASSERT_EQ(f.update_candidate(Y1, c4), Status::ok);
  f.reset();
  const adcs::Mat<8, 8> P_reset = f.covariance();
  f.accept(c4);
  EXPECT_EQ(f.covariance(), P_reset);
}

// Bierman's update out of place (EskfUd's first output of a sample: no copy of the factors) is the
// in-place update of a copy, bit for bit, whatever the destination held before, `first` > 0 too.
TEST(UdFactors, OutOfPlaceBiermanIsTheInPlaceUpdateOfACopyBitForBit) {
  std::mt19937_64 gen(11);
  std::normal_distribution<double> N01;
  for (int trial = 0; trial < 30; ++trial) {
    adcs::Mat<7, 9> W;
    for (int i = 0; i < 63; ++i) W.data()[i] = N01(gen);
    Eigen::Matrix<double, 1, 9> w;
    for (int i = 0; i < 9; ++i) w(i) = std::exp(2.0 * N01(gen));
    adcs::UdFactors<7> in, other;
    adcs::Mat<7, 9> W2 = W;
    adcs::mwgs_ud<7, 9>(W, w, in);
    W2.row(trial % 7) *= 3.0;
    adcs::mwgs_ud<7, 9>(W2, w, other);  // a destination that held other factors
    const int first = trial % 7;
    adcs::Vec<7> h = adcs::Vec<7>::Zero();
    for (int i = first; i < 7; ++i) h(i) = N01(gen);
    const adcs::Vec<7> fv = in.U.transpose() * h;
    const double r = std::exp(N01(gen));
    adcs::UdFactors<7> copy = in;
    adcs::Vec<7> k_in_place, k_out;
    const double a1 = adcs::bierman_update<7>(copy, fv, r, first, k_in_place);
    const double a2 = adcs::bierman_update<7>(in, other, fv, r, first, k_out);
    EXPECT_EQ(a1, a2);
    EXPECT_EQ(k_in_place, k_out);
    EXPECT_EQ(copy.D, other.D) << trial;
    EXPECT_EQ(copy.U, other.U) << trial;  // above the diagonal written, the unit pattern kept
  }
}

// SparseRows::add_product: out += X v from X's nonzeros, each row's sum formed over its nonzeros in
// column order and then added (EskfUd's B_d u and B_e Ĝ); equal to Eigen's product to rounding.
TEST(SparseRows, AddProductSumsEachRowInColumnOrderThenAdds) {
  std::mt19937_64 gen(12);
  std::normal_distribution<double> N01;
  for (int trial = 0; trial < 20; ++trial) {
    adcs::Mat<18, 9> X;
    for (int i = 0; i < 162; ++i) X.data()[i] = (i + trial) % 3 == 0 ? N01(gen) : 0.0;
    adcs::Vec<9> v;
    adcs::Vec<18> out, expected, eigen;
    for (int i = 0; i < 9; ++i) v(i) = N01(gen);
    for (int i = 0; i < 18; ++i) out(i) = N01(gen);
    expected = eigen = out;
    adcs::SparseRows<18, 9> nz;
    nz.assign(X);
    nz.add_product(v, out);
    for (int i = 0; i < 18; ++i) {
      double s = 0.0;
      for (int j = 0; j < 9; ++j)
        if (X(i, j) != 0.0) s += X(i, j) * v(j);
      expected(i) += s;
    }
    eigen.noalias() += X * v;
    EXPECT_EQ(out, expected) << trial;
    EXPECT_LE((out - eigen).norm(), 1e-15 * (eigen.norm() + (X.cwiseAbs() * v.cwiseAbs()).norm())) << trial;
  }
}

// The drag-free filter in U-D form against the Joseph form it replaced and against the same
// recursion evaluated in quadruple precision (__float128, 113-bit significand), on the scenario's
// parameters (spec P_0 = 0.01 I) with seed 004's measurement model. The first updates shrink P by
// ~13 orders: the Joseph form loses as many digits there (and needs its eigen projection), the
// U-D form does not. Measured (max over each 10 s window, of each state's scale): U-D vs exact
// 1e-9 ... 1.6e-8 throughout; Joseph vs exact 0.18, 8.6e-4, 3.2e-5, 2.6e-7, then ~1e-8 like U-D
// from 40 s on (long double, for comparison, is 1.9e-4 off in the first 10 s).
#if defined(__SIZEOF_FLOAT128__)
}  // namespace
namespace Eigen {
template <>
struct NumTraits<__float128> : GenericNumTraits<__float128> {
  using Real = __float128;
  using NonInteger = __float128;
  using Nested = __float128;
  enum { IsComplex = 0, IsInteger = 0, IsSigned = 1, RequireInitialization = 0, ReadCost = 1, AddCost = 3, MulCost = 3 };
};
}  // namespace Eigen
namespace ADCS_UNITY_ID {
using namespace adcs::test::drag_free;

//! √r in quadruple precision: two Newton steps from the double root (no libquadmath needed).
__float128 sqrt_q(__float128 r) {
  __float128 t = std::sqrt(static_cast<double>(r));
  for (int i = 0; i < 2; ++i) t = (t + r / t) / 2;
  return t;
}

//! a b in quadruple precision by plain loops: Eigen's product kernels instantiated for a custom
//! scalar cost ~20 clang+ASan CPU-s of this file's compile time, for a reference that runs once.
template <int R, int K, int C>
Eigen::Matrix<__float128, R, C> mul_q(const Eigen::Matrix<__float128, R, K>& a, const Eigen::Matrix<__float128, K, C>& b) {
  Eigen::Matrix<__float128, R, C> o;
  for (int i = 0; i < R; ++i)
    for (int j = 0; j < C; ++j) {
      __float128 s = 0;
      for (int k = 0; k < K; ++k) s += a(i, k) * b(k, j);
      o(i, j) = s;
    }
  return o;
}

TEST(DragFreeEskf, UdFormTracksTheExactRecursionWhereTheJosephFormLosesDigits) {
  using Qd = __float128;
  using MQ = Eigen::Matrix<Qd, 27, 27>;
  const adcs::DragFreeParams pl;
  const adcs::DragFreeDiscrete d = discrete();
  const adcs::DragFreeEskf::Params e = eskf_params(d);
  adcs::DragFreeEskf ud(e);
  adcs::Eskf<27, 9, 9, 9> jo(e);  // the Joseph form (the two-block Joseph filter equals it, test above)
  const MQ A = e.A_d.cast<Qd>();
  const Eigen::Matrix<Qd, 27, 9> Bd = e.B_d.cast<Qd>();
  const Eigen::Matrix<Qd, 9, 27> C = e.C_d.cast<Qd>();
  const Eigen::Matrix<Qd, 27, 9> Be = e.B_e.cast<Qd>();
  Eigen::Matrix<Qd, 9, 27> qBet = Be.transpose();
  for (int i = 0; i < 9; ++i) qBet.row(i) *= Qd(36) * Qd(e.q(i));
  const MQ Q1 = mul_q<27, 9, 27>(Be, qBet);
  const Eigen::Matrix<Qd, 9, 27> Bdt = Bd.transpose();
  const MQ Q2 = mul_q<27, 9, 27>(Bd, mul_q<9, 9, 27>(e.S.cast<Qd>(), Bdt));
  const MQ At = A.transpose();
  const Eigen::Matrix<Qd, 27, 9> Ct = C.transpose();
  const Eigen::Matrix<Qd, 9, 9> R = e.R.cast<Qd>();
  MQ P = e.P0.cast<Qd>();
  Eigen::Matrix<Qd, 27, 1> x = Eigen::Matrix<Qd, 27, 1>::Zero();
  std::mt19937_64 gen(21);
  std::normal_distribution<double> N01;
  const adcs::DragFreeNoise n = adcs::drag_free_noise(pl);
  adcs::Vec<27> X = adcs::Vec<27>::Zero();
  X.segment<3>(Ix::F_Dsc).setConstant(-12.8e-3);
  X.segment<3>(Ix::T_Dsc).setConstant(1e-5);
  constexpr int kWindows = 5, kWindow = 100;  // 10 s windows
  std::vector<adcs::Vec<27>> x_ud, x_jo, x_q;
  for (int k = 0; k < kWindows * kWindow; ++k) {
    adcs::Vec<9> u;
    for (int i = 0; i < 9; ++i) u(i) = 1e-4 * N01(gen);
    if (k > 0) {
      ASSERT_EQ(ud.predict(u), Status::ok);
      ASSERT_EQ(jo.predict(u), Status::ok);
      const MQ APA = mul_q<27, 27, 27>(mul_q<27, 27, 27>(A, P), At);
      const Qd th = sqrt_q(Q1.trace() / APA.trace());
      P = (1 + th) * APA + (1 + 1 / th) * Q1 + Q2;  // seed 004 eq. (9)
      const Eigen::Matrix<Qd, 9, 1> uq = u.cast<Qd>();
      x = mul_q<27, 27, 1>(A, x) + mul_q<27, 9, 1>(Bd, uq);
      X = (d.A_d * X + d.B_d * u).eval();
    }
    adcs::Vec<9> Y = d.C_d * X;
    for (int i = 0; i < 9; ++i) Y(i) += n.sigma_pos * N01(gen);
    ASSERT_EQ(ud.update(Y), Status::ok);
    ASSERT_EQ(jo.update(Y), Status::ok);
    // K = P Cᵀ S_y⁻¹ by Gauss elimination on the SPD S_y (no pivoting needed), Joseph form for P.
    Eigen::Matrix<Qd, 9, 27> Kt = mul_q<9, 27, 27>(C, P);  // S_y Kᵀ = C P
    Eigen::Matrix<Qd, 9, 9> Sy = mul_q<9, 27, 9>(Kt, Ct) + R;
    for (int c = 0; c < 9; ++c)
      for (int r = c + 1; r < 9; ++r) {
        const Qd m = Sy(r, c) / Sy(c, c);
        Sy.row(r) -= m * Sy.row(c);
        Kt.row(r) -= m * Kt.row(c);
      }
    for (int r = 8; r >= 0; --r) {
      for (int c = r + 1; c < 9; ++c) Kt.row(r) -= Sy(r, c) * Kt.row(c);
      Kt.row(r) /= Sy(r, r);
    }
    const Eigen::Matrix<Qd, 27, 9> K = Kt.transpose();
    const MQ IKC = MQ::Identity() - mul_q<27, 9, 27>(K, C);
    const MQ IKCt = IKC.transpose();
    P = mul_q<27, 27, 27>(mul_q<27, 27, 27>(IKC, P), IKCt) + mul_q<27, 9, 27>(K, mul_q<9, 9, 27>(R, Kt));
    const Eigen::Matrix<Qd, 9, 1> innovation = Y.cast<Qd>() - mul_q<9, 27, 1>(C, x);
    x += mul_q<27, 9, 1>(K, innovation);
    x_ud.push_back(ud.state());
    x_jo.push_back(jo.state());
    adcs::Vec<27> xd;
    for (int i = 0; i < 27; ++i) xd(i) = static_cast<double>(x(i));
    x_q.push_back(xd);
  }
  adcs::Vec<27> scale = adcs::Vec<27>::Zero();
  for (const auto& v : x_q) scale = scale.cwiseMax(v.cwiseAbs());
  auto worst = [&](const std::vector<adcs::Vec<27>>& a, const std::vector<adcs::Vec<27>>& b, int w) {
    double m = 0.0;
    for (int k = w * kWindow; k < (w + 1) * kWindow; ++k) m = std::max(m, (a[k] - b[k]).cwiseAbs().cwiseQuotient(scale).maxCoeff());
    return m;
  };
  for (int w = 0; w < kWindows; ++w) {
    const double ud_q = worst(x_ud, x_q, w), jo_q = worst(x_jo, x_q, w), ud_jo = worst(x_ud, x_jo, w);
    std::printf("[%2d, %2d) s: U-D vs exact %.2e, Joseph vs exact %.2e, U-D vs Joseph %.2e\n", 10 * w, 10 * w + 10,
                ud_q, jo_q, ud_jo);
    EXPECT_LT(ud_q, 1e-7) << w;
    if (w == 0) EXPECT_GT(jo_q, 1e3 * ud_q);  // the Joseph form's lost digits
    if (w >= 4) EXPECT_LT(ud_jo, 1e-7) << w;  // the two agree once the Joseph form has recovered
  }
  EXPECT_EQ(ud.psd_projections(), 0);
}
#endif

// Robustness (issue 20): covariances with condition numbers up to 1e14, near-singular measurement
// noise and saturated accelerometer samples in a row (fused every sample). The U-D filter stays
// finite with D >= 0 (PSD by construction) on every step; the Joseph form (Eskf<27>, without the
// fusion) runs the same data and its projections are counted: it needs them here.
TEST(DragFreeEskf, StaysFiniteAndPsdOnIllConditionedCovariancesAndNoise) {
  const adcs::DragFreeParams pl;
  const adcs::DragFreeDiscrete d = discrete();
  std::mt19937_64 gen(31);
  std::normal_distribution<double> N01;
  long joseph_projections = 0;
  for (const double decades : {6.0, 10.0, 14.0}) {
    for (const double r_scale : {1.0, 1e-12}) {  // R = σ² I, and near-singular σ² 1e-12 of it
      adcs::DragFreeEskf::Params e = eskf_params(d);
      e.R *= r_scale;
      adcs::DragFreeEskf ud(e);
      adcs::Eskf<27, 9, 9, 9> jo(e);
      ASSERT_EQ(ud.status(), Status::ok);
      std::vector<adcs::SaturatedEsf> a2;
      for (int j = 0; j < 3; ++j) a2.emplace_back(esf_params(j));
      // A start with a condition number 10^decades in each block (random eigenvectors).
      adcs::Mat<27, 27> P0 = adcs::Mat<27, 27>::Zero();
      const adcs::Mat<18, 18> P1 = 1e-2 * random_psd<18>(gen, 18, decades);
      const adcs::Mat<9, 9> P2 = 1e-2 * random_psd<9>(gen, 9, decades);
      const adcs::FilterPartition<18, 6> part = adcs::drag_free_attitude_partition_ud();
      for (int i = 0; i < 18; ++i)
        for (int j = 0; j < 18; ++j) P0(part.states[i], part.states[j]) = P1(i, j);
      for (int i = 0; i < 9; ++i)
        for (int j = 0; j < 9; ++j) P0(Ix::r + i, Ix::r + j) = P2(i, j);
      ASSERT_EQ(ud.set_estimate(adcs::Vec<27>::Zero(), P0), Status::ok) << decades;
      ASSERT_EQ(jo.set_estimate(adcs::Vec<27>::Zero(), P0), Status::ok);
      for (int k = 0; k < 400; ++k) {
        adcs::Vec<9> u, Y;
        for (int i = 0; i < 9; ++i) u(i) = 1e-4 * N01(gen), Y(i) = 1e-8 * N01(gen);
        ASSERT_EQ(ud.predict(u), Status::ok) << decades << " " << k;
        (void)jo.predict(u);
        for (int j = 0; j < 3; ++j) ASSERT_EQ(a2[j].predict(u(3 + j)), Status::ok);
        ASSERT_EQ(ud.update(Y), Status::ok) << decades << " " << k;
        (void)jo.update(Y);
        for (int j = 0; j < 3; ++j) {  // saturated in a row: every reading at the range's upper bound
          ASSERT_TRUE(adcs::usable(a2[j].update(pl.accel_max, u(3 + j))));
          ASSERT_EQ(adcs::fuse_axis(ud, a2[j], j), Status::ok) << decades << " " << k;
        }
        ASSERT_TRUE(adcs::all_finite(ud.state()));
        ASSERT_GE(ud.block1().factors().D.minCoeff(), 0.0);
        ASSERT_GE(ud.block2().factors().D.minCoeff(), 0.0);
        ASSERT_TRUE(adcs::all_finite(ud.block1().factors().U) && adcs::all_finite(ud.block2().factors().U));
      }
      const adcs::Mat<27, 27> P = ud.covariance();
      const Eigen::SelfAdjointEigenSolver<adcs::Mat<27, 27>> es(P);
      EXPECT_GE(es.eigenvalues().minCoeff(), -1e-13 * es.eigenvalues().maxCoeff()) << decades;
      joseph_projections += jo.psd_projections();
    }
  }
  std::printf("Joseph-form projections on the same data: %ld\n", joseph_projections);
  EXPECT_GT(joseph_projections, 0);
}
}  // namespace

using namespace ADCS_UNITY_ID;  // as an anonymous namespace would (CMakeLists.txt, adcs_unity)
