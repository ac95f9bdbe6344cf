// The C interface (include/adcs/c/adcs.h) from the caller's side: the promised status values,
// the refusals (NULL, a state init never wrote, a refused parameter set, an unknown failure
// policy), the failure commands after bad input (zero torque, or the last good command under
// hold_last; the wheels coast), re-init, equality with the C++ components bit for bit, and no
// heap in any step. src/c/adcs_c.cpp is compiled into this executable (tests/CMakeLists.txt) so
// that Eigen's runtime allocation check is armed in it too.
#ifdef NDEBUG
#error "the C interface test must build with asserts on (EIGEN_RUNTIME_NO_MALLOC needs them)"
#endif
#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <cstring>
#include <limits>
#include <type_traits>

#include "adcs/actuator/rw_allocation.hpp"
#include "adcs/c/adcs.h"
#include "adcs/control/adrc.hpp"
#include "adcs/control/hybrid_adaptive.hpp"
#include "adcs/control/mrp_pd.hpp"
#include "adcs/control/ppc_neural.hpp"
#include "adcs/control/prescribed_time_se3.hpp"
#include "adcs/plant/flexible_configurations.hpp"
#include "adcs/plant/vscmg_configurations.hpp"
#include "adcs/reference/sinusoidal_euler.hpp"
#include "adcs/reference/sinusoidal_rate.hpp"
#include "scenarios/seed003_data.hpp"  // seed 003's scenario data (paper data, not flight code)
#include "alloc_guard.hpp"  // tests/nomalloc
#include "counting_new.hpp"

namespace ADCS_UNITY_ID {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// A 4-wheel pyramid and the cubesat's gains (examples/c/cfs_app.c).
template <class P>
void fill_axes(P& p) {
  const double s = 1.0 / std::sqrt(3.0);
  const double G[3][4] = {{1, 0, 0, s}, {0, 1, 0, s}, {0, 0, 1, s}};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 4; ++j) p.G_s_B[i][j] = static_cast<decltype(p.G_s_B[0][0] + 0)>(G[i][j]);
}

template <class P>
P law_params() {
  P p{};
  using T = decltype(p.K + 0);
  p.K = T(0.04);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      p.P[i][j] = T(i == j ? 0.05 : 0.0);
      p.J_rw_B[i][j] = T(i == j ? 0.2 + 0.01 * i : 0.0);
    }
  fill_axes(p);
  for (int j = 0; j < 4; ++j) p.J_s[j] = T(2e-5);
  p.period_s = T(0.1);
  p.on_failure = ADCS_FAILURE_SAFE_COMMAND;
  return p;
}

template <class I>
I law_input(int k) {
  I in{};
  using T = decltype(in.sigma_BN[0] + 0);
  const double s[3] = {0.1 + 1e-3 * k, -0.2, 0.3}, w[3] = {0.01, 0.0, -0.02}, r[3] = {0.0, 0.1, 0.0};
  for (int i = 0; i < 3; ++i) {
    in.sigma_BN[i] = T(s[i]);
    in.omega_BN_B[i] = T(w[i]);
    in.sigma_RN[i] = T(r[i]);
    in.omega_RN_N[i] = T(i == 2 ? 1e-3 : 0.0);
    in.domega_RN_N[i] = T(0);
  }
  for (int j = 0; j < 4; ++j) in.Omega_rad_s[j] = T(10.0 * (j + 1));
  return in;
}

TEST(CInterface, StatusValuesAndNamesAreThePromisedOnes) {
  const adcs_status all[] = {ADCS_STATUS_OK, ADCS_STATUS_NON_FINITE_INPUT, ADCS_STATUS_OUT_OF_RANGE,
                             ADCS_STATUS_SINGULAR, ADCS_STATUS_ILL_CONDITIONED, ADCS_STATUS_CONSTRAINT_VIOLATED,
                             ADCS_STATUS_SATURATED, ADCS_STATUS_NOT_CONVERGED, ADCS_STATUS_INVALID_PARAMETER,
                             ADCS_STATUS_REQUEST_NOT_MET};
  for (int v = 0; v < 10; ++v) {
    EXPECT_EQ(all[v], v);
    const auto s = static_cast<adcs::Status>(v);
    EXPECT_STREQ(adcs_status_name(v), adcs::to_string(s));
    EXPECT_EQ(adcs_status_usable(v) != 0, adcs::usable(s));
  }
  EXPECT_STREQ(adcs_status_name(-1), "unknown");
  EXPECT_STREQ(adcs_status_name(10), "unknown");
  EXPECT_EQ(adcs_status_usable(-1), 0);
  EXPECT_EQ(adcs_status_usable(1000), 0);
}

TEST(CInterface, NullPointersAndUninitialisedStatesAreRefusedAndWriteNothing) {
  static adcs_mrp_pd4_state never;  // static: zero, init never ran
  const adcs_mrp_pd4_params p = law_params<adcs_mrp_pd4_params>();
  const adcs_mrp_pd4_input in = law_input<adcs_mrp_pd4_input>(0);
  adcs_mrp_pd4_output out = {{7.0, 8.0, 9.0}};
  EXPECT_EQ(adcs_mrp_pd4_step(&never, &in, &out), ADCS_STATUS_INVALID_PARAMETER);
  EXPECT_EQ(out.torque_B_Nm[0], 7.0);
  EXPECT_EQ(adcs_mrp_pd4_init(nullptr, &never), ADCS_STATUS_INVALID_PARAMETER);
  EXPECT_EQ(adcs_mrp_pd4_init(&p, nullptr), ADCS_STATUS_INVALID_PARAMETER);
  adcs_mrp_pd4_state s;
  ASSERT_EQ(adcs_mrp_pd4_init(&p, &s), ADCS_STATUS_OK);
  EXPECT_EQ(adcs_mrp_pd4_step(nullptr, &in, &out), ADCS_STATUS_INVALID_PARAMETER);
  EXPECT_EQ(adcs_mrp_pd4_step(&s, nullptr, &out), ADCS_STATUS_INVALID_PARAMETER);
  EXPECT_EQ(adcs_mrp_pd4_step(&s, &in, nullptr), ADCS_STATUS_INVALID_PARAMETER);
  EXPECT_EQ(out.torque_B_Nm[2], 9.0);
  static adcs_rw_alloc4f_state never_f;
  const adcs_rw_alloc4f_input req = {{0.01f, 0.0f, 0.0f}};
  adcs_rw_alloc4f_output u = {{5.0f, 5.0f, 5.0f, 5.0f}};
  EXPECT_EQ(adcs_rw_alloc4f_step(&never_f, &req, &u), ADCS_STATUS_INVALID_PARAMETER);
  EXPECT_EQ(u.u_s_Nm[3], 5.0f);
}

TEST(CInterface, RefusedParametersGiveTheSafeCommandOnEveryStep) {
  adcs_mrp_pd4_params p = law_params<adcs_mrp_pd4_params>();
  p.K = kNaN;
  adcs_mrp_pd4_state s;
  EXPECT_EQ(adcs_mrp_pd4_init(&p, &s), ADCS_STATUS_INVALID_PARAMETER);
  const adcs_mrp_pd4_input in = law_input<adcs_mrp_pd4_input>(0);
  adcs_mrp_pd4_output out = {{1.0, 1.0, 1.0}};
  EXPECT_EQ(adcs_mrp_pd4_step(&s, &in, &out), ADCS_STATUS_INVALID_PARAMETER);
  for (double t : out.torque_B_Nm) EXPECT_EQ(t, 0.0);
  // An unknown failure policy is refused like a NaN gain, never cast into the enum.
  p = law_params<adcs_mrp_pd4_params>();
  p.on_failure = 7;
  EXPECT_EQ(adcs_mrp_pd4_init(&p, &s), ADCS_STATUS_INVALID_PARAMETER);
  // Coplanar wheel axes do not span R^3: the allocation refuses them.
  adcs_rw_alloc4_params a{};
  for (int j = 0; j < 4; ++j) {
    a.G_s_B[0][j] = std::cos(j);
    a.G_s_B[1][j] = std::sin(j);
    a.G_s_B[2][j] = 0.0;
  }
  a.torque_limit = 3e-3;
  adcs_rw_alloc4_state as;
  EXPECT_EQ(adcs_rw_alloc4_init(&a, &as), ADCS_STATUS_INVALID_PARAMETER);
}

