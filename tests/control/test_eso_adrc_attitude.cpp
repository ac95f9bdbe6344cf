// EsoAdrcAttitude (control/eso_adrc_attitude.hpp): the discrete observer's poles, convergence of
// f̂ to a constant disturbance on a rigid body, closed-loop settling, parameter refusals, the
// failure semantics (rejected samples leave the observer untouched) and reset(); the float
// instance (issue 19) against the double one.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>

#include "adcs/control/eso_adrc_attitude.hpp"
#include "adcs/math/euler.hpp"

namespace ADCS_UNITY_ID {
using adcs::BodyTorque;
using adcs::EsoAdrcAttitude;
using adcs::Mat3;
using adcs::Status;
using adcs::Vec3;
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kPi = 3.14159265358979323846;

EsoAdrcAttitude::Params params() {
  EsoAdrcAttitude::Params p;
  p.J_B_kgm2 << 420.8, 3.6, -4.2, 3.6, 410.6, 9.4, -4.2, 9.4, 690.7;  // seed 002 Table 1
  p.omega_o_rad_s = 2.0;
  p.omega_c_rad_s = 0.5;
  p.period_s = 0.05;
  return p;
}

EsoAdrcAttitude::Input at_angles(const Vec3& theta) {
  EsoAdrcAttitude::Input in;
  in.state.theta_BN_rad = theta;
  return in;  // reference: ϑ_d = 0 at rest
}

//! A rigid body in the Euler view, ω̇ = J⁻¹(u + d − ω × J ω), ϑ̇ = F(ϑ) ω, by RK4 (the test's truth).
struct RigidBody {
  Mat3 J, J_inv;
  Vec3 d;  // [N m] constant disturbance torque
  Vec3 theta = Vec3::Zero(), omega = Vec3::Zero();
  void deriv(const Vec3& th, const Vec3& w, const Vec3& u, Vec3& th_dot, Vec3& w_dot) const {
    Mat3 F = Mat3::Identity();
    EXPECT_EQ(adcs::euler123_F(th, F), Status::ok);
    th_dot = F * w;
    w_dot = J_inv * (u + d - w.cross(J * w));
  }
  void advance(const Vec3& u, double h, int n) {
    const double dt = h / n;
    for (int i = 0; i < n; ++i) {
      Vec3 k1t, k1w, k2t, k2w, k3t, k3w, k4t, k4w;
      deriv(theta, omega, u, k1t, k1w);
      deriv(theta + 0.5 * dt * k1t, omega + 0.5 * dt * k1w, u, k2t, k2w);
      deriv(theta + 0.5 * dt * k2t, omega + 0.5 * dt * k2w, u, k3t, k3w);
      deriv(theta + dt * k3t, omega + dt * k3w, u, k4t, k4w);
      theta += dt / 6.0 * (k1t + 2.0 * k2t + 2.0 * k3t + k4t);
      omega += dt / 6.0 * (k1w + 2.0 * k2w + 2.0 * k3w + k4w);
    }
  }
};

RigidBody rigid_body(const Vec3& d) {
  RigidBody b;
  b.J = params().J_B_kgm2;
  b.J_inv = b.J.inverse();
  b.d = d;
  return b;
}

bool same_bits(const Vec3& a, const Vec3& b) { return std::memcmp(a.data(), b.data(), sizeof(double) * 3) == 0; }

TEST(EsoAdrcAttitude, ObserverPolesAreAllAtExpMinusOmegaOH) {
  // The error dynamics of the current-form ESO are (I − L H) Φ; its characteristic polynomial
  // must be (z − β)³, β = e^{−ω_o h} (checked on the coefficients: the triple pole is defective,
  // so computed eigenvalues would only be accurate to ~cbrt(eps)).
  for (double wo_h : {0.01, 0.1, 1.0, 5.0}) {
    EsoAdrcAttitude::Params p = params();
    p.omega_o_rad_s = wo_h / p.period_s;
    const EsoAdrcAttitude law(p);
    ASSERT_EQ(law.status(), Status::ok);
    const double h = p.period_s, beta = std::exp(-wo_h);
    const Vec3 L = law.observer_gains();
    Mat3 Phi;
    Phi << 1, h, 0.5 * h * h, 0, 1, h, 0, 0, 1;
    Mat3 IL = Mat3::Identity();
    IL.col(0) -= L;
    const Mat3 M = IL * Phi;
    double minors = 0.0;
    for (int i = 0; i < 3; ++i)
      for (int j = i + 1; j < 3; ++j) minors += M(i, i) * M(j, j) - M(i, j) * M(j, i);
    EXPECT_NEAR(M.trace(), 3.0 * beta, 1e-12) << wo_h;
    EXPECT_NEAR(minors, 3.0 * beta * beta, 1e-12) << wo_h;
    EXPECT_NEAR(M.determinant(), beta * beta * beta, 1e-12) << wo_h;
  }
}

TEST(EsoAdrcAttitude, FirstStepStartsTheObserverAtTheMeasurement) {
  EsoAdrcAttitude law(params());
  EsoAdrcAttitude::Input in = at_angles(Vec3(0.01, -0.02, 0.005));
  in.reference.angles_dot = Vec3(1e-3, 0.0, -1e-3);
  in.reference.angles_ddot = Vec3(0.0, 2e-4, 0.0);
  BodyTorque out;
  EsoAdrcAttitude::Diagnostics diag;
  ASSERT_EQ(law.step(in, out, &diag), Status::ok);
  EXPECT_TRUE(law.started());
  EXPECT_EQ(diag.angles_hat_rad, in.state.theta_BN_rad);
  EXPECT_EQ(diag.angles_dot_hat_rad_s, Vec3::Zero());
  EXPECT_EQ(diag.f_hat_rad_s2, Vec3::Zero());
  // u = J G(y) (ϑ̈_d − k_p e − k_d ė), e = y − ϑ_d, ė = 0 − ϑ̇_d
  const double wc = params().omega_c_rad_s;
  const Vec3 v = in.reference.angles_ddot - wc * wc * in.state.theta_BN_rad + 2.0 * wc * in.reference.angles_dot;
  const Vec3 u = params().J_B_kgm2 * (adcs::euler123_G(in.state.theta_BN_rad) * v);
  EXPECT_LT((out.torque_B_Nm - u).norm(), 1e-14 * u.norm());
}

TEST(EsoAdrcAttitude, ObserverConvergesToAConstantDisturbanceOnARigidBody) {
  // Regulation to ϑ_d = 0 under a constant body torque d: at equilibrium ω = 0, so the total
  // disturbance is f = F(ϑ) J⁻¹ d, and the law must cancel it (u → −d, ϑ → 0).
  const Vec3 d(0.004, -0.003, 0.002);
  RigidBody body = rigid_body(d);
  body.theta = Vec3(0.02, -0.01, 0.015);
  EsoAdrcAttitude law(params());
  const double h = params().period_s;
  BodyTorque out;
  EsoAdrcAttitude::Diagnostics diag;
  for (int k = 0; k < 1200; ++k) {  // 60 s = 30 / ω_c
    ASSERT_EQ(law.step(at_angles(body.theta), out, &diag), Status::ok) << k;
    body.advance(out.torque_B_Nm, h, 5);
  }
  Mat3 F = Mat3::Identity();
  ASSERT_EQ(adcs::euler123_F(body.theta, F), Status::ok);
  const Vec3 f = F * (body.J_inv * d);
  EXPECT_LT((diag.f_hat_rad_s2 - f).norm(), 1e-6 * f.norm());
  EXPECT_LT((out.torque_B_Nm + d).norm(), 1e-6 * d.norm());
  EXPECT_LT(body.theta.norm(), 1e-9);
  EXPECT_LT(diag.angles_dot_hat_rad_s.norm(), 1e-9);
}

TEST(EsoAdrcAttitude, ClosedLoopTracksASinusoidDespiteTheDisturbance) {
  // Seed 002's reference (0.5, 1, −0.5)° at 0.1 rad/s on a rigid body with a disturbance torque,
  // from an offset of ~0.3°: settled to < 1e-4 rad after 20 s (10 / ω_c), a steady error ~1e-6.
  RigidBody body = rigid_body(Vec3(0.009, 0.0045, 0.0045));
  body.theta = Vec3(0.25, 0.15, -0.2) * (kPi / 180.0);
  const Vec3 a = Vec3(0.5, 1.0, -0.5) * (kPi / 180.0);
  const double w = 0.1, h = params().period_s;
  EsoAdrcAttitude law(params());
  BodyTorque out;
  double err_late = 0.0, err_early = 0.0;
  for (int k = 0; k < 2000; ++k) {  // 100 s
    const double t = k * h;
    EsoAdrcAttitude::Input in = at_angles(body.theta);
    in.t_s = t;
    in.reference.angles = a * std::sin(w * t);
    in.reference.angles_dot = a * (w * std::cos(w * t));
    in.reference.angles_ddot = a * (-w * w * std::sin(w * t));
    ASSERT_EQ(law.step(in, out), Status::ok) << k;
    const double e = (body.theta - in.reference.angles).cwiseAbs().maxCoeff();
    if (t >= 20.0 && t < 40.0) err_early = std::max(err_early, e);
    if (t >= 40.0) err_late = std::max(err_late, e);
    body.advance(out.torque_B_Nm, h, 5);
  }
  EXPECT_LT(err_early, 1e-4);
  EXPECT_LT(err_late, 1e-5);
}

TEST(EsoAdrcAttitude, RefusesMissingOrUnphysicalParameters) {
  EXPECT_EQ(EsoAdrcAttitude(params()).status(), Status::ok);
  auto refused = [](EsoAdrcAttitude::Params p) { return EsoAdrcAttitude(p).status() == Status::invalid_parameter; };
  EXPECT_TRUE(refused(EsoAdrcAttitude::Params{}));  // nothing set: J, bandwidths, period all NaN
  EsoAdrcAttitude::Params p = params();
  p.J_B_kgm2 = Mat3::Constant(adcs::kUnset);
  EXPECT_TRUE(refused(p));
  p = params();
  p.J_B_kgm2(0, 1) = 50.0;  // not symmetric
  EXPECT_TRUE(refused(p));
  p = params();
  p.J_B_kgm2(2, 2) = -1.0;  // not positive definite
  EXPECT_TRUE(refused(p));
  for (double bad : {adcs::kUnset, 0.0, -1.0, std::numeric_limits<double>::infinity()}) {
    p = params();
    p.omega_o_rad_s = bad;
    EXPECT_TRUE(refused(p)) << "omega_o " << bad;
    p = params();
    p.omega_c_rad_s = bad;
    EXPECT_TRUE(refused(p)) << "omega_c " << bad;
    p = params();
    p.period_s = bad;
    EXPECT_TRUE(refused(p)) << "period " << bad;
  }
  // The sampled PD on the double integrator needs ω_c h < 1 (Jury: P(−1) = 4(1 − ω_c h)).
  p = params();
  p.omega_c_rad_s = 1.0 / p.period_s;
  EXPECT_TRUE(refused(p));
  p.omega_c_rad_s = 0.99 / p.period_s;
  EXPECT_FALSE(refused(p));
  // No upper limit on ω_o h for the exact current-form observer (β → 0: deadbeat).
  p = params();
  p.omega_o_rad_s = 1e4 / p.period_s;
  EXPECT_FALSE(refused(p));
  // A refused law answers invalid_parameter with zero torque.
  EsoAdrcAttitude bad(EsoAdrcAttitude::Params{});
  BodyTorque out{Vec3::Constant(7.0)};
  EXPECT_EQ(bad.step(at_angles(Vec3(0.1, 0, 0)), out), Status::invalid_parameter);
  EXPECT_EQ(out.torque_B_Nm, Vec3::Zero());
}

TEST(EsoAdrcAttitude, RejectedSamplesLeaveTheObserverUntouched) {
  for (auto policy : {adcs::FailurePolicy::safe_command, adcs::FailurePolicy::hold_last}) {
    EsoAdrcAttitude::Params p = params();
    p.on_failure = policy;
    EsoAdrcAttitude a(p), b(p);
    BodyTorque oa, ob;
    for (int k = 0; k < 10; ++k) {
      const Vec3 th(0.01 - 1e-4 * k, 0.002 * k, -0.003);
      ASSERT_EQ(a.step(at_angles(th), oa), Status::ok);
      ASSERT_EQ(b.step(at_angles(th), ob), Status::ok);
    }
    const Vec3 last = oa.torque_B_Nm;
    const Vec3 expected = policy == adcs::FailurePolicy::hold_last ? last : Vec3::Zero();
    EsoAdrcAttitude::Input bad = at_angles(Vec3(0.0, kNaN, 0.0));
    BodyTorque out;
    EXPECT_EQ(a.step(bad, out), Status::non_finite_input);
    EXPECT_EQ(out.torque_B_Nm, expected);
    bad = at_angles(Vec3::Zero());
    bad.reference.angles_ddot(2) = std::numeric_limits<double>::infinity();
    EXPECT_EQ(a.step(bad, out), Status::non_finite_input);
    EXPECT_EQ(out.torque_B_Nm, expected);
    EXPECT_EQ(a.step(at_angles(Vec3(0.0, kPi / 2.0, 0.0)), out), Status::singular);  // gimbal lock
    EXPECT_EQ(out.torque_B_Nm, expected);
    bad = at_angles(Vec3(1e300, 0.0, 0.0));  // finite but absurd: overflows, nothing committed
    bad.reference.angles_ddot = Vec3::Constant(1e308);
    EXPECT_EQ(a.step(bad, out), Status::out_of_range);
    EXPECT_EQ(out.torque_B_Nm, expected);
    // The observer state is untouched: both twins go on bit for bit.
    for (int k = 10; k < 20; ++k) {
      const Vec3 th(0.01 - 1e-4 * k, 0.002 * k, -0.003);
      ASSERT_EQ(a.step(at_angles(th), oa), Status::ok);
      ASSERT_EQ(b.step(at_angles(th), ob), Status::ok);
      EXPECT_TRUE(same_bits(oa.torque_B_Nm, ob.torque_B_Nm)) << k;
    }
    EXPECT_TRUE(same_bits(a.f_hat_rad_s2(), b.f_hat_rad_s2()));
  }
}

TEST(EsoAdrcAttitude, ReadsOnlyTheAnglesNotTheRate) {
  EsoAdrcAttitude a(params()), b(params());
  BodyTorque oa, ob;
  for (int k = 0; k < 5; ++k) {
    EsoAdrcAttitude::Input in = at_angles(Vec3(0.01 * k, 0.0, -0.002));
    ASSERT_EQ(a.step(in, oa), Status::ok);
    in.state.omega_BN_B = Vec3(kNaN, 1.0, -3.0);  // a failed gyro does not reach the law
    ASSERT_EQ(b.step(in, ob), Status::ok);
    EXPECT_TRUE(same_bits(oa.torque_B_Nm, ob.torque_B_Nm));
  }
}

TEST(EsoAdrcAttitude, AngleWrapDoesNotKickTheObserver) {
  // ϑ_1 crossing +π → −π between two samples is a 0.02 rad step, not a 2π one: the law answers
  // as it does to the same motion measured without the wrap (π − 0.01 → π + 0.01).
  EsoAdrcAttitude wrapped(params()), plain(params());
  BodyTorque ow, op;
  EsoAdrcAttitude::Input in = at_angles(Vec3(kPi - 0.01, 0.0, 0.0));
  in.reference.angles = in.state.theta_BN_rad;
  ASSERT_EQ(wrapped.step(in, ow), Status::ok);
  ASSERT_EQ(plain.step(in, op), Status::ok);
  EsoAdrcAttitude::Diagnostics dw, dp;
  in.state.theta_BN_rad(0) = -kPi + 0.01;
  ASSERT_EQ(wrapped.step(in, ow, &dw), Status::ok);
  in.state.theta_BN_rad(0) = kPi + 0.01;
  ASSERT_EQ(plain.step(in, op, &dp), Status::ok);
  EXPECT_NEAR(dw.innovation_rad(0), 0.02, 1e-12);
  EXPECT_NEAR(dw.e_rad(0), dp.e_rad(0), 1e-12);
  EXPECT_LT((ow.torque_B_Nm - op.torque_B_Nm).norm(), 1e-9 * op.torque_B_Nm.norm());
}

TEST(EsoAdrcAttitude, ResetBringsBackAFreshInstance) {
  EsoAdrcAttitude used(params()), fresh(params());
  BodyTorque o1, o2;
  for (int k = 0; k < 30; ++k) ASSERT_EQ(used.step(at_angles(Vec3(0.01, -0.005 * k, 0.0)), o1), Status::ok);
  used.reset();
  EXPECT_FALSE(used.started());
  EXPECT_EQ(used.f_hat_rad_s2(), Vec3::Zero());
  for (int k = 0; k < 10; ++k) {
    const Vec3 th(0.02, 0.001 * k, -0.01);
    ASSERT_EQ(used.step(at_angles(th), o1), Status::ok);
    ASSERT_EQ(fresh.step(at_angles(th), o2), Status::ok);
    EXPECT_TRUE(same_bits(o1.torque_B_Nm, o2.torque_B_Nm)) << k;
  }
  // hold_last after reset holds zero, not a command from before the reset
  EsoAdrcAttitude::Params p = params();
  p.on_failure = adcs::FailurePolicy::hold_last;
  EsoAdrcAttitude h(p);
  ASSERT_EQ(h.step(at_angles(Vec3(0.1, 0, 0)), o1), Status::ok);
  h.reset();
  EXPECT_EQ(h.step(at_angles(Vec3(kNaN, 0, 0)), o1), Status::non_finite_input);
  EXPECT_EQ(o1.torque_B_Nm, Vec3::Zero());
}

// ---- Issue 19: the same law in single precision (EsoAdrcAttitudeT<float>) ----------------------
using EsoF = adcs::EsoAdrcAttitudeT<float>;
using Vec3f = adcs::Vec<3, float>;

//! The double law's input rounded once to float, as a single-precision computer receives it.
EsoF::Input to_float(const EsoAdrcAttitude::Input& in) { return in.cast<float>(); }

TEST(EsoAdrcAttitudeFloat, GainsAreTheDoubleGainsToFloatPrecision) {
  // l3 = (1 − β)³/h² with β = e^{−ω_o h} = e^{−0.1}: 1 − β loses ~3 bits of float's 24 (header).
  const EsoAdrcAttitude d(params());
  const EsoF f(params().cast<float>());
  ASSERT_EQ(f.status(), Status::ok);
  const Vec3 gd = d.observer_gains(), gf = f.observer_gains().cast<double>();
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(gf(i), gd(i), 2e-6 * std::abs(gd(i))) << i;
}

TEST(EsoAdrcAttitudeFloat, ClosedLoopTracksAsTheDoubleLaw) {
  // The sinusoid of ClosedLoopTracksASinusoidDespiteTheDisturbance, flown by each law on its own
  // rigid body (double truth): the float law settles as the double one and its steady error stays
  // at the double law's level, far above float's resolution of the angles (~2e-9 rad at 1°).
  const Vec3 a = Vec3(0.5, 1.0, -0.5) * (kPi / 180.0);
  const double w = 0.1, h = params().period_s;
  RigidBody bd = rigid_body(Vec3(0.009, 0.0045, 0.0045)), bf = bd;
  bd.theta = bf.theta = Vec3(0.25, 0.15, -0.2) * (kPi / 180.0);
  EsoAdrcAttitude law_d(params());
  EsoF law_f(params().cast<float>());
  BodyTorque ud;
  adcs::BodyTorqueT<float> uf;
  double late_d = 0.0, late_f = 0.0, early_f = 0.0, du_max = 0.0, u_max = 0.0;
  for (int k = 0; k < 2000; ++k) {  // 100 s
    const double t = k * h;
    auto input = [&](const Vec3& theta) {
      EsoAdrcAttitude::Input in = at_angles(theta);
      in.t_s = t;
      in.reference.angles = a * std::sin(w * t);
      in.reference.angles_dot = a * (w * std::cos(w * t));
      in.reference.angles_ddot = a * (-w * w * std::sin(w * t));
      return in;
    };
    const EsoAdrcAttitude::Input in_d = input(bd.theta), in_f = input(bf.theta);
    ASSERT_EQ(law_d.step(in_d, ud), Status::ok) << k;
    ASSERT_EQ(law_f.step(to_float(in_f), uf), Status::ok) << k;
    const double ed = (bd.theta - in_d.reference.angles).cwiseAbs().maxCoeff();
    const double ef = (bf.theta - in_f.reference.angles).cwiseAbs().maxCoeff();
    if (t >= 20.0 && t < 40.0) early_f = std::max(early_f, ef);
    if (t >= 40.0) {
      late_d = std::max(late_d, ed);
      late_f = std::max(late_f, ef);
    }
    du_max = std::max(du_max, (uf.torque_B_Nm.cast<double>() - ud.torque_B_Nm).cwiseAbs().maxCoeff());
    u_max = std::max(u_max, ud.torque_B_Nm.cwiseAbs().maxCoeff());
    bd.advance(ud.torque_B_Nm, h, 5);
    bf.advance(uf.torque_B_Nm.cast<double>(), h, 5);
  }
  EXPECT_LT(early_f, 1e-4);
  EXPECT_LT(late_f, 1e-5);
  EXPECT_LT(late_f, 1.5 * late_d + 1e-7);
  EXPECT_LT(du_max, 1e-4 * u_max);  // the two commands over the whole run, against its peak
}

TEST(EsoAdrcAttitudeFloat, FailuresAnswerAStatusAndAFiniteSafeCommand) {
  constexpr float kNaNf = std::numeric_limits<float>::quiet_NaN();
  for (auto policy : {adcs::FailurePolicy::safe_command, adcs::FailurePolicy::hold_last}) {
    EsoAdrcAttitude::Params p = params();
    p.on_failure = policy;
    EsoF a(p.cast<float>()), b(p.cast<float>());
    adcs::BodyTorqueT<float> oa, ob;
    for (int k = 0; k < 10; ++k) {
      const EsoF::Input in = to_float(at_angles(Vec3(0.01 - 1e-4 * k, 0.002 * k, -0.003)));
      ASSERT_EQ(a.step(in, oa), Status::ok);
      ASSERT_EQ(b.step(in, ob), Status::ok);
    }
    const Vec3f expected = policy == adcs::FailurePolicy::hold_last ? oa.torque_B_Nm : Vec3f::Zero();
    adcs::BodyTorqueT<float> out;
    EsoF::Input bad = to_float(at_angles(Vec3::Zero()));
    bad.state.theta_BN_rad(1) = kNaNf;
    EXPECT_EQ(a.step(bad, out), Status::non_finite_input);
    EXPECT_EQ(out.torque_B_Nm, expected);
    EXPECT_EQ(a.step(to_float(at_angles(Vec3(0.0, kPi / 2.0, 0.0))), out), Status::singular);  // gimbal lock
    EXPECT_EQ(out.torque_B_Nm, expected);
    bad = to_float(at_angles(Vec3(1e30, 0.0, 0.0)));  // finite in float, but the step overflows
    bad.reference.angles_ddot = Vec3f::Constant(3e38f);
    EXPECT_EQ(a.step(bad, out), Status::out_of_range);
    EXPECT_EQ(out.torque_B_Nm, expected);
    EXPECT_TRUE(out.torque_B_Nm.allFinite());
    for (int k = 10; k < 20; ++k) {  // the observer state is untouched: the twins go on bit for bit
      const EsoF::Input in = to_float(at_angles(Vec3(0.01 - 1e-4 * k, 0.002 * k, -0.003)));
      ASSERT_EQ(a.step(in, oa), Status::ok);
      ASSERT_EQ(b.step(in, ob), Status::ok);
      EXPECT_EQ(std::memcmp(oa.torque_B_Nm.data(), ob.torque_B_Nm.data(), sizeof(float) * 3), 0) << k;
    }
  }
}

TEST(EsoAdrcAttitudeFloat, ParametersBeyondFloatRangeAreRefused) {
  EsoAdrcAttitude::Params p = params();
  p.J_B_kgm2 *= 1e40;  // a valid double inertia that float cannot hold (cast: Inf)
  EXPECT_EQ(EsoAdrcAttitude(p).status(), Status::ok);
  EXPECT_EQ(EsoF(p.cast<float>()).status(), Status::invalid_parameter);
  p = params();
  p.omega_o_rad_s = 1e-39;  // β rounds to 1 in float: l3 = 0, refused instead of a dead observer
  EXPECT_EQ(EsoF(p.cast<float>()).status(), Status::invalid_parameter);
}

}  // namespace

using namespace ADCS_UNITY_ID;  // as an anonymous namespace would (CMakeLists.txt, adcs_unity)
