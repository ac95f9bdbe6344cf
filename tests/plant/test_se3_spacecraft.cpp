// SE(3) spacecraft plant, orbit environment and seed 003 scenario data (spec §A.2.2, §A.2.3,
// §A.8): the gravity sanity checks of spec §A.11 #11, the target propagation of #10, the
// zero-relative-twist start of #6, the state-4 numbers of §A.8 / §A.10 #9, and two-body energy and
// momentum conservation through the same Lie-group RK4 the spec's prototype used.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include <Eigen/Eigenvalues>

#include "../support/format.hpp"
#include "adcs/plant/orbit_environment.hpp"
#include "adcs/plant/se3_spacecraft.hpp"
#include "se3_rk4.hpp"
#include "scenarios/seed003_data.hpp"  // seed 003's scenario data (paper data, not flight code)

namespace ADCS_UNITY_ID {
using adcs::Mat3;
using adcs::Mat6;
using adcs::Se3Spacecraft;
using adcs::Se3SpacecraftRates;
using adcs::Se3SpacecraftState;
using adcs::Status;
using adcs::Vec3;
using adcs::Vec6;
using adcs_test::rk4_step;


constexpr double kDt = 0.0125;     // spec Appendix C.1: RK4 at 1/80 s
constexpr int kSteps200s = 16000;  // 200 s

Se3SpacecraftState target0(const adcs::Se3ScenarioParams& p) {
  Se3SpacecraftState x;
  EXPECT_EQ(adcs::se3_target_initial_state(p, x), Status::ok);
  return x;
}

using adcs::test::sci;

Vec3 row(const std::array<double, 3>& a) { return Vec3(a[0], a[1], a[2]); }

// J2 part of the geopotential, U_J2 = −(μ J2 R_E² / (2 r³)) (3 Z²/r² − 1), with a = ∇U
// (independent truth for F_J2 = m ∇U_J2).
double j2_potential(const Vec3& R, const adcs::OrbitEnvironmentParams& e) {
  const double r = R.norm();
  return -e.mu * e.J2 * e.R_E * e.R_E / (2.0 * r * r * r) * (3.0 * R(2) * R(2) / (r * r) - 1.0);
}

}  // namespace

using namespace ADCS_UNITY_ID;  // as an anonymous namespace would (CMakeLists.txt, adcs_unity)

// ---------------------------------------------------------------------------------------------
// Gravity, spec §A.11 #11

TEST(OrbitEnvironment, GravityGradientVanishesAlongPrincipalAxes) {
  const adcs::Se3ScenarioParams p;
  const double mu = p.env.mu, r = 6778e3;
  const double scale = 3.0 * mu / (r * r * r) * p.J0.norm();  // torque scale [N m]
  for (const Mat3& J : {p.J_o, p.J0}) {
    const Eigen::SelfAdjointEigenSolver<Mat3> eig(J);
    for (int a = 0; a < 3; ++a) {
      for (double sgn : {1.0, -1.0}) {
        const Vec3 R_B = sgn * r * eig.eigenvectors().col(a);
        EXPECT_LT(adcs::gravity_gradient_torque_B(J, R_B, mu).norm(), 1e-13 * scale);
      }
    }
  }
  // Off-axis it is not zero, and always perpendicular to R_B.
  const Vec3 R_B = r * Vec3(1.0, 2.0, -0.5).normalized();
  const Vec3 tau = adcs::gravity_gradient_torque_B(p.J0, R_B, mu);
  EXPECT_GT(tau.norm(), 1e-3 * scale);
  EXPECT_LT(std::abs(tau.dot(R_B)), 1e-12 * tau.norm() * r);
}

TEST(OrbitEnvironment, J2ForceInEquatorialPlaneIsRadialWithClosedFormMagnitude) {
  const adcs::OrbitEnvironmentParams e;
  const double m = 108.15;
  for (double r : {6778e3, 7000e3, 42164e3}) {
    for (double lon : {0.0, 0.7, 2.5, -1.9}) {
      const Vec3 R(r * std::cos(lon), r * std::sin(lon), 0.0);
      const Vec3 F = adcs::j2_force_N(m, R, e);
      const double expected = 1.5 * e.J2 * (e.R_E / r) * (e.R_E / r) * m * e.mu / (r * r);
      EXPECT_EQ(F(2), 0.0);
      EXPECT_NEAR(F.norm(), expected, 1e-13 * expected);
      EXPECT_NEAR(F.dot(R) / r, -expected, 1e-13 * expected);  // radial, inward
      EXPECT_LT(F.cross(R).norm() / r, 1e-13 * expected);
    }
  }
}