TEST(CInterface, BadInputGivesTheFailureCommandOfThePolicyAndReInitResets) {
  for (adcs_failure_policy policy : {ADCS_FAILURE_SAFE_COMMAND, ADCS_FAILURE_HOLD_LAST}) {
    adcs_mrp_pd4_params p = law_params<adcs_mrp_pd4_params>();
    p.on_failure = policy;
    adcs_mrp_pd4_state s;
    ASSERT_EQ(adcs_mrp_pd4_init(&p, &s), ADCS_STATUS_OK);
    adcs_mrp_pd4_input in = law_input<adcs_mrp_pd4_input>(0);
    adcs_mrp_pd4_output good{}, bad{};
    ASSERT_EQ(adcs_mrp_pd4_step(&s, &in, &good), ADCS_STATUS_OK);
    in.omega_BN_B[1] = kNaN;
    EXPECT_EQ(adcs_mrp_pd4_step(&s, &in, &bad), ADCS_STATUS_NON_FINITE_INPUT);
    for (int i = 0; i < 3; ++i)
      EXPECT_EQ(bad.torque_B_Nm[i], policy == ADCS_FAILURE_HOLD_LAST ? good.torque_B_Nm[i] : 0.0);
    // Init again: a fresh controller (hold_last has nothing to hold).
    ASSERT_EQ(adcs_mrp_pd4_init(&p, &s), ADCS_STATUS_OK);
    EXPECT_EQ(adcs_mrp_pd4_step(&s, &in, &bad), ADCS_STATUS_NON_FINITE_INPUT);
    for (double t : bad.torque_B_Nm) EXPECT_EQ(t, 0.0);
  }
  adcs_rw_alloc4_params a{};
  fill_axes(a);
  a.torque_limit = 3e-3;
  adcs_rw_alloc4_state as;
  ASSERT_EQ(adcs_rw_alloc4_init(&a, &as), ADCS_STATUS_OK);
  adcs_rw_alloc4_input req = {{1.0, -2.0, 0.5}};  // far above what 3 mN m wheels give
  adcs_rw_alloc4_output u{};
  EXPECT_EQ(adcs_rw_alloc4_step(&as, &req, &u), ADCS_STATUS_SATURATED);
  for (double x : u.u_s_Nm) EXPECT_LE(std::fabs(x), 3e-3);
  req.torque_B_Nm[2] = kNaN;
  EXPECT_EQ(adcs_rw_alloc4_step(&as, &req, &u), ADCS_STATUS_NON_FINITE_INPUT);
  for (double x : u.u_s_Nm) EXPECT_EQ(x, 0.0);  // the wheels coast
}

// Bit for bit the C++ components', in both scalars, with the heap forbidden.
template <class S, class CParams, class CState, class CInput, class COutput, class Init, class Step>
void expect_law_equals_cpp(Init init, Step step) {
  const CParams cp = law_params<CParams>();
  CState cs;
  ASSERT_EQ(init(&cp, &cs), ADCS_STATUS_OK);
  adcs::MrpPdParams<4, S> p;
  p.K = cp.K;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      p.P(i, j) = cp.P[i][j];
      p.J_rw_B(i, j) = cp.J_rw_B[i][j];
    }
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 4; ++j) p.G_s_B(i, j) = cp.G_s_B[i][j];
  for (int j = 0; j < 4; ++j) p.J_s(j) = cp.J_s[j];
  p.period_s = cp.period_s;
  adcs::MrpPd<4, S> cpp(p);
  ASSERT_EQ(cpp.status(), adcs::Status::ok);
  long allocations = 0;
  for (int k = 0; k < 20; ++k) {
    const CInput ci = law_input<CInput>(k);
    typename adcs::MrpPd<4, S>::Input in;
    for (int i = 0; i < 3; ++i) {
      in.state.sigma_BN(i) = ci.sigma_BN[i];
      in.state.omega_BN_B(i) = ci.omega_BN_B[i];
      in.reference.sigma_RN(i) = ci.sigma_RN[i];
      in.reference.omega_RN_N(i) = ci.omega_RN_N[i];
      in.reference.domega_RN_N(i) = ci.domega_RN_N[i];
    }
    for (int j = 0; j < 4; ++j) in.Omega_rad_s(j) = ci.Omega_rad_s[j];
    COutput co{};
    adcs::BodyTorqueT<S> out;
    adcs_status s = 0;
    {
      adcs::test::NoAllocScope scope;
      s = step(&cs, &ci, &co);
      allocations += scope.allocations();
    }
    ASSERT_EQ(s, static_cast<adcs_status>(cpp.step(in, out)));
    for (int i = 0; i < 3; ++i) EXPECT_EQ(std::memcmp(&co.torque_B_Nm[i], &out.torque_B_Nm(i), sizeof(S)), 0);
  }
  EXPECT_EQ(allocations, 0);
}

TEST(CInterface, MrpPdEqualsTheCppComponentBitForBitWithoutHeap) {
  expect_law_equals_cpp<double, adcs_mrp_pd4_params, adcs_mrp_pd4_state, adcs_mrp_pd4_input, adcs_mrp_pd4_output>(
      adcs_mrp_pd4_init, adcs_mrp_pd4_step);
  expect_law_equals_cpp<float, adcs_mrp_pd4f_params, adcs_mrp_pd4f_state, adcs_mrp_pd4f_input, adcs_mrp_pd4f_output>(
      adcs_mrp_pd4f_init, adcs_mrp_pd4f_step);
}

// ---- Seed 002: PPATC (adcs_ppc, adcs_ppcf) ----------------------------------------------------

// The paper's law (seed 002 Table 2) through the C parameter struct of scalar S.
template <class CParams>
CParams ppc_c_params() {
  using S = std::remove_reference_t<decltype(CParams{}.period_s)>;
  const adcs::PpcNeuralParams d{adcs::seed002_tracking_gains(), adcs::seed002_performance()};
  CParams cp{};
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) cp.J_kgm2[i][j] = static_cast<S>(d.gains.J(i, j));
    cp.lambda[i] = static_cast<S>(d.gains.lambda(i));
    cp.K[i] = static_cast<S>(d.gains.K(i));
    cp.tau_w[i] = static_cast<S>(d.gains.compensator.tau_w(i));
    cp.rho0_rad[i] = static_cast<S>(d.ppc.rho[i].rho0);
    cp.rho_inf_rad[i] = static_cast<S>(d.ppc.rho[i].rho_inf);
    cp.k_rho[i] = static_cast<S>(d.ppc.rho[i].k);
    cp.delta[i] = static_cast<S>(d.ppc.delta(i));
  }
  for (int i = 0; i < 6; ++i)
    for (int j = 0; j < 7; ++j) cp.rbf_centers[i][j] = static_cast<S>(d.gains.compensator.layer.centers(i, j));
  for (int j = 0; j < 7; ++j) cp.rbf_widths[j] = static_cast<S>(d.gains.compensator.layer.widths(j));
  cp.tau_mu = static_cast<S>(d.gains.compensator.tau_mu);
  cp.beta = static_cast<S>(d.gains.compensator.beta);
  cp.gamma = static_cast<S>(d.gains.compensator.gamma);
  cp.sigma = static_cast<S>(d.gains.compensator.sigma);
  cp.units = ADCS_ANGLE_UNITS_RADIANS;
  cp.period_s = static_cast<S>(d.gains.period_s);
  cp.robust_clamp = 0;
  cp.funnel_recovery = ADCS_FUNNEL_REOPEN;
  cp.on_failure = ADCS_FAILURE_SAFE_COMMAND;
  return cp;
}

