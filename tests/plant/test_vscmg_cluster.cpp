// VSCMG cluster (seed 001 eqs. (1)-(3)) and its truth plants TP-FULL / TP-CTRL: spec A.7
// checks S4, S5, S6 on the right-hand side (directional derivatives along xdot), the D1 data of
// spec A.2.3, an RK4 momentum-drift run, and TP-CTRL vs TP-FULL consistency.
#include <gtest/gtest.h>

#include <algorithm>
#include <limits>
#include <random>

#include "adcs/plant/vscmg_cluster.hpp"
#include "adcs/plant/vscmg_configurations.hpp"
#include "directional_derivative.hpp"

namespace ADCS_UNITY_ID {
using Full = adcs::VscmgFullPlant<4, 3>;
using Ctrl = adcs::VscmgCtrlPlant<4, 3>;
using Geometry = adcs::VscmgGeometry<4, 3>;
using adcs::Vec;
using adcs::Vec3;

Full::State random_state(std::mt19937_64& rng, const Full& plant) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const Vec3 sigma(0.6 * u(rng), 0.6 * u(rng), 0.6 * u(rng));
  const Vec3 w(0.05 * u(rng), 0.05 * u(rng), 0.05 * u(rng));
  Vec<4> gamma;
  for (int i = 0; i < 4; ++i) gamma(i) = 1.5 * u(rng);
  Vec<3> Om;
  for (int j = 0; j < 3; ++j) Om(j) = 100.0 * u(rng);
  return plant.initial_state(sigma, w, gamma, Om);
}

Full::Input random_input(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  Full::Input in;
  for (int i = 0; i < 4; ++i) in(i) = 0.2 * u(rng);      // [rad/s]
  for (int j = 4; j < 7; ++j) in(j) = 5.0 * u(rng);      // [rad/s^2]
  return in;
}


TEST(VscmgCluster, S5NominalAxesOrthonormalAndRotorBookkeeping) {
  const Geometry g = adcs::pyramid_4cmg_3rw_nominal();
  for (int i = 0; i < 4; ++i) {
    const Vec3 gi = g.A_cg.col(i), s0 = g.A_cs0.col(i), t0 = g.A_ct0.col(i);
    EXPECT_LT((gi.cross(s0) - t0).norm(), 1e-15);
    EXPECT_NEAR(gi.norm(), 1.0, 1e-15);
    EXPECT_NEAR(s0.norm(), 1.0, 1e-15);
    EXPECT_NEAR(t0.norm(), 1.0, 1e-15);
    EXPECT_NEAR(gi.dot(s0), 0.0, 1e-15);
    EXPECT_NEAR(gi.dot(t0), 0.0, 1e-15);
    EXPECT_NEAR(s0.dot(t0), 0.0, 1e-15);
  }
  EXPECT_EQ((g.A_ws - adcs::Mat3::Identity()).norm(), 0.0);
  // d s/d gamma = t, d t/d gamma = -s (true, deviated axes too: eq. (3) is linear in s0, t0).
  const Geometry tr = adcs::vscmg_params_A_REF().truth;
  const Vec<4> gamma(0.3, -1.1, 2.0, 0.7);
  const double h = 1e-6;
  for (int i = 0; i < 4; ++i) {
    Vec<4> gp = gamma, gm = gamma;
    gp(i) += h;
    gm(i) -= h;
    const Vec3 ds = (tr.A_cs(gp).col(i) - tr.A_cs(gm).col(i)) / (2 * h);
    const Vec3 dt = (tr.A_ct(gp).col(i) - tr.A_ct(gm).col(i)) / (2 * h);
    EXPECT_LT((ds - tr.A_ct(gamma).col(i)).norm(), 1e-9);
    EXPECT_LT((dt + tr.A_cs(gamma).col(i)).norm(), 1e-9);
  }
  // d/dt [h_cw s_i(gamma_i(t))] = h_cw t_i gamma_dot_i along gamma(t) = gamma + gamma_dot t.
  const Vec<4> gdot(0.1, -0.25, 0.05, 0.3);
  const adcs::Mat<3, 4> lhs =
      (tr.A_cs(Vec<4>(gamma + h * gdot)) - tr.A_cs(Vec<4>(gamma - h * gdot))) * tr.h_cw.asDiagonal() /
      (2 * h);
  const adcs::Mat<3, 4> rhs = tr.A_ct(gamma) * tr.h_cw.cwiseProduct(gdot).asDiagonal();
  EXPECT_LT((lhs - rhs).norm(), 1e-8);
}

