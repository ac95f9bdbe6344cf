// The failure policy (core/failure_policy.hpp, docs/FAILURE-POLICY.md): after a step that
// produced no command, every controller outputs its family's safe command by default (zero
// torque, zero gimbal rate and wheel acceleration, zero actuation), or its last good command
// when the user chose hold_last; the law's state is untouched either way.
#include <gtest/gtest.h>

#include <limits>

#include "adcs/control/adrc.hpp"
#include "adcs/control/hybrid_adaptive.hpp"
#include "adcs/control/mrp_pd.hpp"
#include "adcs/control/pid.hpp"
#include "adcs/control/ppc_neural.hpp"
#include "adcs/plant/flexible_configurations.hpp"
#include "adcs/plant/vscmg_configurations.hpp"
#include "adcs/reference/sinusoidal_rate.hpp"

namespace ADCS_UNITY_ID {

using adcs::FailurePolicy;
using adcs::Status;
using adcs::Vec3;
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr FailurePolicy kPolicies[] = {FailurePolicy::safe_command, FailurePolicy::hold_last};

TEST(FailurePolicy, HelperPicksTheSafeOrTheLastCommand) {
  const Vec3 last(1, 2, 3), safe = Vec3::Zero();
  EXPECT_EQ(adcs::failure_command(FailurePolicy::safe_command, last, safe), safe);
  EXPECT_EQ(adcs::failure_command(FailurePolicy::hold_last, last, safe), last);
  EXPECT_EQ(adcs::MrpPdParams<4>{}.on_failure, FailurePolicy::safe_command);  // the default
}

TEST(FailurePolicy, MrpPdZeroTorqueOrHold) {
  for (FailurePolicy policy : kPolicies) {
    adcs::MrpPdParams<4> p;
    p.K = 1.44;
    p.P = 30.0 * adcs::Mat3::Identity();
    p.J_rw_B = Vec3(0.2, 0.25, 0.15).asDiagonal();
    p.G_s_B = adcs::Mat<3, 4>::Zero();
    p.G_s_B.leftCols<3>().setIdentity();
    p.G_s_B.col(3) = Vec3::Ones().normalized();
    p.J_s.setConstant(1e-4);
    p.period_s = 0.1;
    p.on_failure = policy;
    adcs::MrpPd<4> ctrl(p);
    adcs::MrpPd<4>::Input in;
    in.state.sigma_BN = Vec3(0.1, -0.2, 0.3);
    adcs::BodyTorque good, out;
    ASSERT_EQ(ctrl.step(in, good), Status::ok);
    ASSERT_GT(good.torque_B_Nm.norm(), 0.0);
    in.state.omega_BN_B(1) = kNaN;
    EXPECT_EQ(ctrl.step(in, out), Status::non_finite_input);
    EXPECT_EQ(out.torque_B_Nm, policy == FailurePolicy::hold_last ? good.torque_B_Nm : Vec3::Zero());
  }
}

TEST(FailurePolicy, HybridAdaptiveZeroRatesOrHoldAndEstimatesUntouched) {
  for (FailurePolicy policy : kPolicies) {
    adcs::HybridAdaptive<4, 3>::Params p;
    p.nominal = adcs::pyramid_4cmg_3rw_nominal();
    p.on_failure = policy;
    adcs::HybridAdaptive<4, 3> ctrl(p);
    adcs::HybridAdaptive<4, 3>::Input in;
    in.state.sigma_BN << 0.3, -0.2, 0.1;
    in.state.omega_BN_B << 0.01, -0.02, 0.015;
    in.actuators.gamma_rad << 0.1, -0.2, 0.15, 0.05;
    in.reference = adcs::SinusoidalRateReference{}.sample(12.0, Vec3(0.29, -0.21, 0.1));
    adcs::VscmgRates<4, 3> good, out;
    ASSERT_TRUE(adcs::usable(ctrl.step(in, good)));
    ASSERT_GT(good.stacked().norm(), 0.0);
    const auto theta_F = ctrl.theta_F();
    in.actuators.gamma_rad(2) = kNaN;
    EXPECT_EQ(ctrl.step(in, out), Status::non_finite_input);
    EXPECT_EQ(out.stacked(), policy == FailurePolicy::hold_last ? good.stacked() : adcs::Vec<7>::Zero());
    EXPECT_EQ(ctrl.theta_F(), theta_F);
  }
}

TEST(FailurePolicy, PpcNeuralZeroTorqueOrHold) {
  for (FailurePolicy policy : kPolicies) {
    adcs::PpcNeuralParams p;
    p.gains = adcs::seed002_tracking_gains();
    p.gains.on_failure = policy;
    adcs::PpcNeural law(p);
    ASSERT_EQ(law.status(), Status::ok);
    adcs::EulerTrackingInput in;
    in.state.theta_BN_rad = Vec3(0.002, -0.002, 0.001);  // inside the funnel: rho0 = 0.3 deg
    adcs::BodyTorque good, out;
    ASSERT_TRUE(adcs::usable(law.step(in, good)));
    ASSERT_GT(good.torque_B_Nm.norm(), 0.0);
    in.t_s = 1e-4;
    in.state.omega_BN_B(0) = kNaN;
    EXPECT_EQ(law.step(in, out), Status::non_finite_input);
    EXPECT_EQ(out.torque_B_Nm, policy == FailurePolicy::hold_last ? good.torque_B_Nm : Vec3::Zero());
  }
}

TEST(FailurePolicy, PidAndAdrcZeroOrHold) {
  for (FailurePolicy policy : kPolicies) {
    adcs::PidParams<3> pp;
    pp.kp = Vec3(1, 2, 3);
    pp.on_failure = policy;
    adcs::Pid<3> pid(pp);
    adcs::PidOutput<3> good, out;
    out.u = Vec3::Constant(-9.0);
    ASSERT_EQ(pid.step(adcs::PidInput<3>{Vec3(1, 1, 1), Vec3::Zero()}, good), Status::ok);
    EXPECT_EQ(pid.step(adcs::PidInput<3>{Vec3(kNaN, 0, 0), Vec3::Zero()}, out), Status::non_finite_input);
    EXPECT_EQ(out.u, policy == FailurePolicy::hold_last ? good.u : Vec3::Zero());

    adcs::DragFreeAdrcParams ap;
    ap.on_failure = policy;
    adcs::DragFreeAdrc adrc(ap);
    adcs::DragFreeAdrcInput in;  // F_D_hat_N and phi_sc_cmd_rad zero
    in.x_hat(adcs::DragFreeIndex::r) = 1e-7;
    in.x_hat(adcs::DragFreeIndex::phi_sc) = 1e-6;
    adcs::DragFreeActuation u_good, u = adcs::DragFreeActuation::from_stacked(adcs::Vec<9>::Constant(-9.0));
    ASSERT_TRUE(adcs::usable(adrc.step(in, u_good)));
    ASSERT_GT(u_good.stacked().norm(), 0.0);
    in.x_hat(0) = kNaN;
    EXPECT_EQ(adrc.step(in, u), Status::non_finite_input);
    EXPECT_EQ(u.stacked(), policy == FailurePolicy::hold_last ? u_good.stacked() : adcs::Vec<9>::Zero());
  }
}

}  // namespace

using namespace ADCS_UNITY_ID;  // as an anonymous namespace would (CMakeLists.txt, adcs_unity)