TEST(OrbitEnvironment, ForcesAreGradientsOfThePotential) {
  // F_J2 = m ∇U_J2 and f_g = m ∇(μ/r) at a generic point, by central differences.
  const adcs::OrbitEnvironmentParams e;
  const double m = 105.0, h = 1.0;
  const Vec3 R(4100e3, -3900e3, 3700e3);
  Vec3 grad_j2, grad_pm;
  for (int i = 0; i < 3; ++i) {
    const Vec3 d = h * Vec3::Unit(i);
    grad_j2(i) = (j2_potential(R + d, e) - j2_potential(R - d, e)) / (2.0 * h);
    grad_pm(i) = (e.mu / (R + d).norm() - e.mu / (R - d).norm()) / (2.0 * h);
  }
  const Vec3 F_j2 = adcs::j2_force_N(m, R, e);
  const Vec3 F_pm = adcs::point_mass_gravity_force(m, R, e.mu);
  EXPECT_LT((F_j2 - m * grad_j2).norm(), 1e-6 * F_j2.norm());
  EXPECT_LT((F_pm - m * grad_pm).norm(), 1e-8 * F_pm.norm());
  // Body components are the rotated ECI ones.
  const Mat3 C = adcs::so3_exp(Vec3(0.3, -1.1, 2.0));
  EXPECT_LT((adcs::j2_force_B(m, C, R, e) - C.transpose() * F_j2).norm(), 1e-15 * F_j2.norm());
}

// ---------------------------------------------------------------------------------------------
// Plant

TEST(Se3Spacecraft, ParameterValidationAndGuards) {
  const adcs::Se3ScenarioParams p;
  const Se3Spacecraft ok(adcs::se3_target_params(p));
  EXPECT_EQ(ok.status(), Status::ok);
  adcs::Se3SpacecraftParams bad = adcs::se3_target_params(p);
  bad.J_B(0, 0) = -1.0;
  EXPECT_EQ(Se3Spacecraft(bad).status(), Status::invalid_parameter);
  bad = adcs::se3_target_params(p);
  bad.m = 0.0;
  EXPECT_EQ(Se3Spacecraft(bad).status(), Status::invalid_parameter);

  Se3SpacecraftState x = target0(p);
  Se3SpacecraftRates out;
  out.v_dot_B = Vec3::Constant(7.0);
  x.R_N = Vec3::Zero();
  EXPECT_EQ(ok.derivative(x, Vec6::Zero(), Vec6::Zero(), out), Status::out_of_range);
  x = target0(p);
  x.omega_BN_B(1) = std::nan("");
  EXPECT_EQ(ok.derivative(x, Vec6::Zero(), Vec6::Zero(), out), Status::non_finite_input);
  EXPECT_EQ(out.v_dot_B, Vec3::Constant(7.0));  // untouched on failure
}

TEST(Se3Spacecraft, ExplicitDynamicsEqualCoadjointForm) {
  // Ξ ξ̇ = ad*_ξ Ξ ξ + M_g + τ_c + τ_d, ad*_ξ = [[−ω×, −v×], [0, −ω×]]   (spec §A.2.2)
  const adcs::Se3ScenarioParams p;
  adcs::Se3SpacecraftParams truth;
  ASSERT_EQ(adcs::se3_chaser_truth_params(p, truth), Status::ok);
  const Se3Spacecraft sc(truth);
  Se3SpacecraftState x = adcs::se3_chaser_initial_state(target0(p), adcs::kSe3InitialPoses[2]);
  x.omega_BN_B += Vec3(0.01, -0.02, 0.03);
  // The identity is algebraic; a slow v keeps the rounding of the test's v×(m v) (= 0 exactly,
  // ~eps·m‖v‖² ≈ 1e-6 N m at orbital speed) below the tolerance.
  x.v_B = Vec3(0.3, -1.2, 0.8);
  const Vec6 tau_c = (Vec6() << 0.1, -0.2, 0.3, 1.0, -2.0, 3.0).finished();
  const Vec6 tau_d = adcs::se3_disturbance(3.7, p);
  Se3SpacecraftRates r;
  ASSERT_EQ(sc.derivative(x, tau_c, tau_d, r), Status::ok);
  const Vec3 w = x.omega_BN_B, v = x.v_B;
  Mat6 ad_star = Mat6::Zero();
  ad_star.topLeftCorner<3, 3>() = -adcs::skew(w);
  ad_star.topRightCorner<3, 3>() = -adcs::skew(v);
  ad_star.bottomRightCorner<3, 3>() = -adcs::skew(w);
  const Mat6 Xi = sc.inertia();
  const Vec6 rhs = ad_star * Xi * x.xi() + sc.gravity_wrench(x) + tau_c + tau_d;
  const Vec6 lhs = Xi * r.xi_dot();
  EXPECT_LT((lhs.head<3>() - rhs.head<3>()).norm(), 1e-13 * rhs.head<3>().norm());
  EXPECT_LT((lhs.tail<3>() - rhs.tail<3>()).norm(), 1e-13 * rhs.tail<3>().norm());
  EXPECT_LT((r.R_dot_N - x.C_NB * v).norm(), 1e-14 * v.norm());
}