// Sample k of the paper's manoeuvre near its start (e inside the funnel).
template <class CInput>
CInput ppc_c_input(int k) {
  using S = std::remove_reference_t<decltype(CInput{}.t_s)>;
  const double t = 1e-4 * k;
  const adcs::EulerReferenceSample r = adcs::SinusoidalEulerReference().sample(t);
  const double d2r = adcs::kPiRad / 180.0;
  const adcs::Vec3 theta = r.angles + adcs::Vec3(0.25, 0.15, -0.20) * d2r * std::exp(-0.1 * t);
  CInput ci{};
  ci.t_s = static_cast<S>(t);
  for (int i = 0; i < 3; ++i) {
    ci.theta_BN_rad[i] = static_cast<S>(theta(i));
    ci.omega_BN_B[i] = static_cast<S>(r.angles_dot(i) + 1e-4 * (i + 1));
    ci.theta_d_rad[i] = static_cast<S>(r.angles(i));
    ci.theta_dot_d_rad_s[i] = static_cast<S>(r.angles_dot(i));
    ci.theta_ddot_d_rad_s2[i] = static_cast<S>(r.angles_ddot(i));
  }
  return ci;
}

template <class S, class CParams, class CState, class CInput, class COutput, class Init, class Step>
void expect_ppc_equals_cpp(Init init, Step step) {
  const CParams cp = ppc_c_params<CParams>();
  CState cs;
  ASSERT_EQ(init(&cp, &cs), ADCS_STATUS_OK);
  // The C++ law from the same values: the double parameters, rounded once into S.
  adcs::PpcNeuralT<S> cpp(adcs::PpcNeuralParams{adcs::seed002_tracking_gains(), adcs::seed002_performance()}.cast<S>());
  ASSERT_EQ(cpp.status(), adcs::Status::ok);
  long allocations = 0;
  for (int k = 0; k < 20; ++k) {
    const CInput ci = ppc_c_input<CInput>(k);
    adcs::EulerTrackingInputT<S> in;
    in.t_s = ci.t_s;
    for (int i = 0; i < 3; ++i) {
      in.state.theta_BN_rad(i) = ci.theta_BN_rad[i];
      in.state.omega_BN_B(i) = ci.omega_BN_B[i];
      in.reference.angles(i) = ci.theta_d_rad[i];
      in.reference.angles_dot(i) = ci.theta_dot_d_rad_s[i];
      in.reference.angles_ddot(i) = ci.theta_ddot_d_rad_s2[i];
    }
    COutput co{};
    adcs::BodyTorqueT<S> out;
    adcs_status s = 0;
    {
      adcs::test::NoAllocScope scope;
      s = step(&cs, &ci, &co);
      allocations += scope.allocations();
    }
    ASSERT_EQ(s, static_cast<adcs_status>(cpp.step(in, out))) << k;
    for (int i = 0; i < 3; ++i) EXPECT_EQ(std::memcmp(&co.torque_B_Nm[i], &out.torque_B_Nm(i), sizeof(S)), 0) << k;
  }
  EXPECT_EQ(allocations, 0);
}

TEST(CInterface, PpcEqualsTheCppComponentBitForBitWithoutHeap) {
  expect_ppc_equals_cpp<double, adcs_ppc_params, adcs_ppc_state, adcs_ppc_input, adcs_ppc_output>(adcs_ppc_init,
                                                                                                   adcs_ppc_step);
  expect_ppc_equals_cpp<float, adcs_ppcf_params, adcs_ppcf_state, adcs_ppcf_input, adcs_ppcf_output>(
      adcs_ppcf_init, adcs_ppcf_step);
}

TEST(CInterface, PpcRefusalsAndFailureCommands) {
  adcs_ppc_state s;
  adcs_ppc_output out = {{7.0, 7.0, 7.0}};
  const adcs_ppc_input in = ppc_c_input<adcs_ppc_input>(0);
  // NULL pointers and a state init never wrote: refused, nothing written.
  adcs_ppc_params p = ppc_c_params<adcs_ppc_params>();
  EXPECT_EQ(adcs_ppc_init(nullptr, &s), ADCS_STATUS_INVALID_PARAMETER);
  EXPECT_EQ(adcs_ppc_init(&p, nullptr), ADCS_STATUS_INVALID_PARAMETER);
  static adcs_ppc_state never;
  EXPECT_EQ(adcs_ppc_step(&never, &in, &out), ADCS_STATUS_INVALID_PARAMETER);
  EXPECT_EQ(out.torque_B_Nm[0], 7.0);
  // Refused sets: a forgotten inertia (zeros: not SPD), unknown enumerations, a funnel with
  // ρ∞ ≥ ρ0. Each step then commands zero torque.
  for (int which = 0; which < 5; ++which) {
    p = ppc_c_params<adcs_ppc_params>();
    if (which == 0) std::memset(p.J_kgm2, 0, sizeof p.J_kgm2);
    if (which == 1) p.units = 9;
    if (which == 2) p.funnel_recovery = -1;
    if (which == 3) p.on_failure = 2;
    if (which == 4) p.rho_inf_rad[1] = p.rho0_rad[1];
    EXPECT_EQ(adcs_ppc_init(&p, &s), ADCS_STATUS_INVALID_PARAMETER) << which;
    EXPECT_EQ(adcs_ppc_step(&s, &in, &out), ADCS_STATUS_INVALID_PARAMETER) << which;
    for (double t : out.torque_B_Nm) EXPECT_EQ(t, 0.0) << which;
  }
  // Bad input under each policy: zero torque, or the last good command; in float too.
  for (adcs_failure_policy policy : {ADCS_FAILURE_SAFE_COMMAND, ADCS_FAILURE_HOLD_LAST}) {
    adcs_ppcf_params pf = ppc_c_params<adcs_ppcf_params>();
    pf.on_failure = policy;
    adcs_ppcf_state sf;
    ASSERT_EQ(adcs_ppcf_init(&pf, &sf), ADCS_STATUS_OK);
    adcs_ppcf_input inf = ppc_c_input<adcs_ppcf_input>(0);
    adcs_ppcf_output good{}, bad{};
    ASSERT_EQ(adcs_ppcf_step(&sf, &inf, &good), ADCS_STATUS_OK);
    inf.omega_BN_B[2] = std::numeric_limits<float>::infinity();
    EXPECT_EQ(adcs_ppcf_step(&sf, &inf, &bad), ADCS_STATUS_NON_FINITE_INPUT);
    for (int i = 0; i < 3; ++i)
      EXPECT_EQ(bad.torque_B_Nm[i], policy == ADCS_FAILURE_HOLD_LAST ? good.torque_B_Nm[i] : 0.0f);
  }
}

// ---- Seed 001: the hybrid adaptive law (adcs_hybrid43, adcs_hybrid43f, adcs_hybrid_design_gains)

// Seed 001's closed-loop eigenvalues (seed001_axis_poles) as the C design call takes them.
void seed001_poles(double re[3][2], double im[3][2]) {
  const adcs::AxisPoles<3> poles = adcs::seed001_axis_poles();
  for (int a = 0; a < 3; ++a)
    for (int k = 0; k < 2; ++k) {
      re[a][k] = poles[a][k].real();
      im[a][k] = poles[a][k].imag();
    }
}

