// seed 004 model (spec §B.2-§B.3) — sanity checks B.11: 2 (per-axis model vs the 27-state model,
// and the 27-state propagation against a direct simulation) and 3 (observability, PBH on scaled
// states). One of three files of the drag-free estimator tests, split so that two cores share them.
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <Eigen/SVD>
#include <cmath>
#include <complex>

#include "drag_free_test_model.hpp"

namespace ADCS_UNITY_ID {
using namespace adcs::test::drag_free;  // discrete(), Status, Vec3, Mat3, Ix

TEST(DragFreeModel, PerAxisModelIsThe27StateModelRestrictedB11_2) {
  adcs::DragFreeParams p;
  p.K_trans = p.K_trans.diagonal().asDiagonal();  // zero off-diagonals: the models must agree
  const adcs::DragFreeDiscrete d = discrete(p);
  for (int j = 0; j < 3; ++j) {
    adcs::DragFreeAxisModel m;
    ASSERT_EQ(adcs::drag_free_axis_model(p, j, m), Status::ok);
    const int ix[3] = {Ix::r + j, Ix::r_dot + j, Ix::F_Dsc + j};
    for (int a = 0; a < 3; ++a) {
      for (int b = 0; b < 3; ++b)  // two expm evaluations of different size: ~10 ulp apart
        EXPECT_NEAR(m.A_d(a, b), d.A_d(ix[a], ix[b]), 2e-14 * (1 + std::abs(m.A_d(a, b)))) << j;
      EXPECT_NEAR(m.B_d(a), d.B_d(ix[a], 3 + j), 1e-18) << j;
    }
    // The accelerometer row is −r̈: y = C X + D u matches −(A X + B u) row of ṙ (continuous).
    EXPECT_NEAR(m.C(0), p.K_trans(j, j) / p.m_tm, 1e-20);
    EXPECT_NEAR(m.C(2), 1.0 / p.m_sc, 1e-18);
  }
  // The 27-state propagation equals a direct simulation of (1)-(3) with ZOH f (RK4, 1000 substeps).
  const adcs::DragFreeContinuous c = adcs::drag_free_continuous(p);
  adcs::Vec<27> x0 = adcs::Vec<27>::Zero();
  x0.segment<3>(Ix::phi_sc) << 1e-6, -2e-6, 3e-6;
  x0.segment<3>(Ix::r) << 1e-7, 2e-7, -1e-7;
  x0.segment<3>(Ix::T_Dsc) << -12.8e-3, -5e-3, -20e-3;
  x0.segment<3>(Ix::F_Dsc) << -12.8e-3, -5e-3, -20e-3;
  x0.segment<3>(Ix::phi_rel) << 1e-7, 0, -1e-7;
  adcs::Vec<9> u;
  u << 1e-3, -2e-3, 3e-3, 1e-2, -1e-2, 2e-2, 1e-9, 0, -1e-9;
  adcs::Vec<27> x = x0;
  const double hh = 0.1 / 1000;
  auto f = [&](const adcs::Vec<27>& s) { return adcs::Vec<27>(c.A * s + c.B * u); };
  for (int i = 0; i < 1000; ++i) {
    const adcs::Vec<27> k1 = f(x), k2 = f(x + hh / 2 * k1), k3 = f(x + hh / 2 * k2), k4 = f(x + hh * k3);
    x += hh / 6 * (k1 + 2 * k2 + 2 * k3 + k4);
  }
  const adcs::Vec<27> xd = d.A_d * x0 + d.B_d * u;
  for (int i = 0; i < 27; ++i) EXPECT_NEAR(xd(i), x(i), 1e-10 * (std::abs(x(i)) + 1e-12)) << i;
}

TEST(DragFreeModel, ExtendedModelIsObservableB11_3) {
  // PBH: rank [λI − A_d; C_d] = 27 for every eigenvalue λ, on scaled states (magnitudes span
  // ~1e-12..1): T = diag(typical sizes), A_s = T⁻¹ A_d T, C_s = C_d T.
  const adcs::DragFreeDiscrete d = discrete();
  adcs::Vec<27> scale;
  for (int b = 0; b < 9; ++b) scale.segment<3>(3 * b).setConstant(b % 3 == 2 ? 1e-2 : (b % 3 == 1 ? 1e-6 : 1e-5));
  const adcs::Mat<27, 27> A = scale.cwiseInverse().asDiagonal() * d.A_d * scale.asDiagonal();
  const adcs::Mat<9, 27> C = d.C_d * scale.asDiagonal();
  const Eigen::EigenSolver<adcs::Mat<27, 27>> es(A);
  for (int i = 0; i < 27; ++i) {
    const std::complex<double> lam = es.eigenvalues()(i);
    Eigen::Matrix<std::complex<double>, 36, 27> M;
    M.topRows<27>() = lam * Eigen::Matrix<std::complex<double>, 27, 27>::Identity() - A.cast<std::complex<double>>();
    M.bottomRows<9>() = C.cast<std::complex<double>>();
    const Eigen::JacobiSVD<Eigen::Matrix<std::complex<double>, 36, 27>> svd(M);
    const double smin = svd.singularValues()(26), smax = svd.singularValues()(0);
    EXPECT_GT(smin / smax, 1e-13) << "eigenvalue " << lam;
  }
}
}  // namespace

using namespace ADCS_UNITY_ID;  // as an anonymous namespace would (CMakeLists.txt, adcs_unity)
