// Parameter validation of every component with parameters (issue 15, "Validation";
// docs/VALIDATION.md has the table): its default configuration is accepted (a documented real
// configuration) or refused (no default: NaN until set), one EXPECT per refusal, and a refused
// component's step()/update()/derivative() answers invalid_parameter (or its documented safe
// value) with a finite output. Grouped by folder.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <limits>
#include <utility>
#include <vector>

#include "adcs/actuator/limits.hpp"
#include "adcs/actuator/quantizer.hpp"
#include "adcs/actuator/rw_allocation.hpp"
#include "adcs/actuator/saturation.hpp"
#include "adcs/actuator/steering.hpp"
#include "adcs/actuator/vscmg_steering.hpp"
#include "adcs/adapt/normalized_step.hpp"
#include "adcs/adapt/ppc.hpp"
#include "adcs/adapt/projection.hpp"
#include "adcs/adapt/rbf_compensator.hpp"
#include "adcs/adapt/rbf_network.hpp"
#include "adcs/control/adaptive_tracking.hpp"
#include "adcs/control/adrc.hpp"
#include "adcs/control/ftsmc_se3.hpp"
#include "adcs/control/hybrid_adaptive.hpp"
#include "adcs/control/mrp_pd.hpp"
#include "adcs/control/nonsingular_power.hpp"
#include "adcs/control/pid.hpp"
#include "adcs/control/ppc_neural.hpp"
#include "adcs/control/prescribed_time_se3.hpp"
#include "adcs/core/signals.hpp"
#include "adcs/core/validation.hpp"
#include "adcs/estimate/drag_free_eskf.hpp"
#include "adcs/estimate/eskf.hpp"
#include "adcs/estimate/fusion.hpp"
#include "adcs/estimate/saturated_esf.hpp"
#include "adcs/plant/drag_free.hpp"
#include "adcs/plant/flexible_configurations.hpp"
#include "adcs/plant/flexible_spacecraft.hpp"
#include "adcs/plant/orbit_environment.hpp"
#include "adcs/plant/rigid_body_rw.hpp"
#include "adcs/plant/se3_spacecraft.hpp"
#include "adcs/plant/vscmg_cluster.hpp"
#include "adcs/plant/vscmg_configurations.hpp"
#include "adcs/reference/sinusoidal_euler.hpp"
#include "adcs/reference/sinusoidal_rate.hpp"
#include "scenarios/seed003_data.hpp"  // seed 003's scenario data (paper data, not flight code)