// ---------------------------------------------------------------------------------------------
// Scenario data, spec §A.8

TEST(Se3Scenario, TargetInitialStateIsLvlh) {
  const adcs::Se3ScenarioParams p;
  const Se3SpacecraftState x = target0(p);
  const double a = p.env.R_E + 400e3, n = std::sqrt(p.env.mu / (a * a * a));
  const double s45 = std::sqrt(0.5);
  EXPECT_LT((x.R_N - Vec3(a, 0.0, 0.0)).norm(), 1e-9);
  EXPECT_LT((x.V_N() - std::sqrt(p.env.mu / a) * Vec3(0.0, s45, s45)).norm(), 1e-9);
  EXPECT_LT((x.C_NB.transpose() * x.C_NB - Mat3::Identity()).norm(), 1e-15);
  EXPECT_NEAR(x.C_NB.determinant(), 1.0, 1e-15);
  EXPECT_LT((x.C_NB.col(2) + x.R_N.normalized()).norm(), 1e-15);  // z nadir
  EXPECT_LT((x.omega_BN_B - Vec3(0.0, -n, 0.0)).norm(), 1e-18);
  // The frame turns about the orbit normal R × V at n (independent of the LVLH sign choices).
  const Vec3 h_hat = x.R_N.cross(x.V_N()).normalized();
  EXPECT_LT((x.C_NB * x.omega_BN_B - n * h_hat).norm(), 1e-18);
  EXPECT_LT((x.v_B - Vec3(std::sqrt(p.env.mu / a), 0.0, 0.0)).norm(), 1e-9);
}

TEST(Se3Scenario, ParametersDisturbanceAndLimits) {
  adcs::Se3ScenarioParams p;
  adcs::Se3SpacecraftParams truth;
  ASSERT_EQ(adcs::se3_chaser_truth_params(p, truth), Status::ok);
  EXPECT_LT((truth.J_B - 1.12 * p.J0).norm(), 1e-13);
  EXPECT_NEAR(truth.m, 108.15, 1e-12);
  p.uncertainty_sign = -1;
  ASSERT_EQ(adcs::se3_chaser_truth_params(p, truth), Status::ok);
  EXPECT_LT((truth.J_B - 0.88 * p.J0).norm(), 1e-13);
  EXPECT_NEAR(truth.m, 101.85, 1e-12);
  p.uncertainty_sign = 0;
  const adcs::Se3SpacecraftParams before = truth;
  EXPECT_EQ(adcs::se3_chaser_truth_params(p, truth), Status::invalid_parameter);
  EXPECT_EQ(truth.m, before.m);

  const double t = 7.3;
  const Vec6 u = adcs::se3_disturbance(t, p);
  const Vec3 d(std::sin(0.2 * t), std::cos(0.1 * t), -std::sin(0.3 * t));
  EXPECT_LT((u.head<3>() - 0.005 * d).norm(), 1e-17);
  EXPECT_LT((u.tail<3>() - 0.005 * d).norm(), 1e-17);
  const Vec6 lim = adcs::se3_actuator_limits(p);
  EXPECT_EQ(lim, (Vec6() << 0.5, 0.5, 0.5, 5.0, 5.0, 5.0).finished());
}