// The A-REF law (nominal pyramid + 3 wheels, the paper's gains, T_c = 1 ms) through the C
// parameter struct of scalar S, with K and P from the C design call, rounded once into S.
template <class CParams>
CParams hybrid_c_params() {
  using S = std::remove_reference_t<decltype(CParams{}.period_s)>;
  adcs::HybridAdaptiveParams<4, 3> d;
  d.nominal = adcs::pyramid_4cmg_3rw_nominal();
  double re[3][2], im[3][2], Q[6][6], K[3][6], P[6][6];
  seed001_poles(re, im);
  for (int i = 0; i < 6; ++i)
    for (int j = 0; j < 6; ++j) Q[i][j] = d.Q_L(i, j);
  EXPECT_EQ(adcs_hybrid_design_gains(re, im, Q, K, P), ADCS_STATUS_OK);
  CParams cp{};
  const adcs::VscmgGeometry<4, 3>& g = d.nominal;
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 4; ++j) {
      cp.A_cg[i][j] = static_cast<S>(g.A_cg(i, j));
      cp.A_cs0[i][j] = static_cast<S>(g.A_cs0(i, j));
      cp.A_ct0[i][j] = static_cast<S>(g.A_ct0(i, j));
    }
    for (int j = 0; j < 3; ++j) {
      cp.A_ws[i][j] = static_cast<S>(g.A_ws(i, j));
      cp.J_s[i][j] = static_cast<S>(g.J_s(i, j));
    }
    for (int j = 0; j < 6; ++j) cp.K[i][j] = static_cast<S>(K[i][j]);
    cp.I_wws[i] = static_cast<S>(g.I_wws(i));
    cp.H_I_n[i] = static_cast<S>(d.H_I_n(i));
  }
  for (int j = 0; j < 4; ++j) {
    cp.I_cs[j] = static_cast<S>(g.I_cs(j));
    cp.I_ct[j] = static_cast<S>(g.I_ct(j));
    cp.I_cg[j] = static_cast<S>(g.I_cg(j));
    cp.h_cw[j] = static_cast<S>(g.h_cw(j));
  }
  for (int i = 0; i < 6; ++i)
    for (int j = 0; j < 6; ++j) {
      cp.P[i][j] = static_cast<S>(P[i][j]);
      cp.Q_L[i][j] = static_cast<S>(Q[i][j]);
    }
  cp.alpha_F = static_cast<S>(d.alpha_F);
  cp.alpha_G = static_cast<S>(d.alpha_G);
  cp.beta_G = static_cast<S>(d.beta_G);
  cp.delta_G = static_cast<S>(d.delta_G);
  cp.period_s = static_cast<S>(d.period_s);
  cp.steering_sigma_threshold = static_cast<S>(d.steering.sigma_threshold);
  cp.steering_lambda_max = static_cast<S>(d.steering.lambda_max);
  cp.steering_max_torque_error = static_cast<S>(d.steering.max_torque_error);
  cp.adaptation_step = ADCS_ADAPTATION_EXPLICIT_EULER;
  cp.max_step_gain = static_cast<S>(d.max_step_gain);
  cp.on_failure = ADCS_FAILURE_SAFE_COMMAND;
  return cp;
}

// Sample k of seed 001's reference (SinusoidalRateReference) with an attitude and rate error.
template <class CInput>
CInput hybrid_c_input(int k) {
  using S = std::remove_reference_t<decltype(CInput{}.sigma_BN[0])>;
  const adcs::Vec3 sigma(0.01, -0.02, 0.03 + 1e-4 * k);
  const adcs::MrpReferenceSample r = adcs::SinusoidalRateReference().sample(1e-3 * k, 0.5 * sigma);
  CInput ci{};
  for (int i = 0; i < 3; ++i) {
    ci.sigma_BN[i] = static_cast<S>(sigma(i));
    ci.omega_BN_B[i] = static_cast<S>(1e-3 * (i + 1));
    ci.Omega_rad_s[i] = static_cast<S>(0.0);
    ci.sigma_d[i] = static_cast<S>(r.sigma(i));
    ci.sigma_dot_d[i] = static_cast<S>(r.sigma_dot(i));
    ci.sigma_ddot_d[i] = static_cast<S>(r.sigma_ddot(i));
  }
  for (int j = 0; j < 4; ++j) ci.gamma_rad[j] = static_cast<S>(0.1 * j + 1e-3 * k);
  return ci;
}

template <class S, class CParams, class CState, class CInput, class COutput, class Init, class Step>
void expect_hybrid_equals_cpp(Init init, Step step) {
  const CParams cp = hybrid_c_params<CParams>();
  CState cs;
  ASSERT_EQ(init(&cp, &cs), ADCS_STATUS_OK);
  // The C++ law from the same values: the double parameters and the C call's design (the same
  // function as adcs::design_hybrid_adaptive_gains; compiled once, in the library), rounded once
  // into S.
  adcs::HybridAdaptiveParams<4, 3> d;
  d.nominal = adcs::pyramid_4cmg_3rw_nominal();
  const auto designed = hybrid_c_params<adcs_hybrid43_params>();
  adcs::HybridAdaptiveGains<double> g;
  g.K = Eigen::Map<const Eigen::Matrix<double, 3, 6, Eigen::RowMajor>>(&designed.K[0][0]);
  g.P = Eigen::Map<const Eigen::Matrix<double, 6, 6, Eigen::RowMajor>>(&designed.P[0][0]);
  adcs::HybridAdaptive<4, 3, S> cpp(d.cast<S>(), g.cast<S>());
  ASSERT_EQ(cpp.status(), adcs::Status::ok);
  long allocations = 0;
  for (int k = 0; k < 20; ++k) {
    const CInput ci = hybrid_c_input<CInput>(k);
    adcs::HybridAdaptiveInput<4, 3, S> in;
    for (int i = 0; i < 3; ++i) {
      in.state.sigma_BN(i) = ci.sigma_BN[i];
      in.state.omega_BN_B(i) = ci.omega_BN_B[i];
      in.actuators.Omega_rad_s(i) = ci.Omega_rad_s[i];
      in.reference.sigma(i) = ci.sigma_d[i];
      in.reference.sigma_dot(i) = ci.sigma_dot_d[i];
      in.reference.sigma_ddot(i) = ci.sigma_ddot_d[i];
    }
    for (int j = 0; j < 4; ++j) in.actuators.gamma_rad(j) = ci.gamma_rad[j];
    COutput co{};
    adcs::VscmgRates<4, 3, S> out;
    adcs_status s = 0;
    {
      adcs::test::NoAllocScope scope;
      s = step(&cs, &ci, &co);
      allocations += scope.allocations();
    }
    ASSERT_EQ(s, static_cast<adcs_status>(cpp.step(in, out))) << k;
    for (int j = 0; j < 4; ++j)
      EXPECT_EQ(std::memcmp(&co.gamma_dot_rad_s[j], &out.gamma_dot_rad_s(j), sizeof(S)), 0) << k;
    for (int j = 0; j < 3; ++j)
      EXPECT_EQ(std::memcmp(&co.Omega_dot_rad_s2[j], &out.Omega_dot_rad_s2(j), sizeof(S)), 0) << k;
  }
  EXPECT_EQ(allocations, 0);
}

TEST(CInterface, HybridEqualsTheCppComponentBitForBitWithoutHeap) {
  expect_hybrid_equals_cpp<double, adcs_hybrid43_params, adcs_hybrid43_state, adcs_hybrid43_input,
                           adcs_hybrid43_output>(adcs_hybrid43_init, adcs_hybrid43_step);
  expect_hybrid_equals_cpp<float, adcs_hybrid43f_params, adcs_hybrid43f_state, adcs_hybrid43f_input,
                           adcs_hybrid43f_output>(adcs_hybrid43f_init, adcs_hybrid43f_step);
}

