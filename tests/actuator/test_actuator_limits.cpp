// Per-actuator limits (actuator/limits.hpp, issue 15): gimbal rates, wheel torques and wheel
// speeds, each on its own; refusals leave the command untouched.
#include <gtest/gtest.h>

#include <limits>

#include "adcs/actuator/limits.hpp"

namespace ADCS_UNITY_ID {
using adcs::Status;
constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

TEST(ActuatorLimits, DefaultsAreNoLimitAndPassEverythingThrough) {
  const adcs::ActuatorLimits<4, 3> none;
  EXPECT_TRUE(adcs::valid(none));
  adcs::Vec<7> u;
  u << 1e3, -1e3, 5.0, 0.0, 1e6, -1e6, 2.0;
  const adcs::Vec<7> before = u;
  adcs::LimitReport r;
  EXPECT_EQ((adcs::limit_vscmg_command<4, 3>(none, adcs::Vec3::Constant(1e-3), adcs::Vec3(1e4, -1e4, 0.0), u, &r)),
            Status::ok);
  EXPECT_EQ(u, before);
  EXPECT_FALSE(r.any());
}

TEST(ActuatorLimits, WheelTorquesClipPerWheelAndStopAtTheSpeedLimit) {
  adcs::ActuatorLimits<0, 4> l;
  l.wheel_torque_max_Nm << 3e-3, 3e-3, 1e-3, 3e-3;
  l.wheel_speed_max_rad_s << 600.0, 600.0, 600.0, 600.0;
  adcs::Vec<4> u(5e-3, -5e-3, 2e-3, 1e-3);
  const adcs::Vec<4> Omega(0.0, 0.0, 0.0, 600.0);  // wheel 4 at its limit, spinning up
  adcs::LimitReport r;
  EXPECT_EQ(adcs::limit_wheel_torques<4>(l, Omega, u, &r), Status::saturated);
  EXPECT_EQ(u, adcs::Vec<4>(3e-3, -3e-3, 1e-3, 0.0));
  EXPECT_EQ(r.wheel_torque_clipped, 3);
  EXPECT_EQ(r.wheel_speed_held, 1);
  // Braking a wheel at its limit is allowed, and so is anything below it.
  adcs::Vec<4> brake(0.0, 0.0, 0.0, -2e-3);
  EXPECT_EQ(adcs::limit_wheel_torques<4>(l, Omega, brake, &r), Status::ok);
  EXPECT_EQ(brake(3), -2e-3);
  adcs::Vec<4> neg(0.0, 0.0, 0.0, -2e-3);
  EXPECT_EQ(adcs::limit_wheel_torques<4>(l, adcs::Vec<4>(0.0, 0.0, 0.0, -700.0), neg, &r), Status::saturated);
  EXPECT_EQ(neg(3), 0.0);  // negative speed beyond the limit: no more negative torque
}

TEST(ActuatorLimits, VscmgCommandLimitsGimbalRatesAndWheelAccelerations) {
  adcs::ActuatorLimits<4, 3> l;
  l.gimbal_rate_max_rad_s.setConstant(1.0);
  l.wheel_torque_max_Nm.setConstant(0.1);
  l.wheel_speed_max_rad_s.setConstant(kInf);
  const adcs::Vec3 I_ws = adcs::Vec3::Constant(0.01);  // -> |Omega_dot| <= 10 rad/s^2
  adcs::Vec<7> u;
  u << 2.0, -0.5, -3.0, 1.0, 20.0, -5.0, -10.0;
  adcs::LimitReport r;
  EXPECT_EQ((adcs::limit_vscmg_command<4, 3>(l, I_ws, adcs::Vec3::Zero(), u, &r)), Status::saturated);
  adcs::Vec<7> want;
  want << 1.0, -0.5, -1.0, 1.0, 10.0, -5.0, -10.0;
  EXPECT_EQ(u, want);
  EXPECT_EQ(r.gimbal_rate_clipped, 2);
  EXPECT_EQ(r.wheel_torque_clipped, 1);
  // A pure CMG cluster (no wheels).
  adcs::ActuatorLimits<4, 0> cmg;
  cmg.gimbal_rate_max_rad_s.setConstant(0.5);
  adcs::Vec<4> g(1.0, 0.2, -0.7, 0.0);
  EXPECT_EQ((adcs::limit_vscmg_command<4, 0>(cmg, adcs::Vec<0>(), adcs::Vec<0>(), g, &r)), Status::saturated);
  EXPECT_EQ(g, adcs::Vec<4>(0.5, 0.2, -0.5, 0.0));
}

TEST(ActuatorLimits, RefusalsLeaveTheCommandUntouched) {
  adcs::Vec<4> u(1.0, 2.0, 3.0, 4.0);
  const adcs::Vec<4> before = u;
  adcs::ActuatorLimits<0, 4> bad;
  for (double v : {0.0, -1.0, kNaN}) {
    bad = adcs::ActuatorLimits<0, 4>{};
    bad.wheel_torque_max_Nm(2) = v;
    EXPECT_FALSE(adcs::valid(bad)) << v;
    EXPECT_EQ(adcs::limit_wheel_torques<4>(bad, adcs::Vec<4>::Zero(), u), Status::invalid_parameter) << v;
    bad = adcs::ActuatorLimits<0, 4>{};
    bad.wheel_speed_max_rad_s(0) = v;
    EXPECT_EQ(adcs::limit_wheel_torques<4>(bad, adcs::Vec<4>::Zero(), u), Status::invalid_parameter) << v;
  }
  const adcs::ActuatorLimits<0, 4> ok;
  EXPECT_EQ(adcs::limit_wheel_torques<4>(ok, adcs::Vec<4>(0.0, kNaN, 0.0, 0.0), u), Status::non_finite_input);
  adcs::Vec<4> inf_u(kInf, 0.0, 0.0, 0.0);
  EXPECT_EQ(adcs::limit_wheel_torques<4>(ok, adcs::Vec<4>::Zero(), inf_u), Status::non_finite_input);
  EXPECT_EQ(u, before);
  adcs::Vec<7> w = adcs::Vec<7>::Ones();
  EXPECT_EQ((adcs::limit_vscmg_command<4, 3>(adcs::ActuatorLimits<4, 3>{}, adcs::Vec3(0.01, 0.0, 0.01),
                                             adcs::Vec3::Zero(), w)),
            Status::invalid_parameter);  // I_ws = 0
  EXPECT_EQ(w, adcs::Vec<7>::Ones());
}
}  // namespace

using namespace ADCS_UNITY_ID;  // as an anonymous namespace would (CMakeLists.txt, adcs_unity)