TEST(VscmgCluster, D1ValuesAndAREFInitialMomentum) {
  const adcs::VscmgDeviation<4, 3> d = adcs::deviation_set_D1();
  const double cG[4] = {0.00462, 0.00742, 0.00626, 0.00794};
  const double wG[3] = {0.00206, 0.00042, 0.00253};
  for (int i = 0; i < 4; ++i) EXPECT_NEAR(d.theta_cG(i).squaredNorm(), cG[i], 0.5e-5) << i;
  for (int j = 0; j < 3; ++j) EXPECT_NEAR(d.theta_wG(j).squaredNorm(), wG[j], 0.5e-5) << j;

  const adcs::VscmgParams<4, 3> p = adcs::vscmg_params_A_REF();
  const Full plant(p);
  ASSERT_EQ(plant.status(), adcs::Status::ok);
  const Full::State x0 =
      plant.initial_state(Vec3::Zero(), Vec3::Zero(), Vec<4>::Zero(), Vec<3>::Zero());
  const Vec3 H_true = plant.momentum_N(x0);
  EXPECT_NEAR(H_true(0), 0.026, 0.5e-3);
  EXPECT_NEAR(H_true(1), -0.334, 0.5e-3);
  EXPECT_NEAR(H_true(2), -0.005, 0.5e-3);
  EXPECT_LT((H_true - Vec3(10.0 * d.dA_cs0.rowwise().sum())).norm(), 1e-14);
  // Nominal momentum H_I^n at A-REF is zero (zero-momentum pyramid).
  EXPECT_LT(p.nominal.internal_momentum(Vec<4>::Zero(), Vec<4>::Zero(), Vec<3>::Zero()).norm(),
            1e-15);

  const adcs::Mat3 J_n = p.nominal.J_tr(Vec<4>::Zero());
  EXPECT_NEAR(J_n(0, 0), 120.0613, 0.5e-4);
  EXPECT_NEAR(J_n(1, 1), 100.0613, 0.5e-4);
  EXPECT_NEAR(J_n(2, 2), 80.0493, 0.5e-4);
  EXPECT_LT((J_n - adcs::Mat3(J_n.diagonal().asDiagonal())).norm(), 1e-15);
  const Ctrl ctrl(p);
  EXPECT_EQ(ctrl.status(), adcs::Status::ok);
  EXPECT_EQ((ctrl.J_n() - J_n).norm(), 0.0);
}

TEST(VscmgCluster, ModeBRigidMountingKeepsEachTriadOrthonormal) {
  // Spec A.2.3 Mode B: rotated triads stay unit and orthogonal with g × s0 = t0; the deviation
  // is first-order φ × v, so |Δ| <= |φ| |v|.
  const Geometry nom = adcs::pyramid_4cmg_3rw_nominal();
  adcs::Mat<3, 4> phi_c;
  adcs::Mat<3, 3> phi_w;
  phi_c << 0.05, -0.03, 0.01, 0.0, 0.02, 0.04, -0.05, 0.03, -0.01, 0.0, 0.05, -0.02;
  phi_w << 0.01, -0.05, 0.03, 0.04, 0.0, -0.02, -0.03, 0.02, 0.05;
  const auto dev = adcs::rigid_mounting_deviation(nom, phi_c, phi_w);
  const Geometry g = adcs::apply_deviation(nom, dev);
  for (int i = 0; i < 4; ++i) {
    EXPECT_NEAR(g.A_cg.col(i).norm(), 1.0, 1e-15);
    EXPECT_NEAR(g.A_cs0.col(i).norm(), 1.0, 1e-15);
    EXPECT_NEAR(g.A_cg.col(i).dot(g.A_cs0.col(i)), 0.0, 1e-15);
    EXPECT_LT((g.A_cg.col(i).cross(g.A_cs0.col(i)) - g.A_ct0.col(i)).norm(), 1e-15);
    EXPECT_LE(dev.theta_cG(i).head<3>().norm(), phi_c.col(i).norm() + 1e-15);
    EXPECT_LT((dev.dA_cs0.col(i) - phi_c.col(i).cross(nom.A_cs0.col(i))).norm(),
              phi_c.col(i).squaredNorm());
  }
  for (int j = 0; j < 3; ++j) {
    EXPECT_NEAR(g.A_ws.col(j).norm(), 1.0, 1e-15);
    EXPECT_GT(dev.theta_wG(j).norm(), 0.0);
  }
  const auto none = adcs::rigid_mounting_deviation(nom, adcs::Mat<3, 4>::Zero().eval(),
                                                   adcs::Mat<3, 3>::Zero().eval());
  EXPECT_EQ(none.dA_cs0.norm() + none.dA_ct0.norm() + none.dA_cg.norm() + none.dA_ws.norm(), 0.0);
}

