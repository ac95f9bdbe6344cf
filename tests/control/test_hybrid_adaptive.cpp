// seed 001 controller algebra (spec §A.3) on the controller-model plant TP-CTRL:
// S7 (K, P), S8 (parameterisation exactness), S10 (exact linear error dynamics with the true Θ),
// S14 (no deviations, no adaptation: e ≡ 0), bad input, reset, determinism.
#include <gtest/gtest.h>

#include <unsupported/Eigen/MatrixFunctions>

#include <cstring>
#include <limits>

#include "adcs/control/hybrid_adaptive.hpp"
#include "adcs/plant/vscmg_configurations.hpp"
#include "tp_ctrl_rk4.hpp"

namespace ADCS_UNITY_ID {
using Ctrl = adcs::HybridAdaptive<4, 3>;
using Plant = adcs::VscmgCtrlPlant<4, 3>;
using adcs::Status;
using adcs::Vec3;
using adcs::Vec6;

Ctrl::Params controller_params(double alpha_F = 1e7, double alpha_G = 1e3) {
  Ctrl::Params p;
  p.nominal = adcs::pyramid_4cmg_3rw_nominal();
  p.alpha_F = alpha_F;
  p.alpha_G = alpha_G;
  return p;
}

// The law's input at the plant state x (exact measurements) with the reference r.
Ctrl::Input measure(const Plant::State& x, const adcs::MrpReferenceSample& r = adcs::MrpReferenceSample{}) {
  Ctrl::Input in;
  in.state.sigma_BN = Plant::sigma_BN(x);
  in.state.omega_BN_B = Plant::omega_BN_B(x);
  in.actuators.gamma_rad = Plant::gamma(x);
  in.actuators.Omega_rad_s = Plant::Omega_w(x);
  in.reference = r;
  return in;
}

// Closed loop on TP-CTRL: controller at 1 ms with ZOH, plant and σ_d by RK4 (1 ms).
struct Loop {
  Plant plant;
  Ctrl ctrl;
  adcs::SinusoidalRateReference ref;
  Plant::State x;
  Vec3 sigma_d = Vec3::Zero();
  double t = 0.0;
  int nonok = 0;

  Loop(const adcs::VscmgParams<4, 3>& pp, const Ctrl::Params& cp, const Plant::State& x0)
      : plant(pp), ctrl(cp), x(x0) {}

  Vec6 error() const {
    Vec6 e;
    const Vec3 s = Plant::sigma_BN(x);
    e << s - sigma_d,
        adcs::mrp_G(s) * Plant::omega_BN_B(x) - ref.sigma_dot(t, sigma_d);
    return e;
  }