namespace ADCS_UNITY_ID {
using adcs::Mat3;
using adcs::Status;
using adcs::Vec3;
using adcs::Vec6;

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

//! One named change that must turn a good parameter set into a refused one.
template <class P>
using Refusal = std::pair<const char*, std::function<void(P&)>>;

//! `good` is accepted; each refusal applied to a copy of it gives invalid_parameter.
template <class P, class StatusOf>
void expect_refusals(const P& good, StatusOf status_of, const std::vector<Refusal<P>>& refusals) {
  ASSERT_EQ(status_of(good), Status::ok);
  for (const auto& [what, change] : refusals) {
    P bad = good;
    change(bad);
    EXPECT_EQ(status_of(bad), Status::invalid_parameter) << what;
  }
}

//! A parameter struct that a valid() predicate checks (free functions' parameters), as a Status.
template <class P>
Status valid_status(const P& p) {
  return adcs::valid(p) ? Status::ok : Status::invalid_parameter;
}

template <class Derived>
bool finite(const Eigen::DenseBase<Derived>& x) {
  return adcs::all_finite(x);
}

adcs::Mat<3, 4> four_wheel_axes() {
  const double s = 1.0 / std::sqrt(3.0);
  adcs::Mat<3, 4> G;
  G << 1, 0, 0, s, 0, 1, 0, s, 0, 0, 1, s;
  return G;
}

// ============================================================================ core/validation
TEST(ParameterValidationCore, PredicatesRefuseNaNInfAndUnphysicalMatrices) {
  EXPECT_TRUE(adcs::finite_positive(1e-300));
  EXPECT_FALSE(adcs::finite_positive(0.0));
  EXPECT_FALSE(adcs::finite_positive(kInf));
  EXPECT_FALSE(adcs::finite_positive(adcs::kUnset));
  EXPECT_TRUE(adcs::finite_nonnegative(0.0));
  EXPECT_FALSE(adcs::finite_nonnegative(-1e-300));
  EXPECT_FALSE(adcs::finite_nonnegative(Vec3(1.0, kNaN, 1.0)));
  EXPECT_TRUE(adcs::symmetric_positive_definite<3>(Vec3(1, 2, 3).asDiagonal()));
  EXPECT_FALSE(adcs::symmetric_positive_definite<3>(Vec3(1, 0, 3).asDiagonal()));  // singular
  Mat3 asym = Mat3::Identity();
  asym(0, 1) = 0.1;
  EXPECT_FALSE(adcs::symmetric_positive_definite<3>(asym));
  EXPECT_TRUE(adcs::symmetric_positive_semidefinite<3>(Vec3(1, 0, 3).asDiagonal()));
  EXPECT_FALSE(adcs::symmetric_positive_semidefinite<3>(Vec3(1, -1e-3, 3).asDiagonal()));
  EXPECT_FALSE(adcs::symmetric_positive_semidefinite<3>(Mat3::Constant(adcs::kUnset)));
  EXPECT_TRUE((adcs::unit_columns<3, 4>(four_wheel_axes())));
  EXPECT_FALSE((adcs::unit_columns<3, 4>(1.001 * four_wheel_axes())));
}

// ============================================================================ actuator/
TEST(ParameterValidationActuator, QuantizerChannelDefaultIsSeed003TorqueRowAndRefusals) {
  using P = adcs::QuantizerChannelParams;
  expect_refusals<P>(P{}, [](const P& p) { return adcs::QuantizerChannel(p).status(); },
                     {{"rho NaN", [](P& p) { p.rho = kNaN; }},
                      {"rho 0", [](P& p) { p.rho = 0.0; }},
                      {"rho 1", [](P& p) { p.rho = 1.0; }},
                      {"u_min 0", [](P& p) { p.u_min = 0.0; }},
                      {"u_min inf", [](P& p) { p.u_min = kInf; }},
                      {"u_s < u_min", [](P& p) { p.u_s = 0.5 * p.u_min; }},
                      {"sigma 0", [](P& p) { p.sigma = 0.0; }},
                      {"sigma NaN", [](P& p) { p.sigma = kNaN; }},
                      {"more than kMaxQuantizerLevels levels", [](P& p) {
                         p.rho = 0.9;
                         p.u_s = 1e6;
                       }}});
}

TEST(ParameterValidationActuator, RefusedCompositeQuantizerAppliesNothing) {
  EXPECT_EQ(adcs::CompositeQuantizer<6>(adcs::CompositeQuantizerParams<6>{}).status(), Status::ok);
  adcs::CompositeQuantizerParams<6> p = adcs::seed003_quantizer_params();
  p.channel[4].sigma = -1.0;
  adcs::CompositeQuantizer<6> q(p);
  EXPECT_EQ(q.status(), Status::invalid_parameter);
  Vec6 u_q = Vec6::Constant(7.0);
  EXPECT_EQ(q.apply(Vec6::Constant(0.1), u_q), Status::invalid_parameter);
  EXPECT_EQ(u_q, Vec6::Constant(7.0));  // untouched
  EXPECT_EQ(q.transmissions(), 0u);
}

TEST(ParameterValidationActuator, RwAllocatorHasNoDefaultGeometryAndRefusals) {
  using P = adcs::RwAllocationParams<4>;
  EXPECT_EQ(adcs::RwTorqueAllocator<4>(P{}).status(), Status::invalid_parameter);  // axes unset
  P good;
  good.G_s_B = four_wheel_axes();
  EXPECT_EQ(good.torque_limit, 0.2);  // the rigid-rw-mrp-pd vehicle's limit
  expect_refusals<P>(good, [](const P& p) { return adcs::RwTorqueAllocator<4>(p).status(); },
                     {{"axis NaN", [](P& p) { p.G_s_B(1, 2) = kNaN; }},
                      {"axis not unit", [](P& p) { p.G_s_B.col(3) *= 1.1; }},
                      {"axes in a plane", [](P& p) {
                         const double c = 1.0 / std::sqrt(2.0);  // unit columns that cannot span z
                         p.G_s_B << 1, 0, -1, c, 0, 1, 0, c, 0, 0, 0, 0;
                       }},
                      {"limit 0", [](P& p) { p.torque_limit = 0.0; }},
                      {"limit < 0", [](P& p) { p.torque_limit = -0.2; }},
                      {"limit NaN", [](P& p) { p.torque_limit = kNaN; }},
                      {"limit inf", [](P& p) { p.torque_limit = kInf; }}});
}

// Issue 17: a failed step outputs zero wheel torques (the wheels coast); it used to leave u_s untouched.
TEST(ParameterValidationActuator, RefusedRwAllocatorOutputsZeroWheelTorques) {
  const adcs::RwTorqueAllocator<4> a(adcs::RwAllocationParams<4>{});
  adcs::WheelTorques<4> u;
  u.u_s_Nm.setConstant(0.05);
  EXPECT_EQ(a.step(adcs::BodyTorque{Vec3(0.1, 0.0, 0.0)}, u), Status::invalid_parameter);
  EXPECT_EQ(u.u_s_Nm, adcs::Vec<4>::Zero());
}

TEST(ParameterValidationActuator, SaturationLimitNotPositiveMeansNone) {
  // saturate_each has no parameter struct: a limit that is not > 0 (0, < 0, NaN) is "no limit".
  adcs::Vec<3> u(5.0, -5.0, 5.0);
  EXPECT_EQ(adcs::saturate_each<3>(u, adcs::Vec<3>(kNaN, 0.0, 1.0)), 1);
  EXPECT_EQ(u, adcs::Vec<3>(5.0, -5.0, 1.0));
}

// The component (issue 17), unlike saturate_each, has parameters: a limit must be set and > 0;
// +inf is accepted and means no limit on that channel.
TEST(ParameterValidationActuator, SaturationHasNoDefaultLimitAndRefusals) {
  using P = adcs::SaturationParams<3>;
  const adcs::Saturation<3> unset(P{});
  EXPECT_EQ(unset.status(), Status::invalid_parameter);  // limit unset
  Vec3 out = Vec3::Constant(9.0);
  EXPECT_EQ(unset.step(Vec3::Ones(), out), Status::invalid_parameter);
  EXPECT_EQ(out, Vec3::Zero());  // the actuators idle
  P good;
  good.limit = Vec3(1.0, 2.0, kInf);  // +inf: no limit on the third channel
  expect_refusals<P>(good, [](const P& p) { return adcs::Saturation<3>(p).status(); },
                     {{"limit unset", [](P& p) { p.limit = P{}.limit; }},
                      {"limit NaN", [](P& p) { p.limit(1) = kNaN; }},
                      {"limit 0", [](P& p) { p.limit(0) = 0.0; }},
                      {"limit < 0", [](P& p) { p.limit(2) = -1.0; }},
                      {"limit -inf", [](P& p) { p.limit(2) = -kInf; }}});
  P none;
  none.limit.setConstant(kInf);
  const adcs::Saturation<3> unlimited(none);
  EXPECT_EQ(unlimited.status(), Status::ok);
  EXPECT_EQ(unlimited.step(Vec3(1e6, -1e6, 3.0), out), Status::ok);
  EXPECT_EQ(out, Vec3(1e6, -1e6, 3.0));
}

TEST(ParameterValidationActuator, SaturatedQuantizerHasNoDefaultLimitAndRefusals) {
  using P = adcs::SaturatedQuantizerParams<6>;
  adcs::SaturatedQuantizer<6> unset(P{});
  EXPECT_EQ(unset.status(), Status::invalid_parameter);  // limit unset (the default channels are valid)
  Vec6 out = Vec6::Constant(9.0);
  EXPECT_EQ(unset.step(Vec6::Constant(0.1), out), Status::invalid_parameter);
  EXPECT_EQ(out, Vec6::Zero());
  EXPECT_EQ(unset.quantizer().transmissions(), 0u);
  P good;
  good.quantizer = adcs::seed003_quantizer_params();
  good.limit << 0.5, 0.5, 0.5, 5.0, 5.0, 5.0;  // seed 003's actuator limits (exact levels, 5 sigma)
  expect_refusals<P>(good, [](const P& p) { return adcs::SaturatedQuantizer<6>(p).status(); },
                     {{"limit unset", [](P& p) { p.limit = P{}.limit; }},
                      {"limit NaN", [](P& p) { p.limit(4) = kNaN; }},
                      {"limit 0", [](P& p) { p.limit(0) = 0.0; }},
                      {"limit < 0", [](P& p) { p.limit(3) = -5.0; }},
                      {"channel refused", [](P& p) { p.quantizer.channel[2].sigma = 0.0; }}});
}

TEST(ParameterValidationActuator, VscmgSteeringHasNoDefaultGeometryAndRefusals) {
  using P = adcs::VscmgSteeringParams<4, 3>;
  using C = adcs::VscmgSteering<4, 3>;
  const C unset(P{});
  EXPECT_EQ(unset.status(), Status::invalid_parameter);  // geometry unset
  adcs::VscmgRates<4, 3> out = adcs::VscmgRates<4, 3>::from_stacked(adcs::Vec<7>::Constant(9.0));
  adcs::VscmgSteeringInput<4, 3> in;
  in.request.torque_B_Nm = Vec3(1e-3, 0.0, 0.0);
  EXPECT_EQ(unset.step(in, out), Status::invalid_parameter);
  EXPECT_EQ(out.stacked(), adcs::Vec<7>::Zero());  // zero rates: the gimbals hold, the wheels coast
  P good;
  good.geometry = adcs::pyramid_4cmg_3rw_nominal();
  expect_refusals<P>(good, [](const P& p) { return C(p).status(); },
                     {{"geometry unset", [](P& p) { p.geometry = adcs::VscmgGeometry<4, 3>{}; }},
                      {"spin axis NaN", [](P& p) { p.geometry.A_cs0(1, 2) = kNaN; }},
                      {"transverse axis not unit", [](P& p) { p.geometry.A_ct0.col(3) *= 1.1; }},
                      {"wheel axes unset", [](P& p) { p.geometry.A_ws.setConstant(adcs::kUnset); }},
                      {"h_cw < 0", [](P& p) { p.geometry.h_cw(0) = -10.0; }},
                      {"I_wws unset", [](P& p) { p.geometry.I_wws.setConstant(adcs::kUnset); }},
                      {"robust threshold NaN", [](P& p) { p.robust.sigma_threshold = kNaN; }},
                      {"escape lambda0 inf", [](P& p) { p.escape.lambda0 = kInf; }}});
}

TEST(ParameterValidationActuator, SteeringDefaultsValidAndRefusals) {
  using P = adcs::SteeringParams;
  expect_refusals<P>(P{}, valid_status<P>,
                     {{"threshold NaN", [](P& p) { p.sigma_threshold = kNaN; }},
                      {"threshold < 0", [](P& p) { p.sigma_threshold = -1.0; }},
                      {"lambda inf", [](P& p) { p.lambda_max = kInf; }},
                      {"error bound 0", [](P& p) { p.max_torque_error = 0.0; }},
                      {"error bound > 1", [](P& p) { p.max_torque_error = 1.5; }}});
  adcs::Vec<4> u = adcs::Vec<4>::Constant(3.0);
  P bad;
  bad.lambda_max = -1.0;
  EXPECT_EQ(adcs::steer<4>(four_wheel_axes(), Vec3(1, 0, 0), bad, u), Status::invalid_parameter);
  EXPECT_EQ(u, adcs::Vec<4>::Constant(3.0));
}

TEST(ParameterValidationActuator, EscapeSteeringDefaultsAreWie2005AndRefusals) {
  using P = adcs::EscapeSteeringParams;
  expect_refusals<P>(P{}, valid_status<P>,
                     {{"lambda0 below the minimum", [](P& p) { p.lambda0 = 0.0; }},
                      {"lambda0 inf", [](P& p) { p.lambda0 = kInf; }},
                      {"mu < 0", [](P& p) { p.mu = -1.0; }},
                      {"epsilon0 0.5", [](P& p) { p.epsilon0 = 0.5; }},
                      {"omega NaN", [](P& p) { p.omega_rad_s = kNaN; }},
                      {"phase NaN", [](P& p) { p.phase_rad(1) = kNaN; }},
                      {"error bound 0", [](P& p) { p.max_torque_error = 0.0; }}});
}

TEST(ParameterValidationActuator, ActuatorLimitsDefaultIsNoLimitAndRefusals) {
  using P = adcs::ActuatorLimits<4, 3>;
  expect_refusals<P>(P{}, valid_status<P>,
                     {{"gimbal rate NaN", [](P& p) { p.gimbal_rate_max_rad_s(0) = kNaN; }},
                      {"gimbal rate 0", [](P& p) { p.gimbal_rate_max_rad_s(3) = 0.0; }},
                      {"wheel torque < 0", [](P& p) { p.wheel_torque_max_Nm(1) = -1e-3; }},
                      {"wheel speed NaN", [](P& p) { p.wheel_speed_max_rad_s(2) = kNaN; }}});
  adcs::ActuatorLimits<0, 4> bad;
  bad.wheel_torque_max_Nm(0) = 0.0;
  adcs::Vec<4> u = adcs::Vec<4>::Constant(1e-3);
  EXPECT_EQ(adcs::limit_wheel_torques<4>(bad, adcs::Vec<4>::Zero(), u), Status::invalid_parameter);
  EXPECT_EQ(u, adcs::Vec<4>::Constant(1e-3));
}

// ============================================================================ adapt/
TEST(ParameterValidationAdapt, ProjectionDefaultsAreSeed001AndRefusals) {
  using P = adcs::ProjectionParams;
  expect_refusals<P>(P{}, valid_status<P>,
                     {{"alpha NaN", [](P& p) { p.alpha = kNaN; }},
                      {"alpha < 0", [](P& p) { p.alpha = -1.0; }},
                      {"beta 0", [](P& p) { p.beta = 0.0; }},
                      {"beta inf", [](P& p) { p.beta = kInf; }},
                      {"delta 0", [](P& p) { p.delta = 0.0; }},
                      {"delta NaN", [](P& p) { p.delta = kNaN; }}});
  P bad;
  bad.delta = -0.1;
  Vec3 rate = Vec3::Constant(4.0);
  EXPECT_EQ(adcs::smooth_projection<3>(Vec3::Ones(), Vec3::Ones(), bad, rate), Status::invalid_parameter);
  EXPECT_EQ(rate, Vec3::Constant(4.0));
}

TEST(ParameterValidationAdapt, RbfLayerHasNoDefaultAndRefusals) {
  using P = adcs::RbfLayerParams<6, 7>;
  const adcs::RbfLayer<6, 7> unset(P{});
  EXPECT_EQ(unset.status(), Status::invalid_parameter);
  EXPECT_EQ(unset.activations(adcs::Vec<6>::Zero()), adcs::Vec<7>::Zero());  // refused: no activation
  expect_refusals<P>(adcs::seed002_rbf_layer(), [](const P& p) { return adcs::RbfLayer<6, 7>(p).status(); },
                     {{"centre NaN", [](P& p) { p.centers(2, 5) = kNaN; }},
                      {"centre inf", [](P& p) { p.centers(0, 0) = -kInf; }},
                      {"width 0", [](P& p) { p.widths(3) = 0.0; }},
                      {"width < 0", [](P& p) { p.widths(3) = -0.1; }},
                      {"width inf", [](P& p) { p.widths(6) = kInf; }}});
}

TEST(ParameterValidationAdapt, RbfCompensatorGainsAreSeed002AndRefusals) {
  using P = adcs::RbfCompensatorParams<6, 7, 3>;
  EXPECT_EQ((adcs::RbfCompensator<6, 7, 3>(P{}).status()), Status::invalid_parameter);  // layer unset
  expect_refusals<P>(adcs::seed002_compensator(),
                     [](const P& p) { return adcs::RbfCompensator<6, 7, 3>(p).status(); },
                     {{"layer refused", [](P& p) { p.layer.widths(0) = 0.0; }},
                      {"tau_w < 0", [](P& p) { p.tau_w(1) = -0.5; }},
                      {"tau_w NaN", [](P& p) { p.tau_w(2) = kNaN; }},
                      {"tau_mu < 0", [](P& p) { p.tau_mu = -0.5; }},
                      {"beta < 0", [](P& p) { p.beta = -0.01; }},
                      {"gamma inf", [](P& p) { p.gamma = kInf; }},
                      {"sigma 0", [](P& p) { p.sigma = 0.0; }},
                      {"sigma NaN", [](P& p) { p.sigma = kNaN; }}});
}

TEST(ParameterValidationAdapt, RefusedRbfCompensatorEvaluatesToZeroAndNeverAdapts) {
  adcs::RbfCompensatorParams<6, 7, 3> p = adcs::seed002_compensator();
  p.sigma = -1.0;
  adcs::RbfCompensator<6, 7, 3> c(p);
  ASSERT_EQ(c.status(), Status::invalid_parameter);
  const auto o = c.evaluate(adcs::Vec<6>::Zero(), Vec3::Ones());
  EXPECT_EQ(o.D_hat, Vec3::Zero());
  EXPECT_EQ(o.robust, Vec3::Zero());
  adcs::Mat<7, 3> W;
  double mu = -1.0;
  c.propose(o, Vec3::Ones(), 0.1, W, mu);
  EXPECT_EQ(W, (adcs::Mat<7, 3>::Zero()));
  EXPECT_EQ(mu, 0.0);
}

TEST(ParameterValidationAdapt, NormalizedStepIgnoresAnInvalidLimit) {
  // normalized_step_scale has no parameter struct: the law validates λ_max; an invalid one here
  // leaves the step unscaled rather than dividing by it.
  EXPECT_EQ(adcs::normalized_step_scale(3.0, kNaN), 1.0);
  EXPECT_EQ(adcs::normalized_step_scale(3.0, 0.0), 1.0);
  EXPECT_EQ(adcs::normalized_step_scale(3.0, -1.0), 1.0);
}

TEST(ParameterValidationAdapt, PrescribedPerformanceRefusals) {
  using P = adcs::PpcParams<3>;
  expect_refusals<P>(adcs::seed002_performance(), [](const P& p) { return adcs::PrescribedPerformance<3>(p).status(); },
                     {{"rho0 NaN", [](P& p) { p.rho[0].rho0 = kNaN; }},
                      {"rho_inf 0", [](P& p) { p.rho[1].rho_inf = 0.0; }},
                      {"delta > 1", [](P& p) { p.delta(2) = 1.5; }},
                      {"delta < 0", [](P& p) { p.delta(0) = -0.1; }}});
}

// ============================================================================ control/
TEST(ParameterValidationControl, MrpPdHasNoDefaultsAndStepsRefusedToZeroTorque) {
  adcs::MrpPd<4> law(adcs::MrpPdParams<4>{});
  EXPECT_EQ(law.status(), Status::invalid_parameter);
  adcs::BodyTorque out;
  out.torque_B_Nm = Vec3::Constant(9.0);
  EXPECT_EQ(law.step({}, out), Status::invalid_parameter);
  EXPECT_EQ(out.torque_B_Nm, Vec3::Zero());
}

// Issue 17: the sample period is a parameter of every component, and MrpPd's has no default.
TEST(ParameterValidationControl, MrpPdRefusesAMissingPeriod) {
  using P = adcs::MrpPdParams<4>;
  P good;
  good.K = 3.0;
  good.P = 40.0 * Mat3::Identity();
  good.J_rw_B = Vec3(900, 800, 600).asDiagonal();
  good.G_s_B = four_wheel_axes();
  good.J_s.setConstant(0.1);
  good.period_s = 0.1;
  expect_refusals<P>(good, [](const P& p) { return adcs::MrpPd<4>(p).status(); },
                     {{"period unset", [](P& p) { p.period_s = P{}.period_s; }},
                      {"period NaN", [](P& p) { p.period_s = kNaN; }},
                      {"period 0", [](P& p) { p.period_s = 0.0; }},
                      {"period < 0", [](P& p) { p.period_s = -0.1; }},
                      {"period inf", [](P& p) { p.period_s = kInf; }}});
}

TEST(ParameterValidationControl, PidHasNoDefaultProportionalGainAndRefusals) {
  using P = adcs::PidParams<3>;
  EXPECT_EQ(adcs::Pid<3>(P{}).status(), Status::invalid_parameter);  // K_P unset
  P good;
  good.kp = Vec3(1, 2, 3);
  EXPECT_EQ(good.period_s, 0.1);  // seed 004 §4
  expect_refusals<P>(good, [](const P& p) { return adcs::Pid<3>(p).status(); },
                     {{"kp NaN", [](P& p) { p.kp(0) = kNaN; }},
                      {"kp < 0", [](P& p) { p.kp(1) = -1.0; }},
                      {"ki inf", [](P& p) { p.ki(2) = kInf; }},
                      {"ki < 0", [](P& p) { p.ki(0) = -0.1; }},
                      {"kd < 0", [](P& p) { p.kd(0) = -1.0; }},
                      {"period 0", [](P& p) { p.period_s = 0.0; }},
                      {"period NaN", [](P& p) { p.period_s = kNaN; }},
                      {"period inf", [](P& p) { p.period_s = kInf; }}});
  adcs::Pid<3> refused(P{});
  adcs::PidOutput<3> out{Vec3::Constant(9.0)};
  EXPECT_EQ(refused.step(adcs::PidInput<3>{Vec3::Ones(), Vec3::Ones()}, out), Status::invalid_parameter);
  EXPECT_EQ(out.u, Vec3::Zero());
}

TEST(ParameterValidationControl, DragFreeAdrcDefaultIsSeed004AndRefusals) {
  using P = adcs::DragFreeAdrcParams;
  expect_refusals<P>(P{}, [](const P& p) { return adcs::DragFreeAdrc(p).status(); },
                     {{"alpha 0", [](P& p) { p.alpha = 0.0; }},
                      {"alpha > 1", [](P& p) { p.alpha = 1.5; }},
                      {"delta 0", [](P& p) { p.delta = 0.0; }},
                      {"delta NaN", [](P& p) { p.delta = kNaN; }},
                      {"limit 0", [](P& p) { p.limit = 0.0; }},
                      {"limit inf", [](P& p) { p.limit = kInf; }},
                      {"attitude kp < 0", [](P& p) { p.attitude.kp = -1e-3; }},
                      {"drag-free ki NaN", [](P& p) { p.drag_free.ki = kNaN; }},
                      {"TM kd inf", [](P& p) { p.tm_attitude.kd = kInf; }},
                      {"PID kd < 0", [](P& p) { p.pid_kd = -9.0; }},
                      {"plant m_sc 0", [](P& p) { p.plant.m_sc = 0.0; }},
                      {"plant I_sc not SPD", [](P& p) { p.plant.I_sc(2, 2) = -1.0; }},
                      {"plant period_s NaN", [](P& p) { p.plant.period_s = kNaN; }}});
  P bad;
  bad.limit = -1.0;
  adcs::DragFreeAdrc refused(bad);
  adcs::DragFreeActuation u = adcs::DragFreeActuation::from_stacked(adcs::Vec<9>::Constant(9.0));
  EXPECT_EQ(refused.step(adcs::DragFreeAdrcInput{}, u), Status::invalid_parameter);
  EXPECT_EQ(u.stacked(), adcs::Vec<9>::Zero());
}

TEST(ParameterValidationControl, NonsingularPowerDefaultIsSpecA8AndRefusals) {
  using P = adcs::NonsingularPowerParams;
  expect_refusals<P>(P{}, [](const P& p) { return adcs::NonsingularPower(p).status(); },
                     {{"p 0", [](P& p) { p.p = 0.0; }},
                      {"p 1", [](P& p) { p.p = 1.0; }},
                      {"p NaN", [](P& p) { p.p = kNaN; }},
                      {"eps 0", [](P& p) { p.eps = 0.0; }},
                      {"eps inf", [](P& p) { p.eps = kInf; }}});
  const adcs::NonsingularPower refused(P{0.5, -1.0});
  EXPECT_EQ(refused.value(0.3), 0.0);
  EXPECT_EQ(refused.derivative(0.0), 0.0);
}

adcs::Se3SpacecraftParams seed003_nominal() {
  return adcs::se3_chaser_nominal_params(adcs::Se3ScenarioParams{});
}

//! The SE(3) laws' parameters with the fields that have no default set: the nominal model (both
//! laws) and, for the prescribed-time law, ζ = 1.05 ϖ of seed 003's quantizer.
adcs::FtsmcSe3Params ftsmc_se3_params() {
  adcs::FtsmcSe3Params p;
  p.nominal = seed003_nominal();
  return p;
}

adcs::PrescribedTimeSe3Params prescribed_time_se3_params() {
  adcs::PrescribedTimeSe3Params p;
  p.zeta = adcs::quantization_compensation_gain(adcs::seed003_quantizer_params());
  p.nominal = seed003_nominal();
  return p;
}

TEST(ParameterValidationControl, FtsmcSe3DefaultIsSpecA8Table2AndRefusals) {
  using P = adcs::FtsmcSe3Params;
  EXPECT_EQ(adcs::FtsmcSe3(P{}).status(), Status::invalid_parameter);  // nominal unset
  expect_refusals<P>(ftsmc_se3_params(), [](const P& p) { return adcs::FtsmcSe3(p).status(); },
                     {{"p_s 0", [](P& p) { p.p_s = 0.0; }},
                      {"p_s 1", [](P& p) { p.p_s = 1.0; }},
                      {"eps 0", [](P& p) { p.eps = 0.0; }},
                      {"C1 < 0", [](P& p) { p.C1(0) = -0.05; }},
                      {"C2 NaN", [](P& p) { p.C2(4) = kNaN; }},
                      {"K_a inf", [](P& p) { p.K_a(2) = kInf; }},
                      {"K_b < 0", [](P& p) { p.K_b(5) = -0.05; }},
                      {"rho 0", [](P& p) { p.rho = 0.0; }},
                      {"rho NaN", [](P& p) { p.rho = kNaN; }},
                      {"k_s < 0", [](P& p) { p.k_s = -1.0; }},
                      {"k_s inf", [](P& p) { p.k_s = kInf; }},
                      {"phi 0", [](P& p) { p.phi = 0.0; }},
                      {"phi inf", [](P& p) { p.phi = kInf; }},
                      {"period_s 0", [](P& p) { p.period_s = 0.0; }},
                      {"period_s NaN", [](P& p) { p.period_s = kNaN; }},
                      {"nominal unset", [](P& p) { p.nominal = adcs::Se3SpacecraftParams{}; }}});
  P bad_nominal = ftsmc_se3_params();
  bad_nominal.nominal.m = 0.0;
  adcs::FtsmcSe3 refused(bad_nominal);
  EXPECT_EQ(refused.status(), Status::invalid_parameter);
  adcs::Wrench u = adcs::Wrench::from_stacked(Vec6::Constant(9.0));
  EXPECT_EQ(refused.step(adcs::Se3TrackingInput{}, u), Status::invalid_parameter);
  EXPECT_EQ(u.stacked(), Vec6::Zero());
}

TEST(ParameterValidationControl, PrescribedTimeSe3DefaultIsSpecA8Table1AndRefusals) {
  using P = adcs::PrescribedTimeSe3Params;
  EXPECT_EQ(adcs::PrescribedTimeSe3(P{}).status(), Status::invalid_parameter);  // zeta, nominal unset
  expect_refusals<P>(prescribed_time_se3_params(), [](const P& p) { return adcs::PrescribedTimeSe3(p).status(); },
                     {{"p 0", [](P& p) { p.p = 0.0; }},
                      {"p 1", [](P& p) { p.p = 1.0; }},
                      {"T 0", [](P& p) { p.T = 0.0; }},
                      {"T inf", [](P& p) { p.T = kInf; }},
                      {"period_s 0", [](P& p) { p.period_s = 0.0; }},
                      {"period_s NaN", [](P& p) { p.period_s = kNaN; }},
                      {"a 0", [](P& p) { p.a = 0.0; }},
                      {"a inf", [](P& p) { p.a = kInf; }},
                      {"eps1 0", [](P& p) { p.eps1 = 0.0; }},
                      {"eps2 NaN", [](P& p) { p.eps2 = kNaN; }},
                      {"eps_q 0", [](P& p) { p.eps_q = 0.0; }},
                      {"gamma < 0", [](P& p) { p.gamma = -1e-7; }},
                      {"sigma1 NaN", [](P& p) { p.sigma1 = kNaN; }},
                      {"sigma2 inf", [](P& p) { p.sigma2 = kInf; }},
                      {"psi_hat0 < 0", [](P& p) { p.psi_hat0 = -1e-4; }},
                      {"K2 < 0", [](P& p) { p.K2(0) = -0.02; }},
                      {"K3 inf", [](P& p) { p.K3(3) = kInf; }},
                      {"Lambda < 0", [](P& p) { p.Lambda(1) = -2.0; }},
                      {"Upsilon NaN", [](P& p) { p.Upsilon(4) = kNaN; }},
                      {"Lambda2 < 0", [](P& p) { p.Lambda2(2) = -1.0; }},
                      {"Upsilon2 inf", [](P& p) { p.Upsilon2(5) = kInf; }},
                      {"zeta < 0", [](P& p) { p.zeta(0) = -0.1; }},
                      {"zeta NaN", [](P& p) { p.zeta(3) = kNaN; }},
                      {"zeta unset", [](P& p) { p.zeta = P{}.zeta; }},
                      {"nominal unset", [](P& p) { p.nominal = adcs::Se3SpacecraftParams{}; }}});
  P bad = prescribed_time_se3_params();
  bad.period_s = -0.125;
  adcs::PrescribedTimeSe3 refused(bad);
  adcs::Wrench u = adcs::Wrench::from_stacked(Vec6::Constant(9.0));
  EXPECT_EQ(refused.step(adcs::Se3TrackingInput{}, u), Status::invalid_parameter);
  EXPECT_EQ(u.stacked(), Vec6::Zero());
  EXPECT_TRUE(std::isfinite(refused.psi_hat()));
}

TEST(ParameterValidationControl, HybridAdaptiveHasNoDefaultGeometryAndRefusals) {
  using P = adcs::HybridAdaptiveParams<4, 3>;
  EXPECT_EQ((adcs::HybridAdaptive<4, 3>(P{}).status()), Status::invalid_parameter);  // nominal unset
  P good;
  good.nominal = adcs::pyramid_4cmg_3rw_nominal();
  expect_refusals<P>(good, [](const P& p) { return adcs::HybridAdaptive<4, 3>(p).status(); },
                     {{"pole in the right half-plane", [](P& p) { p.poles[0] = {{{0.2, 0.2}, {0.2, -0.2}}}; }},
                      {"pole at 0", [](P& p) { p.poles[2] = {{{0.0, 0.0}, {-0.3, 0.0}}}; }},
                      {"pole NaN", [](P& p) { p.poles[1][0] = {kNaN, 0.3}; }},
                      {"poles not conjugate", [](P& p) { p.poles[1] = {{{-0.3, 0.3}, {-0.3, 0.3}}}; }},
                      {"Q_L not SPD", [](P& p) { p.Q_L(3, 3) = -1.0; }},
                      {"Q_L not symmetric", [](P& p) { p.Q_L(0, 5) = 0.5; }},
                      {"alpha_F < 0", [](P& p) { p.alpha_F = -1.0; }},
                      {"alpha_F inf", [](P& p) { p.alpha_F = kInf; }},
                      {"alpha_G NaN", [](P& p) { p.alpha_G = kNaN; }},
                      {"beta_G 0", [](P& p) { p.beta_G = 0.0; }},
                      {"delta_G < 0", [](P& p) { p.delta_G = -0.1; }},
                      {"H_I_n NaN", [](P& p) { p.H_I_n(1) = kNaN; }},
                      {"period 0", [](P& p) { p.period_s = 0.0; }},
                      {"period inf", [](P& p) { p.period_s = kInf; }},
                      {"max_step_gain 0", [](P& p) { p.max_step_gain = 0.0; }},
                      {"steering bound 0", [](P& p) { p.steering.max_torque_error = 0.0; }},
                      {"nominal J_s unset", [](P& p) { p.nominal.J_s = Mat3::Constant(adcs::kUnset); }},
                      {"nominal h_cw < 0", [](P& p) { p.nominal.h_cw(0) = -10.0; }}});
  adcs::HybridAdaptive<4, 3> refused(P{});
  adcs::VscmgRates<4, 3> out = adcs::VscmgRates<4, 3>::from_stacked(adcs::Vec<7>::Constant(9.0));
  EXPECT_EQ(refused.step({}, out), Status::invalid_parameter);
  EXPECT_EQ(out.stacked(), (adcs::Vec<7>::Zero()));
}

TEST(ParameterValidationControl, EulerTrackingLawsHaveNoDefaultInertiaAndRefusals) {
  using G = adcs::EulerTrackingGains;
  EXPECT_EQ(adcs::AdaptiveTracking(adcs::AdaptiveTrackingParams{}).status(), Status::invalid_parameter);  // J unset
  EXPECT_EQ(adcs::PpcNeural(adcs::PpcNeuralParams{}).status(), Status::invalid_parameter);
  expect_refusals<G>(adcs::seed002_tracking_gains(),
                     [](const G& g) { return adcs::AdaptiveTracking(adcs::AdaptiveTrackingParams{g}).status(); },
                     {{"J not SPD", [](G& g) { g.J(2, 2) = -1.0; }},
                      {"lambda 0", [](G& g) { g.lambda(0) = 0.0; }},
                      {"K < 0", [](G& g) { g.K(1) = -0.1; }},
                      {"compensator refused", [](G& g) { g.compensator.sigma = 0.0; }},
                      {"period 0", [](G& g) { g.period_s = 0.0; }},
                      {"period NaN", [](G& g) { g.period_s = kNaN; }}});
  adcs::AdaptiveTracking refused(adcs::AdaptiveTrackingParams{});
  adcs::BodyTorque out;
  out.torque_B_Nm = Vec3::Constant(9.0);
  EXPECT_EQ(refused.step({}, out), Status::invalid_parameter);
  EXPECT_EQ(out.torque_B_Nm, Vec3::Zero());
  adcs::PpcNeural refused_ppc(adcs::PpcNeuralParams{});
  out.torque_B_Nm = Vec3::Constant(9.0);
  EXPECT_EQ(refused_ppc.step({}, out), Status::invalid_parameter);
  EXPECT_EQ(out.torque_B_Nm, Vec3::Zero());
}

// ============================================================================ estimate/
using SmallEskf = adcs::Eskf<3, 2, 1, 2>;

SmallEskf::Params small_eskf() {
  SmallEskf::Params p;
  p.A_d << 1, 0.1, 0, 0, 1, 0.1, 0, 0, 1;
  p.B_d << 0, 0, 0.1, 0, 0, 0.1;
  p.B_e << 0, 0, 1;
  p.C_d << 1, 0, 0, 0, 1, 0;
  p.q(0) = 1e-4;
  p.S = adcs::Vec<2>(1e-6, 0.0).asDiagonal();  // PSD: no noise on the second input
  p.R = adcs::Vec<2>(1e-2, 1e-2).asDiagonal();
  p.period_s = 0.1;  // the period of A_d, B_d above
  return p;
}

TEST(ParameterValidationEstimate, EskfHasNoDefaultModelAndRefusals) {
  using P = SmallEskf::Params;
  EXPECT_EQ(SmallEskf(P{}).status(), Status::invalid_parameter);  // A_d, B_d, B_e, C_d, R unset
  expect_refusals<P>(small_eskf(), [](const P& p) { return SmallEskf(p).status(); },
                     {{"A_d NaN", [](P& p) { p.A_d(0, 1) = kNaN; }},
                      {"B_d unset", [](P& p) { p.B_d.setConstant(adcs::kUnset); }},
                      {"B_e inf", [](P& p) { p.B_e(2) = kInf; }},
                      {"C_d NaN", [](P& p) { p.C_d(1, 1) = kNaN; }},
                      {"q < 0", [](P& p) { p.q(0) = -1e-4; }},
                      {"q NaN", [](P& p) { p.q(0) = kNaN; }},
                      {"S not PSD", [](P& p) { p.S(1, 1) = -1e-6; }},
                      {"S not symmetric", [](P& p) { p.S(0, 1) = 1e-7; }},
                      {"R singular", [](P& p) { p.R(1, 1) = 0.0; }},
                      {"R not symmetric", [](P& p) { p.R(1, 0) = 1e-3; }},
                      {"x0 NaN", [](P& p) { p.x0(2) = kNaN; }},
                      {"P0 not PSD", [](P& p) { p.P0(1, 1) = -0.01; }},
                      {"P0 not symmetric", [](P& p) { p.P0(0, 2) = 0.001; }},
                      {"P0 zero", [](P& p) { p.P0.setZero(); }},
                      {"period unset", [](P& p) { p.period_s = P{}.period_s; }},
                      {"period NaN", [](P& p) { p.period_s = kNaN; }},
                      {"period 0", [](P& p) { p.period_s = 0.0; }}});
}

TEST(ParameterValidationEstimate, RefusedEskfLeavesItsEstimateUntouched) {
  SmallEskf::Params p = small_eskf();
  p.R(0, 0) = -1.0;
  SmallEskf f(p);
  ASSERT_EQ(f.status(), Status::invalid_parameter);
  const Vec3 x = f.state();
  EXPECT_EQ(f.predict(adcs::Vec<2>::Zero()), Status::invalid_parameter);
  EXPECT_EQ(f.update(adcs::Vec<2>::Ones()), Status::invalid_parameter);
  EXPECT_EQ(f.state(), x);
  EXPECT_TRUE(finite(f.state()));
  EXPECT_TRUE(finite(f.covariance()));
}

adcs::DragFreeEskf::Params drag_free_eskf_params() {
  const adcs::DragFreeParams plant;
  adcs::DragFreeDiscrete d;
  EXPECT_EQ(adcs::drag_free_discretize(plant, d), Status::ok);
  adcs::DragFreeEskf::Params e;
  e.A_d = d.A_d;
  e.B_d = d.B_d;
  e.B_e = d.B_e;
  e.C_d = d.C_d;
  e.q.head<6>().setConstant(8.5e-13);
  e.R = 5e-16 * adcs::Mat<9, 9>::Identity();
  e.period_s = plant.period_s;  // the period A_d, B_d were discretised at (0.1 s)
  return e;
}

TEST(ParameterValidationEstimate, DragFreeEskfHasNoDefaultModelAndRefusesCoupling) {
  using P = adcs::DragFreeEskf::Params;
  adcs::DragFreeEskf unset(P{});
  EXPECT_EQ(unset.status(), Status::invalid_parameter);
  const adcs::Vec<27> x = unset.state();
  EXPECT_EQ(unset.predict(adcs::Vec<9>::Zero()), Status::invalid_parameter);
  EXPECT_EQ(unset.update(adcs::Vec<9>::Zero()), Status::invalid_parameter);
  EXPECT_EQ(unset.state(), x);
  EXPECT_TRUE(finite(unset.state()));
  expect_refusals<P>(drag_free_eskf_params(), [](const P& p) { return adcs::DragFreeEskf(p).status(); },
                     {{"A_d couples attitude and translation", [](P& p) { p.A_d(0, adcs::DragFreeIndex::r) = 1e-3; }},
                      {"R couples the blocks", [](P& p) { p.R(0, 3) = p.R(3, 0) = 1e-17; }},
                      {"R unset", [](P& p) { p.R.setConstant(adcs::kUnset); }},
                      {"S not PSD", [](P& p) { p.S(4, 4) = -1e-16; }},
                      {"q NaN", [](P& p) { p.q(7) = kNaN; }},
                      {"period unset", [](P& p) { p.period_s = P{}.period_s; }},
                      {"period NaN", [](P& p) { p.period_s = kNaN; }},
                      {"period 0", [](P& p) { p.period_s = 0.0; }}});
}

adcs::SaturatedEsfParams axis_esf() {
  const adcs::DragFreeParams plant;
  adcs::DragFreeAxisModel m;
  EXPECT_EQ(adcs::drag_free_axis_model(plant, 0, m), Status::ok);
  adcs::SaturatedEsfParams e;
  e.A_d = m.A_d;
  e.B_d = m.B_d;
  e.C = m.C;
  e.D = m.D;
  e.q = 8.5e-13;
  e.S = 1e-16;
  e.R_a = 5e-24;
  e.y_min = plant.accel_min;
  e.y_max = plant.accel_max;
  e.period_s = plant.period_s;  // the period the axis model was discretised at (0.1 s)
  return e;
}

TEST(ParameterValidationEstimate, SaturatedEsfHasNoDefaultModelAndRefusals) {
  using P = adcs::SaturatedEsfParams;
  adcs::SaturatedEsf unset(P{});
  EXPECT_EQ(unset.status(), Status::invalid_parameter);
  EXPECT_EQ(unset.predict(0.0), Status::invalid_parameter);
  EXPECT_EQ(unset.update(1e-6, 0.0), Status::invalid_parameter);
  EXPECT_EQ(unset.state(), Vec3::Zero());
  EXPECT_TRUE(finite(unset.covariance()));
  expect_refusals<P>(axis_esf(), [](const P& p) { return adcs::SaturatedEsf(p).status(); },
                     {{"A_d NaN", [](P& p) { p.A_d(1, 0) = kNaN; }},
                      {"B_d unset", [](P& p) { p.B_d.setConstant(adcs::kUnset); }},
                      {"B_e inf", [](P& p) { p.B_e(2) = kInf; }},
                      {"C NaN", [](P& p) { p.C(0) = kNaN; }},
                      {"D inf", [](P& p) { p.D = kInf; }},
                      {"q < 0", [](P& p) { p.q = -1e-13; }},
                      {"S NaN", [](P& p) { p.S = kNaN; }},
                      {"S < 0", [](P& p) { p.S = -1e-16; }},
                      {"R_a 0", [](P& p) { p.R_a = 0.0; }},
                      {"R_a inf", [](P& p) { p.R_a = kInf; }},
                      {"range empty", [](P& p) { p.y_min = p.y_max; }},
                      {"range NaN", [](P& p) { p.y_max = kNaN; }},
                      {"x0 NaN", [](P& p) { p.x0(0) = kNaN; }},
                      {"P0 not PSD", [](P& p) { p.P0(2, 2) = -0.01; }},
                      {"P0 zero", [](P& p) { p.P0.setZero(); }},
                      {"period unset", [](P& p) { p.period_s = P{}.period_s; }},
                      {"period NaN", [](P& p) { p.period_s = kNaN; }},
                      {"period 0", [](P& p) { p.period_s = 0.0; }}});
}

TEST(ParameterValidationEstimate, FusionRefusesARefusedFilter) {
  adcs::DragFreeEskf alg1(drag_free_eskf_params());
  ASSERT_EQ(alg1.status(), Status::ok);
  adcs::SaturatedEsf refused(adcs::SaturatedEsfParams{});
  const adcs::Vec<27> x1 = alg1.state();
  EXPECT_EQ(adcs::fuse_axis(alg1, refused, 0), Status::invalid_parameter);
  EXPECT_EQ(alg1.state(), x1);
  EXPECT_EQ(refused.state(), Vec3::Zero());
  adcs::DragFreeEskf unset(adcs::DragFreeEskf::Params{});
  adcs::SaturatedEsf alg2(axis_esf());
  ASSERT_EQ(alg2.status(), Status::ok);
  EXPECT_EQ(adcs::fuse_axis(unset, alg2, 1), Status::invalid_parameter);
  EXPECT_EQ(alg2.state(), Vec3::Zero());
}

// ============================================================================ plant/
TEST(ParameterValidationPlant, DragFreeDefaultIsSeed004Table2AndRefusals) {
  using P = adcs::DragFreeParams;
  expect_refusals<P>(P{}, valid_status<P>,
                     {{"m_tm 0", [](P& p) { p.m_tm = 0.0; }},
                      {"m_sc NaN", [](P& p) { p.m_sc = kNaN; }},
                      {"I_tm not SPD", [](P& p) { p.I_tm(0, 0) = -1e-4; }},
                      {"I_sc not symmetric", [](P& p) { p.I_sc(0, 1) = 5.0; }},
                      {"K_trans NaN", [](P& p) { p.K_trans(0, 2) = kNaN; }},
                      {"D_trans inf", [](P& p) { p.D_trans(1, 1) = kInf; }},
                      {"K_rot NaN", [](P& p) { p.K_rot(2, 0) = kNaN; }},
                      {"D_rot inf", [](P& p) { p.D_rot(2, 2) = kInf; }},
                      {"period_s 0", [](P& p) { p.period_s = 0.0; }},
                      {"period_s inf", [](P& p) { p.period_s = kInf; }},
                      {"accel range empty", [](P& p) { p.accel_min = p.accel_max; }},
                      {"accel range inf", [](P& p) { p.accel_max = kInf; }},
                      {"ASD < 0", [](P& p) { p.asd_acc = -1e-12; }},
                      {"ASD NaN", [](P& p) { p.asd_pos = kNaN; }}});
  P bad;
  bad.m_tm = -1.0;
  adcs::DragFreeDiscrete d;
  const adcs::Mat<27, 27> A0 = d.A_d;
  EXPECT_EQ(adcs::drag_free_discretize(bad, d), Status::invalid_parameter);
  EXPECT_EQ(d.A_d, A0);
  adcs::DragFreeAxisModel m;
  EXPECT_EQ(adcs::drag_free_axis_model(bad, 0, m), Status::invalid_parameter);
}

TEST(ParameterValidationPlant, RigidBodyRwHasNoDefaultsAndRefusals) {
  using Plant = adcs::RigidBodyRw<4>;
  using P = Plant::Params;
  const Plant unset(P{});
  EXPECT_EQ(unset.status(), Status::invalid_parameter);
  Plant::State xdot = Plant::State::Constant(9.0);
  unset.derivative(0.0, Plant::State::Constant(0.1), Plant::Input::Constant(0.01), xdot);
  EXPECT_EQ(xdot, Plant::State::Zero());  // a refused plant has no dynamics
  P good;
  good.J_B = Vec3(900, 800, 600).asDiagonal();
  good.G_s_B = four_wheel_axes();
  good.J_s.setConstant(0.1);
  expect_refusals<P>(good, [](const P& p) { return Plant(p).status(); },
                     {{"J_B NaN", [](P& p) { p.J_B(0, 0) = kNaN; }},
                      {"J_B not symmetric", [](P& p) { p.J_B(0, 1) = 10.0; }},
                      {"J_B not SPD", [](P& p) { p.J_B(2, 2) = -600.0; }},
                      {"axis not unit", [](P& p) { p.G_s_B.col(0) *= 2.0; }},
                      {"axis unset", [](P& p) { p.G_s_B.setConstant(adcs::kUnset); }},
                      {"J_s 0", [](P& p) { p.J_s(1) = 0.0; }},
                      {"J_s inf", [](P& p) { p.J_s(2) = kInf; }},
                      {"J_RW not SPD", [](P& p) { p.J_s(0) = 1e4; }}});
}

TEST(ParameterValidationPlant, VscmgGeometryHasNoDefaultsAndRefusals) {
  using Params = adcs::VscmgParams<4, 3>;
  using Full = adcs::VscmgFullPlant<4, 3>;
  using Ctrl = adcs::VscmgCtrlPlant<4, 3>;
  EXPECT_FALSE((adcs::valid(adcs::VscmgGeometry<4, 3>{})));
  const Full unset(Params{});
  EXPECT_EQ(unset.status(), Status::invalid_parameter);
  EXPECT_EQ(Ctrl(Params{}).status(), Status::invalid_parameter);
  Full::State xdot = Full::State::Constant(9.0);
  unset.derivative(0.0, Full::State::Constant(0.1), Full::Input::Constant(0.01), xdot);
  EXPECT_EQ(xdot, Full::State::Zero());
  expect_refusals<Params>(adcs::vscmg_params_A_REF(), [](const Params& p) { return Full(p).status(); },
                          {{"truth J_s unset", [](Params& p) { p.truth.J_s.setConstant(adcs::kUnset); }},
                           {"nominal J_s not symmetric", [](Params& p) { p.nominal.J_s(0, 1) = 5.0; }},
                           {"nominal J_s not SPD", [](Params& p) { p.nominal.J_s(2, 2) = -80.0; }},
                           {"gimbal axis NaN", [](Params& p) { p.truth.A_cg(0, 0) = kNaN; }},
                           {"spin axes unset", [](Params& p) { p.nominal.A_cs0.setConstant(adcs::kUnset); }},
                           {"wheel axes unset", [](Params& p) { p.truth.A_ws.setConstant(adcs::kUnset); }},
                           {"h_cw < 0", [](Params& p) { p.truth.h_cw(1) = -10.0; }},
                           {"I_cs < 0", [](Params& p) { p.nominal.I_cs(2) = -0.012; }},
                           {"I_wws inf", [](Params& p) { p.truth.I_wws(0) = kInf; }}});
  const Params good = adcs::vscmg_params_A_REF();
  EXPECT_EQ(Ctrl(good).status(), Status::ok);
  Mat3 J_n = good.nominal.J_tr(adcs::Vec<4>::Zero());
  J_n(1, 1) = -1.0;
  const Ctrl refused(good, J_n);
  EXPECT_EQ(refused.status(), Status::invalid_parameter);
  Ctrl::State xc = Ctrl::State::Constant(9.0);
  refused.derivative(0.0, Ctrl::State::Constant(0.1), Ctrl::Input::Constant(0.01), xc);
  EXPECT_EQ(xc, Ctrl::State::Zero());
}

TEST(ParameterValidationPlant, Se3SpacecraftHasNoDefaultMassPropertiesAndRefusals) {
  using P = adcs::Se3SpacecraftParams;
  const adcs::Se3Spacecraft unset(P{});
  EXPECT_EQ(unset.status(), Status::invalid_parameter);
  adcs::Se3SpacecraftRates rates;
  rates.v_dot_B = Vec3::Constant(9.0);
  adcs::Se3SpacecraftState x;
  x.R_N = Vec3(7e6, 0, 0);
  EXPECT_EQ(unset.derivative(x, Vec6::Zero(), Vec6::Zero(), rates), Status::invalid_parameter);
  EXPECT_EQ(rates.v_dot_B, Vec3::Constant(9.0));  // untouched
  expect_refusals<P>(seed003_nominal(), [](const P& p) { return adcs::Se3Spacecraft(p).status(); },
                     {{"J NaN", [](P& p) { p.J_B(1, 1) = kNaN; }},
                      {"J not symmetric", [](P& p) { p.J_B(0, 2) = 3.0; }},
                      {"J not SPD", [](P& p) { p.J_B(0, 0) = -25.0; }},
                      {"m 0", [](P& p) { p.m = 0.0; }},
                      {"m inf", [](P& p) { p.m = kInf; }},
                      {"mu 0", [](P& p) { p.env.mu = 0.0; }},
                      {"R_E NaN", [](P& p) { p.env.R_E = kNaN; }},
                      {"J2 inf", [](P& p) { p.env.J2 = kInf; }}});
}

TEST(ParameterValidationPlant, OrbitEnvironmentDefaultIsSeed003AndRefusals) {
  using P = adcs::OrbitEnvironmentParams;
  auto status_of = [](const P& p) { return adcs::orbit_environment_valid(p) ? Status::ok : Status::invalid_parameter; };
  expect_refusals<P>(P{}, status_of,
                     {{"mu 0", [](P& p) { p.mu = 0.0; }},
                      {"mu NaN", [](P& p) { p.mu = kNaN; }},
                      {"R_E < 0", [](P& p) { p.R_E = -6378e3; }},
                      {"J2 NaN", [](P& p) { p.J2 = kNaN; }}});
  P bad;
  bad.mu = -1.0;
  adcs::CircularOrbitLvlh o;
  EXPECT_EQ(adcs::circular_orbit_lvlh(400e3, 0.5, 0.0, 0.0, bad, o), Status::invalid_parameter);
}

TEST(ParameterValidationPlant, FlexibleSpacecraftHasNoDefaultsAndRefusals) {
  using Plant = adcs::FlexibleSpacecraft<2, 4>;
  using P = Plant::Params;
  const Plant unset(P{});
  EXPECT_EQ(unset.status(), Status::invalid_parameter);
  Plant::State xdot = Plant::State::Constant(9.0);
  unset.derivative(0.0, Plant::State::Zero(), Vec3::Ones(), xdot);
  EXPECT_EQ(xdot, Plant::State::Zero());
  expect_refusals<P>(adcs::flexible_params_seed002(), [](const P& p) { return Plant(p).status(); },
                     {{"J NaN", [](P& p) { p.J(0, 0) = kNaN; }},
                      {"J not symmetric", [](P& p) { p.J(0, 1) = 10.0; }},
                      {"J not SPD", [](P& p) { p.J(1, 1) = -410.6; }},
                      {"F_s unset", [](P& p) { p.F_s[1].setConstant(adcs::kUnset); }},
                      {"M_eff not SPD", [](P& p) { p.F_s[0] *= 20.0; }},
                      {"Omega 0", [](P& p) { p.Omega[0](2) = 0.0; }},
                      {"Omega inf", [](P& p) { p.Omega[1](0) = kInf; }},
                      {"xi < 0", [](P& p) { p.xi[1](3) = -0.005; }},
                      {"xi NaN", [](P& p) { p.xi[0](0) = kNaN; }}});
}

// ============================================================================ reference/
TEST(ParameterValidationReference, SinusoidalEulerDefaultIsSeed002AndRefusals) {
  using P = adcs::SinusoidalEulerParams;
  expect_refusals<P>(P{}, [](const P& p) { return adcs::SinusoidalEulerReference(p).status(); },
                     {{"amplitude NaN", [](P& p) { p.amplitude_rad(1) = kNaN; }},
                      {"amplitude inf", [](P& p) { p.amplitude_rad(2) = -kInf; }},
                      {"frequency < 0", [](P& p) { p.frequency_rad_s = -0.1; }},
                      {"frequency inf", [](P& p) { p.frequency_rad_s = kInf; }}});
  P bad;
  bad.frequency_rad_s = kNaN;
  const adcs::EulerReferenceSample r = adcs::SinusoidalEulerReference(bad).sample(3.0);
  EXPECT_EQ(r.angles, Vec3::Zero());
  EXPECT_EQ(r.angles_dot, Vec3::Zero());
  EXPECT_EQ(r.angles_ddot, Vec3::Zero());
}

TEST(ParameterValidationReference, SinusoidalRateDefaultIsSeed001AndRefusals) {
  using P = adcs::SinusoidalRateParams;
  expect_refusals<P>(P{}, [](const P& p) { return adcs::SinusoidalRateReference(p).status(); },
                     {{"amplitude inf", [](P& p) { p.amplitude_rad_s(0) = kInf; }},
                      {"amplitude NaN", [](P& p) { p.amplitude_rad_s(2) = kNaN; }},
                      {"period 0", [](P& p) { p.period_s(1) = 0.0; }},
                      {"period < 0", [](P& p) { p.period_s(2) = -400.0; }},
                      {"period NaN", [](P& p) { p.period_s(0) = kNaN; }}});
  P bad;
  bad.period_s(0) = 0.0;
  const adcs::SinusoidalRateReference ref(bad);
  const Vec3 sigma_d(0.1, -0.2, 0.05);
  const adcs::MrpReferenceSample r = ref.sample(12.0, sigma_d);
  EXPECT_EQ(r.sigma, sigma_d);
  EXPECT_EQ(r.omega, Vec3::Zero());
  EXPECT_EQ(r.sigma_dot, Vec3::Zero());
  EXPECT_EQ(r.sigma_ddot, Vec3::Zero());
  EXPECT_EQ(ref.sigma_dot(12.0, sigma_d), Vec3::Zero());
}

// Construction status from default parameters: those whose defaults are a usable configuration
// report ok, those that need the caller's geometry, model or gains (wheel axes, inertia, filter
// matrices, K_P, RBF layer, actuator limits, steering geometry, nominal model, ζ, sample period)
// refuse it instead of building a silently wrong object (docs/VALIDATION.md; the tests above
// have one test per refusal). Here rather than in test_instantiate_all.cpp (now the coverage
// build's explicit instantiation unit only): this file instantiates the same constructors.
TEST(InstantiateAll, DefaultParametersGiveTheDocumentedConstructionStatus) {
  EXPECT_EQ(adcs::RwTorqueAllocator<4>(adcs::RwAllocationParams<4>{}).status(), Status::invalid_parameter);
  EXPECT_EQ(adcs::Saturation<6>(adcs::SaturationParams<6>{}).status(), Status::invalid_parameter);  // limit
  EXPECT_EQ(adcs::CompositeQuantizer<6>(adcs::seed003_quantizer_params()).status(), Status::ok);
  EXPECT_EQ(adcs::CompositeQuantizer<6>(adcs::CompositeQuantizerParams<6>{}).status(), Status::ok);
  EXPECT_EQ(adcs::SaturatedQuantizer<6>(adcs::SaturatedQuantizerParams<6>{}).status(), Status::invalid_parameter);
  EXPECT_EQ((adcs::VscmgSteering<4, 0>(adcs::VscmgSteeringParams<4, 0>{}).status()), Status::invalid_parameter);
  EXPECT_EQ(adcs::MrpPd<4>(adcs::MrpPdParams<4>{}).status(), Status::invalid_parameter);
  EXPECT_EQ(adcs::PrescribedTimeSe3(adcs::PrescribedTimeSe3Params{}).status(), Status::invalid_parameter);  // ζ, J0
  EXPECT_EQ(adcs::FtsmcSe3(adcs::FtsmcSe3Params{}).status(), Status::invalid_parameter);  // nominal model
  EXPECT_EQ(adcs::Pid<1>(adcs::PidParams<1>{}).status(), Status::invalid_parameter);
  EXPECT_EQ((adcs::Eskf<27, 9, 9, 9>(adcs::EskfParams<27, 9, 9, 9>{}).status()), Status::invalid_parameter);
  EXPECT_EQ((adcs::RbfCompensator<6, 7, 3>(adcs::RbfCompensatorParams<6, 7, 3>{}).status()),
            Status::invalid_parameter);
  EXPECT_EQ(adcs::PrescribedPerformance<3>(adcs::PpcParams<3>{}).status(), Status::ok);
  adcs::HybridAdaptive<4, 3>::Params hp;
  hp.nominal = adcs::pyramid_4cmg_3rw_nominal();
  EXPECT_EQ((adcs::HybridAdaptive<4, 3>(hp).status()), Status::ok);
  EXPECT_EQ((adcs::FlexibleSpacecraft<2, 4>(adcs::flexible_params_seed002()).status()), Status::ok);
}

}  // namespace

using namespace ADCS_UNITY_ID;  // as an anonymous namespace would (CMakeLists.txt, adcs_unity)