TEST(VscmgCluster, S4MomentumConservedAndTorqueBalanceOnRhs) {
  Full plant(adcs::vscmg_params_A_REF());
  std::mt19937_64 rng(17);
  for (int k = 0; k < 30; ++k) {
    const Full::State x = random_state(rng, plant);
    const Full::Input u = random_input(rng);
    const auto HN = [&](const Full::State& y) { return plant.momentum_N(y); };
    const double scale = 1.0 + plant.momentum_N(x).norm();

    plant.set_external_torque(Vec3::Zero());
    Full::State xdot;
    plant.derivative(0.0, x, u, xdot);
    EXPECT_LT(directional(HN, x, xdot, 1e-4).norm(), 1e-8 * scale);

    const Vec3 tau(1e-3, -2e-3, 5e-4);
    plant.set_external_torque(tau);
    plant.derivative(0.0, x, u, xdot);
    const Vec3 expected = adcs::mrp_to_dcm(Full::sigma_BN(x)).transpose() * tau;
    EXPECT_LT((directional(HN, x, xdot, 1e-4) - expected).norm(), 1e-8 * scale);
  }
}

TEST(VscmgCluster, S4Rk4MomentumDriftWithRandomHeldInputs) {
  const Full plant(adcs::vscmg_params_A_REF());
  std::mt19937_64 rng(23);
  Full::State x = plant.initial_state(Vec3(0.1, -0.2, 0.3), Vec3(0.02, -0.01, 0.03),
                                      Vec<4>(0.1, -0.2, 0.0, 0.3), Vec<3>(50.0, -20.0, 10.0));
  const Vec3 H0 = plant.momentum_N(x);
  const double h0 = Full::h_B(x).norm();
  const double dt = 0.01;  // [s]
  Full::Input u = Full::Input::Zero();
  double max_drift = 0.0;
  for (int k = 0; k < 20000; ++k) {  // 200 s
    if (k % 100 == 0) {              // new random held input every 1 s
      u = random_input(rng);
      u.head<4>() *= 0.1;            // gimbal rates within 0.02 rad/s: |gamma| stays moderate
    }
    Full::State k1, k2, k3, k4;
    plant.derivative(0.0, x, u, k1);
    plant.derivative(0.0, Full::State(x + 0.5 * dt * k1), u, k2);
    plant.derivative(0.0, Full::State(x + 0.5 * dt * k2), u, k3);
    plant.derivative(0.0, Full::State(x + dt * k3), u, k4);
    x += (dt / 6.0) * (k1 + 2.0 * k2 + 2.0 * k3 + k4);
    max_drift = std::max(max_drift, (plant.momentum_N(x) - H0).norm());
  }
  EXPECT_TRUE(adcs::all_finite(x));
  EXPECT_LE(max_drift, 1e-10 * H0.norm()) << "max drift " << max_drift << " of " << H0.norm();
  EXPECT_NEAR(Full::h_B(x).norm(), h0, 1e-10 * h0);
}

TEST(VscmgCluster, S6LockedGimbalsHeldRotorsConserveBodyEnergyAndMomentumNorm) {
  const Full plant(adcs::vscmg_params_A_REF());
  std::mt19937_64 rng(29);
  const Full::Input u = Full::Input::Zero();
  for (int k = 0; k < 30; ++k) {
    const Full::State x = random_state(rng, plant);
    Full::State xdot;
    plant.derivative(0.0, x, u, xdot);
    EXPECT_EQ(xdot.tail<7>().norm(), 0.0);  // gamma and Omega_w held
    const auto T = [&](const Full::State& y) {
      const Vec3 w = plant.omega_BN_B(y, u);
      return 0.5 * w.dot(plant.J_tr(y) * w);
    };
    const auto hn = [&](const Full::State& y) { return Full::h_B(y).norm(); };
    EXPECT_LT(std::abs(directional(T, x, xdot, 1e-3)), 1e-10 * (1.0 + T(x)));
    EXPECT_LT(std::abs(directional(hn, x, xdot, 1e-3)), 1e-10 * (1.0 + hn(x)));
  }
}