  void run(double duration, double h = 1e-3) {
    const int n = static_cast<int>(std::lround(duration / h));
    const double t0 = t;
    for (int k = 0; k < n; ++k) {
      Ctrl::Output c;
      if (ctrl.step(measure(x, ref.sample(t, sigma_d)), c) != Status::ok) ++nonok;
      adcs_test::tp_ctrl_rk4_step(plant, ref, t, h, c.stacked(), x, sigma_d);  // RK4 of [x; σ_d], u held
      t = t0 + (k + 1) * h;
    }
  }
};

// Θ̂ = the true Θ for D1, and Θ̂_F = H_I,true − H_I^n.
void set_true_estimates(Ctrl& c, const Plant& plant, const Plant::State& x0, const Vec3& H_n) {
  const adcs::VscmgDeviation<4, 3> d = adcs::deviation_set_D1();
  adcs::Mat<6, 4> th_c;
  adcs::Mat<3, 3> th_w;
  for (int i = 0; i < 4; ++i) th_c.col(i) = d.theta_cG(i);
  for (int j = 0; j < 3; ++j) th_w.col(j) = d.theta_wG(j);
  ASSERT_EQ(c.set_estimates(Vec3(plant.momentum_N(x0) - H_n), th_c, th_w), Status::ok);
}

TEST(HybridAdaptive, GainsAndLyapunovMatrixS7) {
  const Ctrl c(controller_params());
  ASSERT_EQ(c.status(), Status::ok);
  const Vec3 kp(0.08, 0.18, 0.12), kd(0.4, 0.6, 0.5 * std::sqrt(2.0));
  EXPECT_LT((c.K().leftCols<3>().diagonal() - kp).norm(), 1e-14);
  EXPECT_LT((c.K().rightCols<3>().diagonal() - kd).norm(), 1e-14);
  for (int i = 0; i < 3; ++i) {  // spec §A.3 closed form
    EXPECT_NEAR(c.P()(i + 3, i), 1.0 / (2 * kp(i)), 1e-12);
    EXPECT_NEAR(c.P()(i + 3, i + 3), (1 + kp(i)) / (2 * kp(i) * kd(i)), 1e-12);
    EXPECT_NEAR(c.P()(i, i), (1 + kp(i)) / (2 * kd(i)) + kd(i) / (2 * kp(i)), 1e-12);
  }
  const adcs::Mat6 A1 = adcs::double_integrator_closed_loop<3>(c.K());
  EXPECT_LT((A1.transpose() * c.P() + c.P() * A1 + adcs::Mat6::Identity()).norm(), 1e-12);
  EXPECT_NEAR(c.J_n()(0, 0), 120.0613, 1e-4);
}

// Gains designed on the ground (HybridAdaptive(params, gains)): the designed table gives the same
// law bit for bit; a table that does not belong to Q_L, is not SPD, destabilises A_1 or is not
// finite is refused with the failure command.
TEST(HybridAdaptive, GroundDesignedGainsAreCheckedAndGiveTheSameLaw) {
  const Ctrl::Params p = controller_params();
  adcs::HybridAdaptiveGains<double> g;
  ASSERT_EQ(adcs::design_hybrid_adaptive_gains(p.poles, p.Q_L, g), Status::ok);
  Ctrl a(p), b(p, g);
  ASSERT_EQ(b.status(), Status::ok);
  EXPECT_EQ(a.K(), b.K());
  EXPECT_EQ(a.P(), b.P());
  EXPECT_EQ(a.J_n(), b.J_n());
  Ctrl::Input in;
  in.state.sigma_BN << 0.01, 0.02, -0.01;
  in.state.omega_BN_B << 1e-3, -2e-3, 5e-4;
  in.actuators.gamma_rad << 0.1, -0.2, 0.05, 0.0;
  for (int k = 0; k < 20; ++k) {
    Ctrl::Output ua, ub;
    ASSERT_EQ(a.step(in, ua), Status::ok);
    ASSERT_EQ(b.step(in, ub), Status::ok);
    const adcs::Vec<7> sa = ua.stacked(), sb = ub.stacked();
    ASSERT_EQ(std::memcmp(sa.data(), sb.data(), sizeof(double) * 7), 0);
  }
  EXPECT_EQ(a.theta_F(), b.theta_F());

  auto refused = [&](const adcs::HybridAdaptiveGains<double>& bad, const Ctrl::Params& q) {
    Ctrl c(q, bad);
    Ctrl::Output u;
    u.gamma_dot_rad_s.setConstant(1.0);
    return c.status() == Status::invalid_parameter && c.step(in, u) == Status::invalid_parameter &&
           u.stacked().isZero(0.0);
  };
  EXPECT_TRUE(refused(adcs::HybridAdaptiveGains<double>{}, p));  // no default: NaN
  adcs::HybridAdaptiveGains<double> bad = g;
  bad.P(0, 0) *= 1.001;  // P no longer solves the Lyapunov equation of this K and Q_L
  EXPECT_TRUE(refused(bad, p));
  bad = g;
  bad.P(0, 3) += 1e-3;  // asymmetric
  EXPECT_TRUE(refused(bad, p));
  bad = g;
  bad.K *= -1.0;  // A_1 unstable: the Lyapunov equation then has P negative definite
  bad.P *= -1.0;
  EXPECT_TRUE(refused(bad, p));
  bad = g;
  bad.K(1, 4) = std::numeric_limits<double>::infinity();
  EXPECT_TRUE(refused(bad, p));
  Ctrl::Params q = p;
  q.Q_L *= 2.0;  // the table was designed for another Q_L
  EXPECT_TRUE(refused(g, q));
  // The ground design refuses what the parameter constructor refuses: unstable poles, Q_L not SPD.
  adcs::HybridAdaptiveGains<double> untouched;
  q = p;
  q.poles[0][0] = {0.2, 0.2};
  q.poles[0][1] = {0.2, -0.2};
  EXPECT_EQ(adcs::design_hybrid_adaptive_gains(q.poles, q.Q_L, untouched), Status::invalid_parameter);
  q = p;
  q.Q_L(5, 5) = -1.0;
  EXPECT_EQ(adcs::design_hybrid_adaptive_gains(q.poles, q.Q_L, untouched), Status::invalid_parameter);
  EXPECT_TRUE(untouched.K.array().isNaN().all());
}

TEST(HybridAdaptive, ParameterisationIsExactS8) {
  const adcs::VscmgParams<4, 3> pp = adcs::vscmg_params_A_REF();
  const Plant plant(pp);
  Ctrl c(controller_params());
  set_true_estimates(c, plant, Plant::State::Zero(), Vec3::Zero());
  std::srand(3);
  for (int k = 0; k < 20; ++k) {
    Ctrl::Input in;
    in.state.sigma_BN = 0.5 * Vec3::Random();
    in.state.omega_BN_B = 0.02 * Vec3::Random();
    in.actuators.gamma_rad = adcs::Vec<4>::Random() * 3.0;
    Ctrl::Diagnostics d;
    Ctrl::Output out;
    Ctrl c2 = c;  // keep the estimates exact for every sample
    ASSERT_TRUE(adcs::usable(c2.step(in, out, &d)));
    const adcs::Mat<3, 7> X_true = -adcs::mrp_G(in.state.sigma_BN) * plant.J_n().inverse() *
                                   pp.truth.Q_act(in.actuators.gamma_rad);
    EXPECT_LT((d.X - X_true).norm(), 1e-13 * X_true.norm()) << k;
  }
}

TEST(HybridAdaptive, OracleErrorDynamicsAreExactlyLinearS10) {
  const adcs::VscmgParams<4, 3> pp = adcs::vscmg_params_A_REF();
  Plant::State x0 = Plant::State::Zero();
  x0.head<3>() << 0.01, -0.02, 0.015;
  Loop loop(pp, controller_params(0.0, 0.0), x0);
  set_true_estimates(loop.ctrl, loop.plant, x0, Vec3::Zero());
  const Vec6 e0 = loop.error();
  const adcs::Mat6 A1 = adcs::double_integrator_closed_loop<3>(loop.ctrl.K());
  for (double t_check : {5.0, 10.0, 20.0}) {
    loop.run(t_check - loop.t);
    const Vec6 expected = (A1 * t_check).exp() * e0;
    // The law is continuous-time; ZOH at 1 ms leaves an O(T) deviation (measured ~9e-5·|e0|).
    EXPECT_LT((loop.error() - expected).norm(), 2e-4 * e0.norm()) << t_check;
  }
  EXPECT_EQ(loop.nonok, 0);
}

TEST(HybridAdaptive, NoDeviationNoAdaptationTracksExactlyS14) {
  // Spec S14: |e| < 1e-12 for the continuous law. Sampled at T with ZOH the residual is O(T):
  // check it is small at 1 ms and halves with T (so it is the sampling, not the algebra).
  adcs::VscmgParams<4, 3> pp;
  pp.nominal = adcs::pyramid_4cmg_3rw_nominal();
  pp.truth = pp.nominal;
  double e_at[2] = {0.0, 0.0};
  for (int k = 0; k < 2; ++k) {
    const double T = k == 0 ? 1e-3 : 5e-4;
    Ctrl::Params cp = controller_params(0.0, 0.0);
    cp.period_s = T;
    Loop loop(pp, cp, Plant::State::Zero());
    loop.run(50.0, T);
    e_at[k] = loop.error().norm();
    EXPECT_EQ(loop.nonok, 0);
  }
  EXPECT_LT(e_at[0], 5e-9);  // measured 3.6e-9 after 50 s
  EXPECT_NEAR(e_at[0] / e_at[1], 2.0, 0.2);
}

TEST(HybridAdaptive, CommandsArePhysicalRatesAndAccelerationsS15) {
  // Spec S15: u_1..4 in rad/s, u_5..7 in rad/s², not normalised. (a) X's columns are
  // −h_cw,i G J⁻¹ t_i [1/s per rad/s] and −I_ws,j G J⁻¹ s_wj [1/s² per rad/s²]; (b) the command,
  // applied to the SI plant, produces exactly the σ̈ the law asked for; (c) ten times the rotor
  // momentum and wheel inertia needs a tenth of the rates and accelerations.
  adcs::VscmgParams<4, 3> pp;
  pp.nominal = adcs::pyramid_4cmg_3rw_nominal();
  pp.truth = pp.nominal;
  const Plant plant(pp);
  Ctrl::Params cp = controller_params(0.0, 0.0);
  Plant::State x = Plant::State::Zero();
  x.head<3>() << 0.1, -0.2, 0.05;
  x.segment<3>(3) << 0.01, -0.02, 0.005;
  x.segment<4>(6) << 0.3, -0.1, 0.2, 0.4;
  cp.H_I_n = plant.momentum_N(x);
  Ctrl c(cp);
  adcs::MrpReferenceSample r;
  r.sigma_ddot << 1e-4, -2e-4, 3e-4;
  const Ctrl::Input in = measure(x, r);
  const Vec3& sigma = in.state.sigma_BN;
  const Vec3& omega = in.state.omega_BN_B;
  Ctrl::Output out;
  Ctrl::Diagnostics d;
  ASSERT_EQ(c.step(in, out, &d), Status::ok);

  const adcs::Mat3 GJ = adcs::mrp_G(sigma) * c.J_n().inverse();
  const adcs::Mat<3, 4> T = pp.nominal.A_ct(in.actuators.gamma_rad);
  for (int i = 0; i < 4; ++i)
    EXPECT_LT((d.X.col(i) + pp.nominal.h_cw(i) * GJ * T.col(i)).norm(), 1e-15) << i;
  for (int j = 0; j < 3; ++j)
    EXPECT_LT((d.X.col(4 + j) + pp.nominal.I_wws(j) * GJ * pp.nominal.A_ws.col(j)).norm(), 1e-15) << j;

  Plant::State dx;
  plant.derivative(0.0, x, out.stacked(), dx);
  const Vec3 sigma_dot = adcs::mrp_G(sigma) * omega;
  const Vec3 sigma_ddot = adcs::mrp_G_dot(sigma, sigma_dot) * omega + adcs::mrp_G(sigma) * dx.segment<3>(3);
  const Vec3 asked = -c.K() * d.e + r.sigma_ddot;  // eq. (24) with the exact model
  EXPECT_LT((sigma_ddot - asked).norm(), 1e-12 * asked.norm());

  Ctrl::Params cp10 = cp;
  cp10.nominal.h_cw *= 10.0;
  cp10.nominal.I_wws *= 10.0;
  cp10.nominal.J_s -= 9.0 * 0.02 * adcs::Mat3::Identity();  // keep J_n: the wheels are on the axes
  Ctrl c10(cp10);
  ASSERT_NEAR((c10.J_n() - c.J_n()).norm(), 0.0, 1e-12);
  Ctrl::Output out10;
  ASSERT_EQ(c10.step(in, out10), Status::ok);
  EXPECT_LT((10.0 * out10.stacked() - out.stacked()).norm(), 1e-12 * out.stacked().norm());
}

TEST(HybridAdaptive, NormalizedStepIsThePaperLawWhenTheLoopGainIsSmall) {
  // adapt/normalized_step.hpp: the scale is 1/(1 + λ/λ_max) with λ = T α ‖Y‖² ‖P22‖; with a
  // tiny T the normalized and explicit updates agree to O(λ/λ_max); with a huge one the step of
  // Θ̂_F shrinks to about λ_max/λ of the explicit step, never changing its direction.
  EXPECT_EQ(adcs::normalized_step_scale(0.0, 0.2), 1.0);
  EXPECT_DOUBLE_EQ(adcs::normalized_step_scale(0.2, 0.2), 0.5);
  EXPECT_EQ(adcs::normalized_step_scale(1.0, 0.0), 1.0);  // invalid limit: no scaling
  EXPECT_EQ(adcs::normalized_step_scale(std::numeric_limits<double>::infinity(), 0.2), 0.0);
  Ctrl::Params bad = controller_params();
  bad.max_step_gain = 0.0;
  EXPECT_EQ(Ctrl(bad).status(), Status::invalid_parameter);

  Ctrl::Input in;
  in.state.sigma_BN << 0.8, -0.5, 0.3;
  in.state.omega_BN_B << 0.03, -0.02, 0.04;
  in.actuators.gamma_rad << 0.1, 0.2, -0.3, 0.4;
  in.reference.sigma << 0.79, -0.49, 0.31;
  for (double T : {1e-6, 10.0}) {
    Ctrl::Params pe = controller_params();
    pe.period_s = T;
    Ctrl::Params pn = pe;
    pn.adaptation_step = adcs::AdaptationStep::normalized;
    Ctrl ce(pe), cn(pn);
    Ctrl::Output oe, on;
    Ctrl::Diagnostics dn;
    ASSERT_TRUE(adcs::usable(ce.step(in, oe)));
    ASSERT_TRUE(adcs::usable(cn.step(in, on, &dn)));
    EXPECT_EQ(oe.stacked(), on.stacked());  // the command uses the estimates before the update
    const Vec3 de = ce.theta_F(), dn_F = cn.theta_F();
    ASSERT_GT(de.norm(), 0.0);
    EXPECT_NEAR(dn_F.dot(de) / (dn_F.norm() * de.norm()), 1.0, 1e-12);  // same direction
    EXPECT_NEAR(dn_F.norm() / de.norm(), dn.theta_F_step_scale, 1e-12);
    if (T < 1e-3)
      EXPECT_GT(dn.theta_F_step_scale, 0.999);
    else
      EXPECT_LT(dn.theta_F_step_scale, 1e-2);
  }
}

TEST(HybridAdaptive, AdaptationReducesTrackingErrorOnTpCtrl) {
  const adcs::VscmgParams<4, 3> pp = adcs::vscmg_params_A_REF();
  Loop fixed(pp, controller_params(0.0, 0.0), Plant::State::Zero());
  Loop adaptive(pp, controller_params(), Plant::State::Zero());
  double e_fixed = 0.0, e_adapt = 0.0;
  for (int k = 0; k < 30; ++k) {  // 300 s, error max over [100, 300] s
    fixed.run(10.0);
    adaptive.run(10.0);
    if (fixed.t >= 100.0) {
      e_fixed = std::max(e_fixed, fixed.error().head<3>().norm());
      e_adapt = std::max(e_adapt, adaptive.error().head<3>().norm());
    }
  }
  EXPECT_LT(e_adapt, e_fixed);
  EXPECT_EQ(adaptive.ctrl.safeguard_count(), 0u);
  for (int i = 0; i < 4; ++i) EXPECT_LE(adaptive.ctrl.theta_cG(i).squaredNorm(), 0.15 + 1e-9);
  EXPECT_NE(adaptive.ctrl.theta_F(), Vec3::Zero());
}

// Spec S12: with adaptation and the projection inactive, V = ½eᵀPe + |Θ̃_F|²/(2α_F) +
// Σ|Θ̃_Gk|²/(2α_G) is non-increasing with dV/dt = −½eᵀe (continuous law; here sampled at 1 ms).
TEST(HybridAdaptive, LyapunovFunctionDecreasesS12) {
  const adcs::VscmgParams<4, 3> pp = adcs::vscmg_params_A_REF();
  Plant::State x0 = Plant::State::Zero();
  x0.head<3>() << 0.01, -0.02, 0.015;
  const Ctrl::Params cp = controller_params();
  Loop loop(pp, cp, x0);
  const Vec3 H_true = loop.plant.momentum_N(x0);
  const adcs::VscmgDeviation<4, 3> d = adcs::deviation_set_D1();
  auto V = [&]() {
    const Vec6 e = loop.error();
    double v = 0.5 * e.dot(loop.ctrl.P() * e) +
               (H_true - loop.ctrl.theta_F()).squaredNorm() / (2.0 * cp.alpha_F);
    for (int i = 0; i < 4; ++i) v += (d.theta_cG(i) - loop.ctrl.theta_cG(i)).squaredNorm() / (2.0 * cp.alpha_G);
    for (int j = 0; j < 3; ++j) v += (d.theta_wG(j) - loop.ctrl.theta_wG(j)).squaredNorm() / (2.0 * cp.alpha_G);
    return v;
  };
  const double v0 = V();
  double v_prev = v0, total = 0.0;
  for (int k = 0; k < 60; ++k) {  // 60 s in 1 s slices; ∫½eᵀe by the trapezoid rule per 10 ms
    double integral = 0.0;
    double q_prev = 0.5 * loop.error().squaredNorm();
    for (int m = 0; m < 100; ++m) {
      loop.run(0.01);
      const double q = 0.5 * loop.error().squaredNorm();
      integral += 0.5 * (q + q_prev) * 0.01;
      q_prev = q;
    }
    const double v = V();
    EXPECT_LE(v, v_prev) << "t = " << loop.t;  // non-increasing, slice by slice
    total += integral;
    v_prev = v;
  }
  // V(0) − V(60) = ∫½eᵀe dt. Sampling (ZOH, Euler-integrated estimates) adds an O(T) excess
  // decrease that is visible only once e is tiny; over the run it stays within 2%.
  EXPECT_NEAR(v0 - v_prev, total, 0.02 * total);
  EXPECT_EQ(loop.ctrl.safeguard_count(), 0u);
}

TEST(HybridAdaptive, BadInputHoldsCommandUnderHoldLastAndEstimates) {
  Ctrl::Params params = controller_params();
  params.on_failure = adcs::FailurePolicy::hold_last;  // default zero: test_failure_policy.cpp
  Ctrl c(params);
  Ctrl::Input in;
  in.state.sigma_BN << 0.01, 0.02, -0.01;
  in.state.omega_BN_B << 1e-3, -2e-3, 5e-4;
  Ctrl::Output good, out;
  ASSERT_EQ(c.step(in, good), Status::ok);
  const Vec3 thF = c.theta_F();
  const Vec6 thc = c.theta_cG(2);
  for (double bad : {std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity()}) {
    Ctrl::Input mb = in;
    mb.actuators.gamma_rad(1) = bad;
    EXPECT_EQ(c.step(mb, out), Status::non_finite_input);
    EXPECT_EQ(out.stacked(), good.stacked());
    Ctrl::Input rb = in;
    rb.reference.sigma_ddot(2) = bad;
    EXPECT_EQ(c.step(rb, out), Status::non_finite_input);
    EXPECT_EQ(out.stacked(), good.stacked());
  }
  EXPECT_EQ(c.theta_F(), thF);
  EXPECT_EQ(c.theta_cG(2), thc);
  // Estimates outside the invariant ball are refused.
  EXPECT_EQ(c.set_estimates(Vec3::Zero(), adcs::Mat<6, 4>::Constant(0.5), adcs::Mat3::Zero()),
            Status::out_of_range);
  EXPECT_EQ(c.theta_F(), thF);
  // Invalid parameters: every step says so and the output stays finite (zero).
  Ctrl::Params bad = controller_params();
  bad.delta_G = 0.0;
  Ctrl cb(bad);
  EXPECT_EQ(cb.status(), Status::invalid_parameter);
  EXPECT_EQ(cb.step(in, out), Status::invalid_parameter);
  EXPECT_EQ(out.stacked(), adcs::Vec<7>::Zero());
}

TEST(HybridAdaptive, ResetRestoresInitialBehaviourBitForBit) {
  Ctrl a(controller_params());
  Ctrl::Input in;
  in.state.sigma_BN << 0.01, 0.02, -0.01;
  in.state.omega_BN_B << 1e-3, -2e-3, 5e-4;
  in.actuators.gamma_rad << 0.1, -0.2, 0.05, 0.0;
  Ctrl::Output first, again;
  ASSERT_EQ(a.step(in, first), Status::ok);
  for (int k = 0; k < 10; ++k) ASSERT_EQ(a.step(in, again), Status::ok);
  EXPECT_NE(a.theta_F(), Vec3::Zero());
  a.reset();
  EXPECT_EQ(a.theta_F(), Vec3::Zero());
  ASSERT_EQ(a.step(in, again), Status::ok);
  const adcs::Vec<7> u_first = first.stacked(), u_again = again.stacked();
  EXPECT_EQ(std::memcmp(u_first.data(), u_again.data(), sizeof(double) * 7), 0);
}
// FDIR fallback: a failed gimbal gets exactly 0 (also in the held command), its Θ̂_G block stops
// adapting, the others keep tracking; a bad mask is refused and changes nothing.
TEST(HybridAdaptive, FailedActuatorIsNeverCommandedAndTrackingContinues) {
  const adcs::VscmgParams<4, 3> pp = adcs::vscmg_params_A_REF();
  Loop loop(pp, controller_params(), Plant::State::Zero());
  loop.run(5.0);
  const adcs::ActuatorMask stuck = adcs::all_actuators<7>() & ~(1u << 2);  // gimbal 3
  EXPECT_EQ(loop.ctrl.set_available(1u << 9), Status::out_of_range);
  EXPECT_EQ(loop.ctrl.available(), adcs::all_actuators<7>());
  ASSERT_EQ(loop.ctrl.set_available(stuck), Status::ok);
  const Vec6 theta_c3 = loop.ctrl.theta_cG(2);
  // A rejected step right after the mask holds a command whose failed entry is already 0.
  Ctrl::Input bad;
  bad.state.sigma_BN(0) = std::numeric_limits<double>::quiet_NaN();
  Ctrl::Output held;
  EXPECT_EQ(loop.ctrl.step(bad, held), Status::non_finite_input);
  EXPECT_EQ(held.gamma_dot_rad_s(2), 0.0);
  loop.run(20.0);
  EXPECT_EQ(loop.nonok, 0);
  EXPECT_EQ(loop.ctrl.theta_cG(2), theta_c3);  // no regressor for an actuator that never moves
  Ctrl::Output c;
  ASSERT_EQ(loop.ctrl.step(measure(loop.x, loop.ref.sample(loop.t, loop.sigma_d)), c), Status::ok);
  EXPECT_EQ(c.gamma_dot_rad_s(2), 0.0);
  EXPECT_NE(c.gamma_dot_rad_s(3), 0.0);
  EXPECT_LT(loop.error().head<3>().norm(), 1e-3);  // still tracking on the other six actuators
}

}  // namespace

using namespace ADCS_UNITY_ID;  // as an anonymous namespace would (CMakeLists.txt, adcs_unity)