TEST(CInterface, HybridDesignPlacesThePolesAndSolvesTheLyapunovEquation) {
  // Per axis a, s² + K(a, 3+a) s + K(a, a) has the requested roots: K_d = −(p1 + p2), K_p = p1 p2;
  // P solves A_1ᵀP + PA_1 = −Q_L and is SPD (checked without a second Schur-based solve).
  double re[3][2], im[3][2], Q[6][6] = {}, K[3][6], P[6][6];
  for (int i = 0; i < 6; ++i) Q[i][i] = 1.0;
  seed001_poles(re, im);
  ASSERT_EQ(adcs_hybrid_design_gains(re, im, Q, K, P), ADCS_STATUS_OK);
  for (int a = 0; a < 3; ++a) {
    const std::complex<double> p1(re[a][0], im[a][0]), p2(re[a][1], im[a][1]);
    EXPECT_NEAR(K[a][3 + a], -(p1 + p2).real(), 1e-12) << a;
    EXPECT_NEAR(K[a][a], (p1 * p2).real(), 1e-12) << a;
    for (int j = 0; j < 6; ++j)
      if (j != a && j != 3 + a) EXPECT_EQ(K[a][j], 0.0) << a << "," << j;
  }
  const adcs::Mat<3, 6> Km = Eigen::Map<const Eigen::Matrix<double, 3, 6, Eigen::RowMajor>>(&K[0][0]);
  const adcs::Mat6 Pm = Eigen::Map<const Eigen::Matrix<double, 6, 6, Eigen::RowMajor>>(&P[0][0]);
  const adcs::Mat6 A1 = adcs::double_integrator_closed_loop<3>(Km);
  EXPECT_LT((A1.transpose() * Pm + Pm * A1 + adcs::Mat6::Identity()).norm(), 1e-10 * Pm.norm());
  EXPECT_TRUE(adcs::symmetric_positive_definite<6>(Pm));
}

TEST(CInterface, HybridDesignRefusesBadPolesAndWritesNothing) {
  double re[3][2], im[3][2], Q[6][6] = {}, K[3][6], P[6][6];
  for (int i = 0; i < 6; ++i) Q[i][i] = 1.0;
  seed001_poles(re, im);
  K[0][0] = 7.0;
  P[0][0] = 7.0;
  EXPECT_EQ(adcs_hybrid_design_gains(nullptr, im, Q, K, P), ADCS_STATUS_INVALID_PARAMETER);
  re[1][0] = 0.3;  // an unstable pair
  re[1][1] = 0.3;
  EXPECT_EQ(adcs_hybrid_design_gains(re, im, Q, K, P), ADCS_STATUS_INVALID_PARAMETER);
  seed001_poles(re, im);
  Q[2][2] = -1.0;  // Q_L not SPD
  EXPECT_EQ(adcs_hybrid_design_gains(re, im, Q, K, P), ADCS_STATUS_INVALID_PARAMETER);
  EXPECT_EQ(K[0][0], 7.0);
  EXPECT_EQ(P[0][0], 7.0);
}

TEST(CInterface, HybridRefusalsAndFailureCommands) {
  adcs_hybrid43_state s;
  adcs_hybrid43_output out = {{7.0, 7.0, 7.0, 7.0}, {7.0, 7.0, 7.0}};
  const adcs_hybrid43_input in = hybrid_c_input<adcs_hybrid43_input>(0);
  adcs_hybrid43_params p = hybrid_c_params<adcs_hybrid43_params>();
  EXPECT_EQ(adcs_hybrid43_init(nullptr, &s), ADCS_STATUS_INVALID_PARAMETER);
  EXPECT_EQ(adcs_hybrid43_init(&p, nullptr), ADCS_STATUS_INVALID_PARAMETER);
  static adcs_hybrid43_state never;
  EXPECT_EQ(adcs_hybrid43_step(&never, &in, &out), ADCS_STATUS_INVALID_PARAMETER);
  EXPECT_EQ(out.gamma_dot_rad_s[0], 7.0);
  // Refused sets: gains left at zero (no design uploaded), a P that does not solve the Lyapunov
  // equation for Q_L, a forgotten body inertia, unknown enumerations. Each step then commands zero
  // gimbal rates and wheel accelerations.
  for (int which = 0; which < 5; ++which) {
    p = hybrid_c_params<adcs_hybrid43_params>();
    if (which == 0) {
      std::memset(p.K, 0, sizeof p.K);
      std::memset(p.P, 0, sizeof p.P);
    }
    if (which == 1) p.Q_L[0][0] = 2.0;
    if (which == 2) std::memset(p.J_s, 0, sizeof p.J_s);
    if (which == 3) p.adaptation_step = 5;
    if (which == 4) p.on_failure = -1;
    EXPECT_EQ(adcs_hybrid43_init(&p, &s), ADCS_STATUS_INVALID_PARAMETER) << which;
    EXPECT_EQ(adcs_hybrid43_step(&s, &in, &out), ADCS_STATUS_INVALID_PARAMETER) << which;
    for (double u : out.gamma_dot_rad_s) EXPECT_EQ(u, 0.0) << which;
    for (double u : out.Omega_dot_rad_s2) EXPECT_EQ(u, 0.0) << which;
  }
  // Bad input under each policy: zero rates, or the last good command; in float.
  for (adcs_failure_policy policy : {ADCS_FAILURE_SAFE_COMMAND, ADCS_FAILURE_HOLD_LAST}) {
    adcs_hybrid43f_params pf = hybrid_c_params<adcs_hybrid43f_params>();
    pf.on_failure = policy;
    adcs_hybrid43f_state sf;
    ASSERT_EQ(adcs_hybrid43f_init(&pf, &sf), ADCS_STATUS_OK);
    adcs_hybrid43f_input inf = hybrid_c_input<adcs_hybrid43f_input>(0);
    adcs_hybrid43f_output good{}, bad{};
    ASSERT_TRUE(adcs_status_usable(adcs_hybrid43f_step(&sf, &inf, &good)));
    inf.gamma_rad[1] = std::numeric_limits<float>::quiet_NaN();
    EXPECT_EQ(adcs_hybrid43f_step(&sf, &inf, &bad), ADCS_STATUS_NON_FINITE_INPUT);
    for (int j = 0; j < 4; ++j)
      EXPECT_EQ(bad.gamma_dot_rad_s[j], policy == ADCS_FAILURE_HOLD_LAST ? good.gamma_dot_rad_s[j] : 0.0f);
    for (int j = 0; j < 3; ++j)
      EXPECT_EQ(bad.Omega_dot_rad_s2[j], policy == ADCS_FAILURE_HOLD_LAST ? good.Omega_dot_rad_s2[j] : 0.0f);
  }
}

// ---- Seed 003: the prescribed-time SE(3) law (adcs_se3_ptc, adcs_se3_ptcf) -----------------------

// Seed 003's BsPdTC (spec A.8 Table 1, ζ = 1.05 ϖ of the paper's quantizer, the nominal chaser).
adcs::PrescribedTimeSe3Params se3_cpp_params() {
  adcs::PrescribedTimeSe3Params p;
  p.zeta = adcs::quantization_compensation_gain(adcs::seed003_quantizer_params());
  p.nominal = adcs::se3_chaser_nominal_params(adcs::Se3ScenarioParams{});
  return p;
}

