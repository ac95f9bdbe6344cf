#include <gtest/gtest.h>

#include <cstring>
#include <limits>
#include <vector>

#include "adcs/control/mrp_pd.hpp"

namespace ADCS_UNITY_ID {
using Ctrl = adcs::MrpPd<4>;

Ctrl::Params params() {
  Ctrl::Params p;
  p.K = 3.0;
  p.P = adcs::Vec3(40, 35, 30).asDiagonal();
  p.J_rw_B = adcs::Vec3(900, 800, 600).asDiagonal();
  const double s = 1.0 / std::sqrt(3.0);
  p.G_s_B << 1, 0, 0, s, 0, 1, 0, s, 0, 0, 1, s;
  p.J_s.setConstant(0.1);
  p.period_s = 0.1;
  return p;
}

TEST(MrpPd, ProportionalAndDerivativeSigns) {
  Ctrl c(params());
  Ctrl::Input in;
  in.state.sigma_BN << 0.1, 0, 0;
  adcs::BodyTorque out;
  ASSERT_EQ(c.step(in, out), adcs::Status::ok);
  EXPECT_NEAR(out.torque_B_Nm(0), -0.3, 1e-15);
  EXPECT_NEAR(out.torque_B_Nm.tail<2>().norm(), 0.0, 1e-15);
  in.state.sigma_BN.setZero();
  in.state.omega_BN_B << 0, 0.01, 0;
  ASSERT_EQ(c.step(in, out), adcs::Status::ok);
  // -P omega plus the gyroscopic term omega x H (zero here: H parallel to omega? no wheels spin)
  EXPECT_NEAR(out.torque_B_Nm(1), -0.35, 1e-12);
}

TEST(MrpPd, GyroscopicCompensationCancelsWheelMomentumCoupling) {
  Ctrl c(params());
  Ctrl::Input in;
  in.state.sigma_BN.setZero();
  in.state.omega_BN_B << 0.0, 0.0, 0.0;
  in.Omega_rad_s << 100, 0, 0, 0;
  adcs::BodyTorque out;
  ASSERT_EQ(c.step(in, out), adcs::Status::ok);
  EXPECT_LT(out.torque_B_Nm.norm(), 1e-15);  // at rest, on target: nothing to do
  in.state.omega_BN_B << 0.0, 0.0, 0.001;
  ASSERT_EQ(c.step(in, out), adcs::Status::ok);
  const adcs::Vec3& w = in.state.omega_BN_B;
  const adcs::Vec3 H = params().J_rw_B * w +
                       params().G_s_B * (params().J_s.cwiseProduct(params().G_s_B.transpose() * w + in.Omega_rad_s));
  const adcs::Vec3 expected = -params().P * w + w.cross(H);
  EXPECT_LT((out.torque_B_Nm - expected).norm(), 1e-15);
}

TEST(MrpPd, TracksAroundTheReferenceNotTheOrigin) {
  Ctrl c(params());
  Ctrl::Input in;
  in.state.sigma_BN << 0.1, 0.2, -0.3;
  in.reference.sigma_RN = in.state.sigma_BN;
  adcs::BodyTorque out;
  Ctrl::Diagnostics diag;
  diag.sigma_BR.setConstant(7.0);  // so that the check below sees what step() wrote
  ASSERT_EQ(c.step(in, out, &diag), adcs::Status::ok);
  EXPECT_LT(diag.sigma_BR.norm(), 1e-15);
  EXPECT_LT(out.torque_B_Nm.norm(), 1e-14);
}

TEST(MrpPd, NonFiniteInputHoldsLastCommandUnderHoldLastAndResetClears) {
  Ctrl::Params hold = params();
  hold.on_failure = adcs::FailurePolicy::hold_last;  // default zero: test_failure_policy.cpp
  Ctrl c(hold);
  Ctrl::Input in;
  in.state.sigma_BN << 0.1, 0, 0;
  adcs::BodyTorque good, out;
  ASSERT_EQ(c.step(in, good), adcs::Status::ok);
  for (double bad : {std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity()}) {
    Ctrl::Input ib = in;
    ib.Omega_rad_s(2) = bad;
    EXPECT_EQ(c.step(ib, out), adcs::Status::non_finite_input);
    EXPECT_EQ(out.torque_B_Nm, good.torque_B_Nm);
    Ctrl::Input rb = in;
    rb.reference = adcs::AttitudeReference{};
    rb.reference.domega_RN_N(0) = bad;
    EXPECT_EQ(c.step(rb, out), adcs::Status::non_finite_input);
    EXPECT_TRUE(adcs::all_finite(out.torque_B_Nm));
  }
  // Finite but absurd input overflows: out_of_range, still finite output.
  Ctrl::Input huge = in;
  huge.state.omega_BN_B << 1e300, 1e300, -1e300;
  EXPECT_EQ(c.step(huge, out), adcs::Status::out_of_range);
  EXPECT_TRUE(adcs::all_finite(out.torque_B_Nm));
  c.reset();
  Ctrl::Input ib = in;
  ib.state.sigma_BN(0) = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(c.step(ib, out), adcs::Status::non_finite_input);
  EXPECT_EQ(out.torque_B_Nm, adcs::Vec3::Zero());
}

TEST(MrpPd, DeterministicBitForBit) {
  Ctrl a(params()), b(params());
  Ctrl::Input in;
  in.state.sigma_BN << 0.3, -0.1, 0.2;
  in.state.omega_BN_B << 0.01, 0.02, -0.03;
  in.Omega_rad_s << 1, 2, 3, 4;
  in.reference.sigma_RN << 0.1, 0.0, 0.05;
  in.reference.omega_RN_N << 0.001, 0.0, 0.0;
  adcs::BodyTorque oa, ob;
  ASSERT_EQ(a.step(in, oa), adcs::Status::ok);
  ASSERT_EQ(b.step(in, ob), adcs::Status::ok);
  EXPECT_EQ(std::memcmp(oa.torque_B_Nm.data(), ob.torque_B_Nm.data(), sizeof(double) * 3), 0);
}
// Issue 15: no made-up defaults. A forgotten field is NaN and refused; so is anything unphysical.
TEST(MrpPd, RefusesMissingOrUnphysicalParameters) {
  EXPECT_EQ(Ctrl(Ctrl::Params{}).status(), adcs::Status::invalid_parameter);  // nothing set
  EXPECT_EQ(Ctrl(params()).status(), adcs::Status::ok);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  std::vector<Ctrl::Params> bad(11, params());
  bad[0].K = 0.0;
  bad[1].K = nan;
  bad[2].P(0, 1) = 5.0;                 // not symmetric
  bad[3].P = -bad[3].P;                 // not positive definite
  bad[4].J_rw_B(2, 2) = 0.0;            // singular inertia
  bad[5].J_rw_B(1, 1) = std::numeric_limits<double>::infinity();
  bad[6].G_s_B.col(2) *= 2.0;           // not a unit axis
  bad[7].J_s(1) = -0.1;
  bad[8].G_s_B(0, 0) = nan;
  bad[9].period_s = nan;                // the period has no default either
  bad[10].period_s = 0.0;
  for (std::size_t i = 0; i < bad.size(); ++i) {
    Ctrl c(bad[i]);
    EXPECT_EQ(c.status(), adcs::Status::invalid_parameter) << i;
    adcs::BodyTorque out;
    out.torque_B_Nm.setConstant(7.0);
    EXPECT_EQ(c.step(Ctrl::Input{}, out), adcs::Status::invalid_parameter) << i;
    EXPECT_EQ(out.torque_B_Nm, adcs::Vec3::Zero()) << i;  // the safe command, never a made-up torque
  }
}

}  // namespace

using namespace ADCS_UNITY_ID;  // as an anonymous namespace would (CMakeLists.txt, adcs_unity)