TEST(VscmgCluster, CtrlPlantMatchesFullPlantWithoutGimbalInertia) {
  adcs::VscmgParams<4, 3> p = adcs::vscmg_params_A_REF();
  p.truth.I_cs.setZero();
  p.truth.I_ct.setZero();
  p.truth.I_cg.setZero();
  p.nominal = p.truth;  // identical geometry: J_n = J_tr(gamma) = const
  const Full full(p);
  const Ctrl ctrl(p);
  ASSERT_EQ(full.status(), adcs::Status::ok);
  ASSERT_EQ(ctrl.status(), adcs::Status::ok);
  std::mt19937_64 rng(31);
  for (int k = 0; k < 20; ++k) {
    const Full::State x = random_state(rng, full);
    const Full::Input u = random_input(rng);
    Full::State xdot;
    full.derivative(0.0, x, u, xdot);
    const double h = 1e-4;
    const Vec3 w = full.omega_BN_B(x, u);
    const Vec3 wdot_full = (full.omega_BN_B(Full::State(x + h * xdot), u) -
                            full.omega_BN_B(Full::State(x - h * xdot), u)) / (2 * h);
    Ctrl::State xc;
    xc << Full::sigma_BN(x), w, Full::gamma(x), Full::Omega_w(x);
    Ctrl::State xcdot;
    ctrl.derivative(0.0, xc, u, xcdot);
    EXPECT_LT((xcdot.segment<3>(3) - wdot_full).norm(), 1e-7 * (1.0 + wdot_full.norm()));
    EXPECT_LT((xcdot.head<3>() - xdot.head<3>()).norm(), 1e-15);
    EXPECT_LT((ctrl.momentum_B(xc) - Full::h_B(x)).norm(), 1e-12);
  }
}

TEST(VscmgCluster, GimbalRateSwitchJumpsOmegaByGimbalMomentum) {
  // spec A.2.4: switching the held gamma_dot changes omega by -J^-1 sum I_cg,i dgamma_dot_i g_i
  // (h, sigma, gamma, Omega_w are continuous).
  const adcs::VscmgParams<4, 3> p = adcs::vscmg_params_A_REF();
  const Full plant(p);
  std::mt19937_64 rng(37);
  const Full::State x = random_state(rng, plant);
  const Full::Input u1 = random_input(rng), u2 = random_input(rng);
  const Vec<4> dgd = Full::gamma_dot(u2) - Full::gamma_dot(u1);
  Vec3 m = Vec3::Zero();
  for (int i = 0; i < 4; ++i) m += p.truth.I_cg(i) * dgd(i) * Vec3(p.truth.A_cg.col(i));
  const Vec3 expected = -plant.J_tr(x).inverse() * m;
  const Vec3 jump = plant.omega_BN_B(x, u2) - plant.omega_BN_B(x, u1);
  EXPECT_GT(expected.norm(), 1e-6);
  // The jump is a difference of two rates: its rounding is relative to ‖ω‖, not to the jump
  // (clang's evaluation order gave 3.8e-17 against a 2.7e-5 rad/s jump).
  EXPECT_LT((jump - expected).norm(), 1e-12 * (expected.norm() + plant.omega_BN_B(x, u1).norm()));
  // and omega satisfies seed 001 eq. (1) with the true axes
  const Vec3 w = plant.omega_BN_B(x, u1);
  const Vec3 h1 = plant.J_tr(x) * w + p.truth.A_cg * p.truth.I_cg.cwiseProduct(Full::gamma_dot(u1)) +
                  p.truth.A_cs(Full::gamma(x)) * p.truth.h_cw +
                  p.truth.A_ws * p.truth.I_wws.cwiseProduct(Full::Omega_w(x));
  EXPECT_LT((h1 - Full::h_B(x)).norm(), 1e-12 * (1.0 + h1.norm()));
}

TEST(VscmgCluster, InvalidParametersAreRejected) {
  const adcs::VscmgParams<4, 3> good = adcs::vscmg_params_A_REF();
  EXPECT_EQ(Full(good).status(), adcs::Status::ok);
  EXPECT_EQ(Ctrl(good).status(), adcs::Status::ok);

  adcs::VscmgParams<4, 3> bad = good;
  bad.truth.J_s(2, 2) = -1.0;  // not positive definite
  EXPECT_EQ(Full(bad).status(), adcs::Status::invalid_parameter);
  EXPECT_EQ(Ctrl(bad).status(), adcs::Status::invalid_parameter);

  bad = good;
  bad.nominal.I_cs(1) = -0.01;  // negative inertia
  EXPECT_EQ(Full(bad).status(), adcs::Status::invalid_parameter);

  bad = good;
  bad.truth.A_ws(0, 1) = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(Full(bad).status(), adcs::Status::invalid_parameter);

  bad = good;
  bad.truth.J_s(0, 1) = 5.0;  // not symmetric
  EXPECT_EQ(Full(bad).status(), adcs::Status::invalid_parameter);

  EXPECT_EQ(Ctrl(good, -adcs::Mat3::Identity()).status(), adcs::Status::invalid_parameter);
}
}  // namespace

using namespace ADCS_UNITY_ID;  // as an anonymous namespace would (CMakeLists.txt, adcs_unity)