template <class CParams>
CParams se3_c_params() {
  using S = std::remove_reference_t<decltype(CParams{}.period_s)>;
  const adcs::PrescribedTimeSe3Params d = se3_cpp_params();
  CParams cp{};
  cp.p = static_cast<S>(d.p);
  cp.T_s = static_cast<S>(d.T);
  for (int i = 0; i < 6; ++i) {
    cp.K2[i] = static_cast<S>(d.K2(i));
    cp.Lambda[i] = static_cast<S>(d.Lambda(i));
    cp.Upsilon[i] = static_cast<S>(d.Upsilon(i));
    cp.K3[i] = static_cast<S>(d.K3(i));
    cp.Lambda2[i] = static_cast<S>(d.Lambda2(i));
    cp.Upsilon2[i] = static_cast<S>(d.Upsilon2(i));
    cp.zeta[i] = static_cast<S>(d.zeta(i));
  }
  cp.eps1 = static_cast<S>(d.eps1);
  cp.eps2 = static_cast<S>(d.eps2);
  cp.eps_q = static_cast<S>(d.eps_q);
  cp.a = static_cast<S>(d.a);
  cp.gamma = static_cast<S>(d.gamma);
  cp.sigma1 = static_cast<S>(d.sigma1);
  cp.sigma2 = static_cast<S>(d.sigma2);
  cp.psi_hat0 = static_cast<S>(d.psi_hat0);
  cp.period_s = static_cast<S>(d.period_s);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) cp.J0_kgm2[i][j] = static_cast<S>(d.nominal.J_B(i, j));
  cp.m0_kg = static_cast<S>(d.nominal.m);
  cp.mu_m3_s2 = static_cast<S>(d.nominal.env.mu);
  cp.J2 = static_cast<S>(d.nominal.env.J2);
  cp.R_E_m = static_cast<S>(d.nominal.env.R_E);
  cp.on_failure = ADCS_FAILURE_SAFE_COMMAND;
  return cp;
}

// The paper's pair at state 1 with a relative twist that varies with k (every term active).
adcs::Se3TrackingInput se3_cpp_input(int k) {
  adcs::Se3TrackingInput in;
  EXPECT_TRUE(adcs::se3_paper_tracking_input(adcs::Se3ScenarioParams{}, 0, adcs::Vec3(1e-3, -2e-3, 1e-3) * (1.0 + 0.1 * k),
                                             adcs::Vec3(0.02, -0.01, 0.03) * (1.0 - 0.05 * k), in.state, in.desired));
  return in;
}

template <class CInput, class S>
CInput se3_c_input(const adcs::Se3TrackingInputT<S>& in) {
  CInput ci{};
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) {
      ci.C_NB[i][j] = in.state.C_NB(i, j);
      ci.C_ND[i][j] = in.desired.C_ND(i, j);
    }
    ci.R_N_m[i] = in.state.R_N(i);
    ci.omega_BN_B[i] = in.state.omega_BN_B(i);
    ci.v_B_m_s[i] = in.state.v_B(i);
    ci.R_d_N_m[i] = in.desired.R_N(i);
    ci.omega_DN_D[i] = in.desired.omega_DN_D(i);
    ci.v_D_m_s[i] = in.desired.v_D(i);
    ci.omega_dot_D[i] = in.desired.omega_dot_D(i);
    ci.v_dot_D_m_s2[i] = in.desired.v_dot_D(i);
  }
  return ci;
}

template <class S, class CParams, class CState, class CInput, class COutput, class Init, class Step>
void expect_se3_equals_cpp(Init init, Step step) {
  const CParams cp = se3_c_params<CParams>();
  CState cs;
  ASSERT_EQ(init(&cp, &cs), ADCS_STATUS_OK);
  // The C++ law from the same values: the double parameters, rounded once into S.
  adcs::PrescribedTimeSe3T<S> cpp(se3_cpp_params().cast<S>());
  ASSERT_EQ(cpp.status(), adcs::Status::ok);
  long allocations = 0;
  for (int k = 0; k < 20; ++k) {
    const adcs::Se3TrackingInputT<S> in = se3_cpp_input(k).cast<S>();
    const CInput ci = se3_c_input<CInput>(in);
    COutput co{};
    adcs::WrenchT<S> out;
    adcs_status s = 0;
    {
      adcs::test::NoAllocScope scope;
      s = step(&cs, &ci, &co);
      allocations += scope.allocations();
    }
    ASSERT_EQ(s, static_cast<adcs_status>(cpp.step(in, out))) << k;
    for (int i = 0; i < 3; ++i) {
      EXPECT_EQ(std::memcmp(&co.torque_B_Nm[i], &out.torque_B_Nm(i), sizeof(S)), 0) << k;
      EXPECT_EQ(std::memcmp(&co.force_B_N[i], &out.force_B_N(i), sizeof(S)), 0) << k;
    }
  }
  EXPECT_EQ(allocations, 0);
}

TEST(CInterface, Se3PtcEqualsTheCppComponentBitForBitWithoutHeap) {
  expect_se3_equals_cpp<double, adcs_se3_ptc_params, adcs_se3_ptc_state, adcs_se3_ptc_input, adcs_se3_ptc_output>(
      adcs_se3_ptc_init, adcs_se3_ptc_step);
  expect_se3_equals_cpp<float, adcs_se3_ptcf_params, adcs_se3_ptcf_state, adcs_se3_ptcf_input, adcs_se3_ptcf_output>(
      adcs_se3_ptcf_init, adcs_se3_ptcf_step);
}

TEST(CInterface, Se3PtcRefusalsAndFailureCommands) {
  adcs_se3_ptc_state s;
  adcs_se3_ptc_output out = {{7.0, 7.0, 7.0}, {7.0, 7.0, 7.0}};
  const adcs_se3_ptc_input in = se3_c_input<adcs_se3_ptc_input>(se3_cpp_input(0));
  adcs_se3_ptc_params p = se3_c_params<adcs_se3_ptc_params>();
  EXPECT_EQ(adcs_se3_ptc_init(nullptr, &s), ADCS_STATUS_INVALID_PARAMETER);
  EXPECT_EQ(adcs_se3_ptc_init(&p, nullptr), ADCS_STATUS_INVALID_PARAMETER);
  static adcs_se3_ptc_state never;
  EXPECT_EQ(adcs_se3_ptc_step(&never, &in, &out), ADCS_STATUS_INVALID_PARAMETER);
  EXPECT_EQ(out.force_B_N[0], 7.0);
  // Refused sets: a forgotten inertia (zeros: not SPD), a forgotten ζ (NaN: no default), an
  // unknown failure policy, p outside (0, 1), a negative mass. Each step commands the zero wrench.
  for (int which = 0; which < 5; ++which) {
    p = se3_c_params<adcs_se3_ptc_params>();
    if (which == 0) std::memset(p.J0_kgm2, 0, sizeof p.J0_kgm2);
    if (which == 1) p.zeta[4] = kNaN;
    if (which == 2) p.on_failure = 7;
    if (which == 3) p.p = 1.0;
    if (which == 4) p.m0_kg = -1.0;
    EXPECT_EQ(adcs_se3_ptc_init(&p, &s), ADCS_STATUS_INVALID_PARAMETER) << which;
    EXPECT_EQ(adcs_se3_ptc_step(&s, &in, &out), ADCS_STATUS_INVALID_PARAMETER) << which;
    for (int i = 0; i < 3; ++i) {
      EXPECT_EQ(out.torque_B_Nm[i], 0.0) << which;
      EXPECT_EQ(out.force_B_N[i], 0.0) << which;
    }
  }
  // Bad input under each policy: the zero wrench, or the last good command; in float too.
  for (adcs_failure_policy policy : {ADCS_FAILURE_SAFE_COMMAND, ADCS_FAILURE_HOLD_LAST}) {
    adcs_se3_ptcf_params pf = se3_c_params<adcs_se3_ptcf_params>();
    pf.on_failure = policy;
    adcs_se3_ptcf_state sf;
    ASSERT_EQ(adcs_se3_ptcf_init(&pf, &sf), ADCS_STATUS_OK);
    adcs_se3_ptcf_input inf = se3_c_input<adcs_se3_ptcf_input>(se3_cpp_input(0).cast<float>());
    adcs_se3_ptcf_output good{}, bad{};
    ASSERT_EQ(adcs_se3_ptcf_step(&sf, &inf, &good), ADCS_STATUS_OK);
    inf.v_dot_D_m_s2[1] = std::numeric_limits<float>::quiet_NaN();
    EXPECT_EQ(adcs_se3_ptcf_step(&sf, &inf, &bad), ADCS_STATUS_NON_FINITE_INPUT);
    for (int i = 0; i < 3; ++i) {
      EXPECT_EQ(bad.torque_B_Nm[i], policy == ADCS_FAILURE_HOLD_LAST ? good.torque_B_Nm[i] : 0.0f);
      EXPECT_EQ(bad.force_B_N[i], policy == ADCS_FAILURE_HOLD_LAST ? good.force_B_N[i] : 0.0f);
    }
  }
}