TEST(Se3Scenario, EulerZyxIsActiveIntrinsic) {
  // C_rel = Rz(ψ) Ry(ϑ) Rx(φ) with active elementary rotations built independently by so3_exp.
  for (const auto& pose : adcs::kSe3InitialPoses) {
    const Vec3 a = row(pose.euler_zyx_deg) * adcs::kPiRad / 180.0;
    const Mat3 expected = adcs::so3_exp(a(0) * Vec3::UnitZ()) *
                          adcs::so3_exp(a(1) * Vec3::UnitY()) * adcs::so3_exp(a(2) * Vec3::UnitX());
    EXPECT_LT((adcs::se3_relative_attitude(pose) - expected).norm(), 1e-14);
  }
}

TEST(Se3Scenario, State4RotationAngleAndPositionError) {
  // spec §A.8 check (165.48°, paper "165.5°") and §A.10 #9 (‖R_e(0)‖ = 55.45 m).
  const adcs::Se3ScenarioParams p;
  const Mat3 C_rel = adcs::se3_relative_attitude(adcs::kSe3InitialPoses[3]);
  const double cos_angle = std::clamp((C_rel.trace() - 1.0) / 2.0, -1.0, 1.0);
  const double angle_deg = std::acos(cos_angle) * 180.0 / adcs::kPiRad;
  EXPECT_NEAR(angle_deg, 165.48, 0.005);

  const Se3SpacecraftState tgt = target0(p);
  const Se3SpacecraftState x = adcs::se3_chaser_initial_state(tgt, adcs::kSe3InitialPoses[3]);
  const Se3Spacecraft target_model(adcs::se3_target_params(p));
  adcs::Se3DesiredState d;
  ASSERT_EQ(adcs::se3_desired_state(target_model, tgt, p, d), Status::ok);
  const Vec3 R_e = d.C_ND.transpose() * (x.R_N - d.R_N);
  EXPECT_NEAR(R_e.norm(), 55.45, 0.005);
  EXPECT_LT((R_e - Vec3(35.0, -25.0, -35.0)).norm(), 1e-8);  // r_rel − r_χ
}

TEST(Se3Scenario, ZeroRelativeTwistStartGivesZeroVelocityError) {
  // spec §A.11 #6: ω_e = ω − C_eᵀω_d, v_e = v − C_eᵀ(v_d + ω_d × R_e), C_e = C_dᵀC,
  // R_e = C_dᵀ(R − R_d) (spec §A.2.3) vanish for every initial state.
  const adcs::Se3ScenarioParams p;
  const Se3SpacecraftState tgt = target0(p);
  const Se3Spacecraft target_model(adcs::se3_target_params(p));
  adcs::Se3DesiredState d;
  ASSERT_EQ(adcs::se3_desired_state(target_model, tgt, p, d), Status::ok);
  // χ_d = (I, [−5,0,0]): ω_d = ω_o, v_d = v_o + ω_o × r_χ.
  EXPECT_LT((d.omega_DN_D - tgt.omega_BN_B).norm(), 1e-18);
  EXPECT_LT((d.v_D - tgt.v_B - tgt.omega_BN_B.cross(p.r_chi)).norm(), 1e-12);
  for (const auto& pose : adcs::kSe3InitialPoses) {
    const Mat3 C_rel = adcs::se3_relative_attitude(pose);
    const Se3SpacecraftState x = adcs::se3_chaser_initial_state(tgt, pose);
    EXPECT_LT((x.omega_BN_B - C_rel.transpose() * tgt.omega_BN_B).norm(), 1e-18);
    EXPECT_LT((x.C_NB - tgt.C_NB * C_rel).norm(), 1e-15);
    const Mat3 C_e = d.C_ND.transpose() * x.C_NB;
    const Vec3 R_e = d.C_ND.transpose() * (x.R_N - d.R_N);
    const Vec3 omega_e = x.omega_BN_B - C_e.transpose() * d.omega_DN_D;
    const Vec3 v_e = x.v_B - C_e.transpose() * (d.v_D + d.omega_DN_D.cross(R_e));
    EXPECT_LT(omega_e.norm(), 1e-9);
    EXPECT_LT(v_e.norm(), 1e-9);
  }
}

