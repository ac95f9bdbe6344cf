// seed 003 SE(3) tracking laws (spec §A.2.3-§A.6) — sanity checks A.11 #5 (error kinematics
// consistency), #9 (Lyapunov decrease with d = 0, no quantization, no saturation), bad input and
// determinism of both laws.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>

#include "../plant/se3_rk4.hpp"
#include "adcs/control/ftsmc_se3.hpp"
#include "adcs/control/prescribed_time_se3.hpp"
#include "scenarios/seed003_data.hpp"  // seed 003's scenario data (paper data, not flight code)

namespace ADCS_UNITY_ID {
using adcs::Se3DesiredState;
using adcs::Se3ScenarioParams;
using adcs::Se3Spacecraft;
using adcs::Se3SpacecraftState;
using adcs::Se3TrackingError;
using adcs::Status;
using adcs::Vec6;
using adcs::Wrench;
using adcs_test::rk4_step;

// The laws' parameters with the nominal model (truth = nominal) and, for the prescribed-time law,
// ζ = 1.05 ϖ of seed 003's quantizer (the fields with no default).
adcs::PrescribedTimeSe3Params ptc_params(const Se3ScenarioParams& sp) {
  adcs::PrescribedTimeSe3Params p;
  p.zeta = adcs::quantization_compensation_gain(adcs::seed003_quantizer_params());
  p.nominal = adcs::se3_chaser_nominal_params(sp);
  return p;
}
adcs::FtsmcSe3Params ftsmc_params(const Se3ScenarioParams& sp) {
  adcs::FtsmcSe3Params p;
  p.nominal = adcs::se3_chaser_nominal_params(sp);
  return p;
}

struct Pair {
  Se3ScenarioParams sp;
  Se3Spacecraft target{adcs::se3_target_params(sp)};
  Se3Spacecraft chaser{adcs::se3_chaser_nominal_params(sp)};  // truth = nominal: d = 0
  Se3SpacecraftState t, c;
  explicit Pair(int state) {
    EXPECT_EQ(adcs::se3_target_initial_state(sp, t), Status::ok);
    c = adcs::se3_chaser_initial_state(t, adcs::kSe3InitialPoses[static_cast<std::size_t>(state)]);
  }
  Se3TrackingError error() const {
    Se3DesiredState d;
    EXPECT_EQ(adcs::se3_desired_state(target, t, sp, d), Status::ok);
    Se3TrackingError e;
    EXPECT_EQ(adcs::se3_tracking_error(c, d, chaser, e), Status::ok);
    return e;
  }
  Se3DesiredState desired() const {
    Se3DesiredState d;
    EXPECT_EQ(adcs::se3_desired_state(target, t, sp, d), Status::ok);
    return d;
  }
  // What the laws read: the chaser state and the desired state.
  adcs::Se3TrackingInput input() const { return adcs::Se3TrackingInput{c, desired()}; }
  void advance(double dt, const Vec6& u) {
    ASSERT_TRUE(rk4_step(chaser, c, dt, u));
    ASSERT_TRUE(rk4_step(target, t, dt));
  }
};

// A.11 #5: along an uncontrolled trajectory (truth = nominal, no disturbance) the time derivative
// of η is G(η) ξ_e and that of ξ_e is F0 (d = 0, u = 0), by central differences in time.
TEST(Se3TrackingError, ErrorKinematicsAndDynamicsMatchFiniteDifferencesA11_5) {
  Pair p(1);
  p.c.omega_BN_B += adcs::Vec3(1e-3, -2e-3, 1.5e-3);  // a nonzero relative twist
  p.c.v_B += adcs::Vec3(0.02, -0.01, 0.03);
  // dt = 0.05 s: the ECI positions (~7e6 m) leave R_e with ~1e-9 m of rounding, so a smaller
  // step is rounding-limited; the O(dt²) truncation is below 1e-7 relative here.
  const double dt = 0.05;
  for (int k = 0; k < 5; ++k) {
    Pair before = p, after = p;
    after.advance(dt, Vec6::Zero());
    // before: step back by integrating with −dt (RK4 is time-reversible to O(dt⁵)).
    before.advance(-dt, Vec6::Zero());
    const Se3TrackingError e = p.error(), ea = after.error(), eb = before.error();
    const Vec6 eta_dot_fd = (ea.eta - eb.eta) / (2.0 * dt);
    const Vec6 xi_e_dot_fd = (ea.xi_e - eb.xi_e) / (2.0 * dt);
    EXPECT_LT((eta_dot_fd - e.eta_dot).norm(), 1e-6 * e.eta_dot.norm()) << k;
    // Rotation: to 1e-6 relative. Translation: F0_v (~1e-4 m/s²) is the difference of two ~8.4 m/s²
    // gravity accelerations along trajectories at 7.6 km/s; the finite difference of v_e carries
    // ~1e-10 of g in rounding (measured 7e-10 m/s², independent of dt and of J2), so the bound is
    // 1e-6 relative plus 1e-9·μ/r².
    const double g_local = p.sp.env.mu / p.c.R_N.squaredNorm();
    EXPECT_LT((xi_e_dot_fd - e.F0).head<3>().norm(), 1e-6 * e.F0.head<3>().norm()) << k;
    EXPECT_LT((xi_e_dot_fd - e.F0).tail<3>().norm(), 1e-6 * e.F0.tail<3>().norm() + 1e-9 * g_local) << k;
    p.advance(2.0, Vec6::Zero());
  }
}

// A.11 #9: with d = 0, no quantization and no saturation, from a small initial error, the law's
// V = ½‖z1‖² + ½‖z2‖² + ψ̂²/(2γ) (ψ = 0) decreases at every tick, and ψ̂ stays ≥ 0.
TEST(PrescribedTimeSe3, LyapunovFunctionDecreasesWithoutDisturbanceA11_9) {
  Pair p(0);
  // Small initial error: the desired pose plus 0.02 rad and 0.5 m.
  const Se3DesiredState d0 = p.desired();
  p.c.C_NB = d0.C_ND * adcs::so3_exp(adcs::Vec3(0.02, -0.01, 0.015));
  p.c.R_N = d0.R_N + d0.C_ND * adcs::Vec3(0.5, -0.3, 0.2);
  p.c.omega_BN_B = p.c.C_NB.transpose() * d0.C_ND * d0.omega_DN_D;
  p.c.v_B = p.c.C_NB.transpose() * (d0.C_ND * d0.v_D + (d0.C_ND * d0.omega_DN_D).cross(p.c.R_N - d0.R_N));
  adcs::PrescribedTimeSe3Params gains = ptc_params(p.sp);
  gains.zeta.setZero();  // Δq = 0: no quantizer, no compensation
  adcs::PrescribedTimeSe3 law(gains);
  ASSERT_EQ(law.status(), Status::ok);
  double V_prev = INFINITY;
  for (int k = 0; k < 400; ++k) {
    Wrench u;
    const double psi_before = law.psi_hat();
    ASSERT_EQ(law.step(p.input(), u), Status::ok);
    const adcs::PrescribedTimeSe3Terms& t = law.terms();
    const double V = 0.5 * t.z1.squaredNorm() + 0.5 * t.z2.squaredNorm() + psi_before * psi_before / (2.0 * gains.gamma);
    EXPECT_LE(V, V_prev * (1.0 + 1e-12)) << k;
    EXPECT_GE(law.psi_hat(), 0.0);
    V_prev = V;
    for (int j = 0; j < 10; ++j) p.advance(gains.period_s / 10.0, u.stacked());
  }
  EXPECT_LT(p.error().eta.norm(), 1e-4);
}

TEST(Se3Laws, BadInputHoldsTheCommandUnderHoldLastAndTheEstimate) {
  Pair p(0);
  adcs::PrescribedTimeSe3Params pp = ptc_params(p.sp);
  pp.on_failure = adcs::FailurePolicy::hold_last;
  adcs::FtsmcSe3Params fp = ftsmc_params(p.sp);
  fp.on_failure = adcs::FailurePolicy::hold_last;
  adcs::PrescribedTimeSe3 ptc(pp);
  adcs::FtsmcSe3 fts(fp);
  Wrench u_ptc, u_fts;
  ASSERT_EQ(ptc.step(p.input(), u_ptc), Status::ok);
  ASSERT_EQ(fts.step(p.input(), u_fts), Status::ok);
  const double psi = ptc.psi_hat();
  adcs::Se3TrackingInput bad = p.input();
  bad.state.v_B(1) = std::numeric_limits<double>::quiet_NaN();
  Wrench u;
  EXPECT_EQ(ptc.step(bad, u), Status::non_finite_input);
  EXPECT_EQ(u.stacked(), u_ptc.stacked());
  EXPECT_EQ(ptc.psi_hat(), psi);
  EXPECT_EQ(fts.step(bad, u), Status::non_finite_input);
  EXPECT_EQ(u.stacked(), u_fts.stacked());
  bad = p.input();
  bad.state.R_N.setZero();  // at the Earth's centre: gravity undefined
  EXPECT_EQ(ptc.step(bad, u), Status::out_of_range);
  EXPECT_EQ(ptc.psi_hat(), psi);
  adcs::PrescribedTimeSe3Params wrong = ptc_params(p.sp);
  wrong.T = 0.0;
  EXPECT_EQ(adcs::PrescribedTimeSe3(wrong).status(), Status::invalid_parameter);
  adcs::FtsmcSe3Params wrong_f = ftsmc_params(p.sp);
  wrong_f.phi = 0.0;
  EXPECT_EQ(adcs::FtsmcSe3(wrong_f).status(), Status::invalid_parameter);
  // Determinism: a second instance gives the same bits.
  adcs::PrescribedTimeSe3 ptc2(ptc_params(p.sp));
  Wrench u2;
  ASSERT_EQ(ptc2.step(p.input(), u2), Status::ok);
  const Vec6 u2_stacked = u2.stacked(), u_ptc_stacked = u_ptc.stacked();
  EXPECT_EQ(std::memcmp(u2_stacked.data(), u_ptc_stacked.data(), sizeof(double) * 6), 0);
}

// FTSMC drives the sliding variable and the error to zero (d = 0, no saturation).
TEST(FtsmcSe3, SlidingVariableAndErrorConverge) {
  Pair p(0);
  const Se3DesiredState d0 = p.desired();
  p.c.C_NB = d0.C_ND * adcs::so3_exp(adcs::Vec3(0.05, 0.02, -0.03));
  p.c.R_N = d0.R_N + d0.C_ND * adcs::Vec3(1.0, -0.5, 0.3);
  adcs::FtsmcSe3 law(ftsmc_params(p.sp));
  Wrench u;
  for (int k = 0; k < 1600; ++k) {
    ASSERT_EQ(law.step(p.input(), u), Status::ok);
    for (int j = 0; j < 10; ++j) p.advance(0.0125, u.stacked());
  }
  EXPECT_LT(law.sliding_variable().norm(), 1e-4);
  EXPECT_LT(p.error().eta.norm(), 1e-4);
}

}  // namespace

using namespace ADCS_UNITY_ID;  // as an anonymous namespace would (CMakeLists.txt, adcs_unity)