// ---- Seed 004: the drag-free ADRC (adcs_drag_free_adrc, adcs_drag_free_adrcf) ---------------------

// The paper's configuration (DragFreeAdrcParams' defaults: seed 004 §4 gains, Table 2 plant), in
// the C struct's scalar.
template <class CParams>
CParams drag_free_c_params(adcs_adrc_x_law x_law = ADCS_ADRC_X_NLPID) {
  using S = std::remove_reference_t<decltype(CParams{}.period_s)>;
  const adcs::DragFreeAdrcParams d;
  CParams cp{};
  cp.m_tm_kg = static_cast<S>(d.plant.m_tm);
  cp.m_sc_kg = static_cast<S>(d.plant.m_sc);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      cp.I_tm_kgm2[i][j] = static_cast<S>(d.plant.I_tm(i, j));
      cp.I_sc_kgm2[i][j] = static_cast<S>(d.plant.I_sc(i, j));
      cp.K_trans_N_m[i][j] = static_cast<S>(d.plant.K_trans(i, j));
      cp.D_trans_Ns_m[i][j] = static_cast<S>(d.plant.D_trans(i, j));
      cp.K_rot_Nm_rad[i][j] = static_cast<S>(d.plant.K_rot(i, j));
      cp.D_rot_Nms_rad[i][j] = static_cast<S>(d.plant.D_rot(i, j));
    }
  cp.period_s = static_cast<S>(d.plant.period_s);
  const adcs::NlpidGains* g[3] = {&d.attitude, &d.drag_free, &d.tm_attitude};
  S* k[3] = {cp.attitude, cp.drag_free, cp.tm_attitude};
  for (int l = 0; l < 3; ++l) {
    k[l][0] = static_cast<S>(g[l]->kp);
    k[l][1] = static_cast<S>(g[l]->ki);
    k[l][2] = static_cast<S>(g[l]->kd);
  }
  cp.alpha = static_cast<S>(d.alpha);
  cp.delta = static_cast<S>(d.delta);
  cp.integral = ADCS_ADRC_INTEGRAL_SCALED_SUM;
  cp.limit = static_cast<S>(d.limit);
  cp.x_law = x_law;
  cp.pid_kp = static_cast<S>(d.pid_kp);
  cp.pid_ki = static_cast<S>(d.pid_ki);
  cp.pid_kd = static_cast<S>(d.pid_kd);
  cp.on_failure = ADCS_FAILURE_SAFE_COMMAND;
  return cp;
}

// Estimates that vary with k: small errors inside fal's linear zone, larger ones beyond it, and
// every fourth sample a drag estimate large enough to clip the force (saturated).
adcs::DragFreeAdrcInput drag_free_cpp_input(int k) {
  adcs::DragFreeAdrcInput in;
  for (int i = 0; i < 27; ++i) in.x_hat(i) = 1e-6 * std::sin(0.7 * i + 0.3 * k) * (i % 3 == 0 ? 1e4 : 1.0);
  in.F_D_hat_N = adcs::Vec3(-12.8e-3, 4e-3, 1e-3 * k) * (k % 4 == 3 ? 5.0 : 1.0);
  in.phi_sc_cmd_rad = adcs::Vec3(k >= 10 ? 0.03 : 0.0, 0.0, -1e-3 * k);
  return in;
}

template <class CInput, class S>
CInput drag_free_c_input(const adcs::DragFreeAdrcInputT<S>& in) {
  CInput ci{};
  for (int i = 0; i < 27; ++i) ci.x_hat[i] = in.x_hat(i);
  for (int i = 0; i < 3; ++i) {
    ci.F_D_hat_N[i] = in.F_D_hat_N(i);
    ci.phi_sc_cmd_rad[i] = in.phi_sc_cmd_rad(i);
  }
  return ci;
}

template <class S, class CParams, class CState, class CInput, class COutput, class Init, class Step>
void expect_drag_free_equals_cpp(Init init, Step step) {
  int saturated = 0;
  for (adcs_adrc_x_law x_law : {ADCS_ADRC_X_NLPID, ADCS_ADRC_X_PID, ADCS_ADRC_X_PID_COMPENSATED}) {
    const CParams cp = drag_free_c_params<CParams>(x_law);
    CState cs;
    ASSERT_EQ(init(&cp, &cs), ADCS_STATUS_OK);
    // The C++ law from the same values: the double parameters, rounded once into S.
    adcs::DragFreeAdrcParams d;
    d.x_law = static_cast<adcs::DragFreeXLaw>(x_law);
    adcs::DragFreeAdrcT<S> cpp(d.cast<S>());
    ASSERT_EQ(cpp.status(), adcs::Status::ok);
    long allocations = 0;
    for (int k = 0; k < 20; ++k) {
      adcs::DragFreeAdrcInputT<S> in;
      const adcs::DragFreeAdrcInput in_d = drag_free_cpp_input(k);
      in.x_hat = in_d.x_hat.cast<S>();
      in.F_D_hat_N = in_d.F_D_hat_N.cast<S>();
      in.phi_sc_cmd_rad = in_d.phi_sc_cmd_rad.cast<S>();
      const CInput ci = drag_free_c_input<CInput>(in);
      COutput co{};
      adcs::DragFreeActuationT<S> out;
      adcs_status s = 0;
      {
        adcs::test::NoAllocScope scope;
        s = step(&cs, &ci, &co);
        allocations += scope.allocations();
      }
      ASSERT_EQ(s, static_cast<adcs_status>(cpp.step(in, out))) << k;
      saturated += s == ADCS_STATUS_SATURATED;
      for (int i = 0; i < 3; ++i) {
        EXPECT_EQ(std::memcmp(&co.T_Csc_Nm[i], &out.T_Csc_Nm(i), sizeof(S)), 0) << k;
        EXPECT_EQ(std::memcmp(&co.F_Csc_N[i], &out.F_Csc_N(i), sizeof(S)), 0) << k;
        EXPECT_EQ(std::memcmp(&co.T_Ctm_Nm[i], &out.T_Ctm_Nm(i), sizeof(S)), 0) << k;
      }
    }
    EXPECT_EQ(allocations, 0);
  }
  EXPECT_GT(saturated, 0);  // the inputs reach the clipping branch
}