TEST(Se3Scenario, DesiredAccelerationIsAdjointOfTargetAcceleration) {
  // ξ̇_d = Ad_{χ⁻¹} ξ̇_o with Ad_{χ⁻¹} = [[C_χᵀ, 0], [−C_χᵀ r_χ×, C_χᵀ]], for a general χ.
  const adcs::Se3ScenarioParams p;
  const Se3SpacecraftState tgt = target0(p);
  Se3SpacecraftRates r;
  const Se3Spacecraft target(adcs::se3_target_params(p));
  ASSERT_EQ(target.derivative(tgt, Vec6::Zero(), Vec6::Zero(), r), Status::ok);
  const Mat3 C_chi = adcs::so3_exp(Vec3(0.4, -0.2, 1.3));
  const Vec3 r_chi(3.0, -7.0, 2.0);
  Mat6 Ad = Mat6::Zero();
  Ad.topLeftCorner<3, 3>() = C_chi.transpose();
  Ad.bottomLeftCorner<3, 3>() = -C_chi.transpose() * adcs::skew(r_chi);
  Ad.bottomRightCorner<3, 3>() = C_chi.transpose();
  const adcs::Se3DesiredState d = adcs::se3_desired_state(tgt, r, C_chi, r_chi);
  EXPECT_LT((d.xi() - Ad * tgt.xi()).norm(), 1e-12 * tgt.xi().norm());
  EXPECT_LT((d.xi_dot() - Ad * r.xi_dot()).norm(), 1e-14 * r.xi_dot().norm());
}

// ---------------------------------------------------------------------------------------------
// Propagation with the prototype integrator

TEST(Se3Propagation, TargetStaysNearCircularOrbitAndLvlhRate) {
  // spec §A.11 #10: r − a ∈ [−300, +10] m (prototype −245 m at 200 s, the J2 pull on a two-body
  // circular speed) and |ω_o − [0,−n,0]| < 1e-9 rad/s (prototype 5e-11) over 200 s.
  const adcs::Se3ScenarioParams p;
  const Se3Spacecraft target(adcs::se3_target_params(p));
  Se3SpacecraftState x = target0(p);
  const double a = p.env.R_E + p.altitude, n = std::sqrt(p.env.mu / (a * a * a));
  double dr_min = 0.0, dr_max = 0.0, dw_max = 0.0;
  for (int k = 0; k < kSteps200s; ++k) {
    ASSERT_TRUE(rk4_step(target, x, kDt));
    const double dr = x.R_N.norm() - a;
    dr_min = std::min(dr_min, dr);
    dr_max = std::max(dr_max, dr);
    dw_max = std::max(dw_max, (x.omega_BN_B - Vec3(0.0, -n, 0.0)).norm());
  }
  const double dr_end = x.R_N.norm() - a;
  RecordProperty("r_minus_a_200s_m", sci(dr_end));
  RecordProperty("omega_drift_max_rad_s", sci(dw_max));
  EXPECT_GE(dr_min, -300.0);
  EXPECT_LE(dr_max, 10.0);
  EXPECT_NEAR(dr_end, -245.0, 25.0);  // prototype value, ±10 %
  EXPECT_LT(dw_max, 1e-9);
  EXPECT_LT((x.C_NB.transpose() * x.C_NB - Mat3::Identity()).norm(), 1e-13);
}

TEST(Se3Propagation, PointMassGravityConservesOrbitalEnergyAndMomentum) {
  // Point-mass gravity only (J2 = 0), no control, no disturbance: ε = ½‖C v‖² − μ/r and
  // h = R × C v are invariants of the translational motion; the integrator must keep them.
  adcs::Se3ScenarioParams p;
  p.env.J2 = 0.0;
  adcs::Se3SpacecraftParams truth;
  ASSERT_EQ(adcs::se3_chaser_truth_params(p, truth), Status::ok);
  const Se3Spacecraft chaser(truth);
  Se3SpacecraftState x = adcs::se3_chaser_initial_state(target0(p), adcs::kSe3InitialPoses[3]);
  const double e0 = adcs::specific_orbital_energy(x.R_N, x.V_N(), p.env.mu);
  const Vec3 h0 = x.R_N.cross(x.V_N());
  for (int k = 0; k < kSteps200s; ++k) ASSERT_TRUE(rk4_step(chaser, x, kDt));
  const double de = std::abs(adcs::specific_orbital_energy(x.R_N, x.V_N(), p.env.mu) / e0 - 1.0);
  const double dh = (x.R_N.cross(x.V_N()) - h0).norm() / h0.norm();
  RecordProperty("energy_rel_drift", sci(de));
  RecordProperty("momentum_rel_drift", sci(dh));
  EXPECT_LE(de, 1e-9);
  EXPECT_LE(dh, 1e-9);
}