TEST(CInterface, DragFreeAdrcEqualsTheCppComponentBitForBitWithoutHeap) {
  expect_drag_free_equals_cpp<double, adcs_drag_free_adrc_params, adcs_drag_free_adrc_state, adcs_drag_free_adrc_input,
                              adcs_drag_free_adrc_output>(adcs_drag_free_adrc_init, adcs_drag_free_adrc_step);
  expect_drag_free_equals_cpp<float, adcs_drag_free_adrcf_params, adcs_drag_free_adrcf_state,
                              adcs_drag_free_adrcf_input, adcs_drag_free_adrcf_output>(adcs_drag_free_adrcf_init,
                                                                                      adcs_drag_free_adrcf_step);
}

TEST(CInterface, DragFreeAdrcRefusalsAndFailureCommands) {
  adcs_drag_free_adrc_state s;
  adcs_drag_free_adrc_output out = {{7.0, 7.0, 7.0}, {7.0, 7.0, 7.0}, {7.0, 7.0, 7.0}};
  const adcs_drag_free_adrc_input in = drag_free_c_input<adcs_drag_free_adrc_input>(drag_free_cpp_input(0));
  adcs_drag_free_adrc_params p = drag_free_c_params<adcs_drag_free_adrc_params>();
  EXPECT_EQ(adcs_drag_free_adrc_init(nullptr, &s), ADCS_STATUS_INVALID_PARAMETER);
  EXPECT_EQ(adcs_drag_free_adrc_init(&p, nullptr), ADCS_STATUS_INVALID_PARAMETER);
  static adcs_drag_free_adrc_state never;
  EXPECT_EQ(adcs_drag_free_adrc_step(&never, &in, &out), ADCS_STATUS_INVALID_PARAMETER);
  EXPECT_EQ(out.F_Csc_N[0], 7.0);
  // Refused sets: the zero-initialised struct (masses, inertias, h, alpha, delta, limit all 0), a
  // spacecraft inertia that is not SPD, alpha above 1, a NaN gain, a negative PID gain, an unknown
  // integral form, X law or failure policy. Each step then commands zero.
  for (int which = 0; which < 8; ++which) {
    p = drag_free_c_params<adcs_drag_free_adrc_params>();
    if (which == 0) p = adcs_drag_free_adrc_params{};
    if (which == 1) p.I_sc_kgm2[1][1] = -2700.0;
    if (which == 2) p.alpha = 1.5;
    if (which == 3) p.drag_free[2] = kNaN;
    if (which == 4) p.pid_kd = -9.0;
    if (which == 5) p.integral = 2;
    if (which == 6) p.x_law = 3;
    if (which == 7) p.on_failure = 7;
    EXPECT_EQ(adcs_drag_free_adrc_init(&p, &s), ADCS_STATUS_INVALID_PARAMETER) << which;
    EXPECT_EQ(adcs_drag_free_adrc_step(&s, &in, &out), ADCS_STATUS_INVALID_PARAMETER) << which;
    for (int i = 0; i < 3; ++i) {
      EXPECT_EQ(out.T_Csc_Nm[i], 0.0) << which;
      EXPECT_EQ(out.F_Csc_N[i], 0.0) << which;
      EXPECT_EQ(out.T_Ctm_Nm[i], 0.0) << which;
    }
  }
  // Bad input under each policy: zero, or the last good command; in float too. The integrals are
  // kept: the next good sample commands what it would have without the bad one.
  for (adcs_failure_policy policy : {ADCS_FAILURE_SAFE_COMMAND, ADCS_FAILURE_HOLD_LAST}) {
    adcs_drag_free_adrcf_params pf = drag_free_c_params<adcs_drag_free_adrcf_params>();
    pf.on_failure = policy;
    adcs_drag_free_adrcf_state sf, reference;
    ASSERT_EQ(adcs_drag_free_adrcf_init(&pf, &sf), ADCS_STATUS_OK);
    ASSERT_EQ(adcs_drag_free_adrcf_init(&pf, &reference), ADCS_STATUS_OK);
    adcs_drag_free_adrcf_input inf = drag_free_c_input<adcs_drag_free_adrcf_input>(drag_free_cpp_input(1));
    adcs_drag_free_adrcf_output good{}, bad{}, next{}, next_ref{};
    ASSERT_TRUE(adcs_status_usable(adcs_drag_free_adrcf_step(&sf, &inf, &good)));
    ASSERT_TRUE(adcs_status_usable(adcs_drag_free_adrcf_step(&reference, &inf, &good)));
    adcs_drag_free_adrcf_input poisoned = inf;
    poisoned.x_hat[13] = std::numeric_limits<float>::infinity();
    EXPECT_EQ(adcs_drag_free_adrcf_step(&sf, &poisoned, &bad), ADCS_STATUS_NON_FINITE_INPUT);
    for (int i = 0; i < 3; ++i) {
      EXPECT_EQ(bad.T_Csc_Nm[i], policy == ADCS_FAILURE_HOLD_LAST ? good.T_Csc_Nm[i] : 0.0f);
      EXPECT_EQ(bad.F_Csc_N[i], policy == ADCS_FAILURE_HOLD_LAST ? good.F_Csc_N[i] : 0.0f);
      EXPECT_EQ(bad.T_Ctm_Nm[i], policy == ADCS_FAILURE_HOLD_LAST ? good.T_Ctm_Nm[i] : 0.0f);
    }
    ASSERT_TRUE(adcs_status_usable(adcs_drag_free_adrcf_step(&sf, &inf, &next)));
    ASSERT_TRUE(adcs_status_usable(adcs_drag_free_adrcf_step(&reference, &inf, &next_ref)));
    EXPECT_EQ(std::memcmp(&next, &next_ref, sizeof next), 0);
  }
}

TEST(CInterface, StateObjectsHaveTheDocumentedSizeAndAlignment) {
  EXPECT_EQ(sizeof(adcs_mrp_pd4_state), 352u);
  EXPECT_EQ(sizeof(adcs_mrp_pd4f_state), 192u);
  EXPECT_EQ(sizeof(adcs_rw_alloc4_state), 272u);
  EXPECT_EQ(sizeof(adcs_rw_alloc4f_state), 160u);
  EXPECT_EQ(alignof(adcs_mrp_pd4_state), 16u);
  EXPECT_EQ(alignof(adcs_rw_alloc4f_state), 16u);
  EXPECT_EQ(sizeof(adcs_ppc_state), 2832u);
  EXPECT_EQ(sizeof(adcs_ppcf_state), 1360u);
  EXPECT_EQ(alignof(adcs_ppc_state), 16u);
  EXPECT_EQ(alignof(adcs_ppcf_state), 4u);
  EXPECT_EQ(sizeof(adcs_hybrid43_state), 2240u);
  EXPECT_EQ(sizeof(adcs_hybrid43f_state), 1216u);
  EXPECT_EQ(alignof(adcs_hybrid43_state), 16u);
  EXPECT_EQ(alignof(adcs_hybrid43f_state), 16u);
  EXPECT_EQ(sizeof(adcs_se3_ptc_state), 1216u);
  EXPECT_EQ(sizeof(adcs_se3_ptcf_state), 588u);
  EXPECT_EQ(alignof(adcs_se3_ptc_state), 16u);
  EXPECT_EQ(alignof(adcs_se3_ptcf_state), 4u);
  EXPECT_EQ(sizeof(adcs_drag_free_adrc_state), 872u);  // 864 before issue 20 (δ^{1−α} kept)
  EXPECT_EQ(sizeof(adcs_drag_free_adrcf_state), 436u);
  EXPECT_EQ(alignof(adcs_drag_free_adrc_state), 8u);
  EXPECT_EQ(alignof(adcs_drag_free_adrcf_state), 4u);
}

}  // namespace ADCS_UNITY_ID
using namespace ADCS_UNITY_ID;  // as an anonymous namespace would (CMakeLists.txt, adcs_unity)
