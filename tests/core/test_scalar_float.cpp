// Issue 19, first part: the attitude chain in single precision. MrpPd<4, float> and
// RwTorqueAllocator<4, float> against their double instances on the same inputs, the attitude
// math they use, the parameter casts, and the failure paths in float.
//
// Tolerances: every float result is compared with the double result rounded to float, relative to
// the size of the quantities that enter it. One float operation has a relative error of at most
// 2^-24 ≈ 6e-8; the MrpPd step is ~150 operations deep with condition ~1 (a sum of PD, feed-forward
// and gyroscopic terms of similar size), so 1e-5 of the largest term is a bound with margin ~50
// over what the chain can accumulate, and tight enough to catch a constant rounded through the
// wrong type (a float π, a truncated gain: errors of 1e-4 and more).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <random>

#include "adcs/actuator/rw_allocation.hpp"
#include "adcs/control/mrp_pd.hpp"
#include "adcs/core/signals.hpp"
#include "adcs/math/euler.hpp"
#include "adcs/math/mrp.hpp"

namespace ADCS_UNITY_ID {

constexpr double kFloatRel = 1e-5;

adcs::MrpPdParams<4> pd_params() {
  adcs::MrpPdParams<4> p;
  p.K = 3.0;
  p.P = adcs::Vec3(40, 35, 30).asDiagonal();
  p.J_rw_B = adcs::Vec3(900, 800, 600).asDiagonal();
  const double s = 1.0 / std::sqrt(3.0);
  p.G_s_B << 1, 0, 0, s, 0, 1, 0, s, 0, 0, 1, s;
  p.J_s.setConstant(0.1);
  p.period_s = 0.1;
  return p;
}

adcs::MrpPdInput<4> random_input(std::mt19937& rng) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  adcs::MrpPdInput<4> in;
  for (int i = 0; i < 3; ++i) {
    in.state.sigma_BN(i) = 0.5 * u(rng);
    in.state.omega_BN_B(i) = 0.05 * u(rng);
    in.reference.sigma_RN(i) = 0.5 * u(rng);
    in.reference.omega_RN_N(i) = 0.01 * u(rng);
    in.reference.domega_RN_N(i) = 1e-4 * u(rng);
  }
  for (int i = 0; i < 4; ++i) in.Omega_rad_s(i) = 200.0 * u(rng);
  return in;
}

TEST(ScalarFloat, MrpPdFloatMatchesDoubleOnRandomInputs) {
  adcs::MrpPd<4> pd_d(pd_params());
  adcs::MrpPd<4, float> pd_f(pd_params().cast<float>());
  ASSERT_EQ(pd_d.status(), adcs::Status::ok);
  ASSERT_EQ(pd_f.status(), adcs::Status::ok);
  static_assert(std::is_same_v<decltype(pd_f.period_s()), float>);
  std::mt19937 rng(19);
  double worst = 0.0;
  for (int k = 0; k < 2000; ++k) {
    const adcs::MrpPdInput<4> in = random_input(rng);
    adcs::BodyTorque out_d;
    adcs::BodyTorqueT<float> out_f;
    ASSERT_EQ(pd_d.step(in, out_d), adcs::Status::ok);
    ASSERT_EQ(pd_f.step(in.cast<float>(), out_f), adcs::Status::ok);
    // Scale: the largest term of the law (K σ, P ω, and the gyroscopic ω × H with H ~ J_s Ω).
    const double scale = std::max({3.0, 40.0 * 0.05, out_d.torque_B_Nm.cwiseAbs().maxCoeff(), 0.05 * 0.1 * 200.0});
    const double err = (out_f.torque_B_Nm.cast<double>() - out_d.torque_B_Nm).cwiseAbs().maxCoeff() / scale;
    worst = std::max(worst, err);
  }
  std::printf("[ measured ] MrpPd<4, float> vs double: worst error %.2e of the largest term, 2000 inputs\n", worst);
  EXPECT_LT(worst, kFloatRel);
  EXPECT_GT(worst, 0.0);  // really computed in float (a double path would agree exactly)
}

TEST(ScalarFloat, MrpPdFloatRefusesUnsetParametersAndNonFiniteInput) {
  adcs::MrpPd<4, float> unset{adcs::MrpPdParams<4, float>{}};
  EXPECT_EQ(unset.status(), adcs::Status::invalid_parameter);
  adcs::MrpPd<4, float> pd(pd_params().cast<float>());
  std::mt19937 rng(3);
  const adcs::MrpPdInput<4, float> in = random_input(rng).cast<float>();
  adcs::BodyTorqueT<float> out;
  ASSERT_EQ(pd.step(in, out), adcs::Status::ok);
  ASSERT_GT(out.torque_B_Nm.norm(), 0.0f);
  for (float bad : {std::numeric_limits<float>::quiet_NaN(), std::numeric_limits<float>::infinity()}) {
    adcs::MrpPdInput<4, float> ib = in;
    ib.state.omega_BN_B(1) = bad;
    out.torque_B_Nm.setConstant(7.0f);
    EXPECT_EQ(pd.step(ib, out), adcs::Status::non_finite_input);
    EXPECT_TRUE(out.torque_B_Nm.isZero(0.0f));  // the safe command: zero torque
  }
  // A finite input whose torque overflows float (but not double): refused, zero torque.
  adcs::MrpPdInput<4, float> huge = in;
  huge.state.omega_BN_B.setConstant(1e30f);
  out.torque_B_Nm.setConstant(7.0f);
  EXPECT_EQ(pd.step(huge, out), adcs::Status::out_of_range);
  EXPECT_TRUE(out.torque_B_Nm.isZero(0.0f));
}

TEST(ScalarFloat, RwAllocationFloatMatchesDoubleAndSaturatesTheSameWay) {
  adcs::RwAllocationParams<4> p;
  p.G_s_B = pd_params().G_s_B;
  p.torque_limit = 0.2;
  adcs::RwTorqueAllocator<4> a_d(p);
  adcs::RwTorqueAllocator<4, float> a_f(p.cast<float>());
  ASSERT_EQ(a_f.status(), adcs::Status::ok);
  EXPECT_NEAR(a_f.geometry().condition, a_d.geometry().condition, 1e-5 * a_d.geometry().condition);
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-0.5, 0.5);
  for (int k = 0; k < 500; ++k) {
    adcs::BodyTorque L{adcs::Vec3(u(rng), u(rng), u(rng))};
    adcs::WheelTorques<4> w_d;
    adcs::WheelTorques<4, float> w_f;
    adcs::RwAllocationDiagnostics diag_d;
    adcs::RwAllocationDiagnosticsT<float> diag_f;
    const adcs::Status s_d = a_d.step(L, w_d, &diag_d);
    const adcs::Status s_f = a_f.step(L.cast<float>(), w_f, &diag_f);
    // Same decision, except within float rounding of the limit itself.
    if (std::abs(diag_d.scale - 1.0) > 1e-5) EXPECT_EQ(s_f, s_d);
    EXPECT_LE(w_f.u_s_Nm.cwiseAbs().maxCoeff(), 0.2f);  // the limit holds exactly in float too
    EXPECT_LT((w_f.u_s_Nm.cast<double>() - w_d.u_s_Nm).cwiseAbs().maxCoeff(), kFloatRel * 0.2);
  }
  adcs::WheelTorques<4, float> w;
  w.u_s_Nm.setConstant(1.0f);
  EXPECT_EQ(a_f.step(adcs::BodyTorqueT<float>{adcs::Vec<3, float>(std::numeric_limits<float>::quiet_NaN(), 0, 0)}, w),
            adcs::Status::non_finite_input);
  EXPECT_TRUE(w.u_s_Nm.isZero(0.0f));  // the wheels coast
}

TEST(ScalarFloat, AttitudeMathAgreesWithDouble) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int k = 0; k < 500; ++k) {
    const adcs::Vec3 sigma = 0.9 * adcs::Vec3(u(rng), u(rng), u(rng)).normalized() * std::abs(u(rng));
    const adcs::Vec3 sigma2 = 0.9 * adcs::Vec3(u(rng), u(rng), u(rng)).normalized() * std::abs(u(rng));
    const adcs::Vec<3, float> sf = sigma.cast<float>(), sf2 = sigma2.cast<float>();
    EXPECT_LT((adcs::mrp_to_dcm(sf).cast<double>() - adcs::mrp_to_dcm(sigma)).cwiseAbs().maxCoeff(), 1e-6);
    EXPECT_LT((adcs::mrp_subtract(sf, sf2).cast<double>() - adcs::mrp_subtract(sigma, sigma2)).norm(), 1e-6);
    EXPECT_LT((adcs::mrp_G(sf).cast<double>() - adcs::mrp_G(sigma)).cwiseAbs().maxCoeff(), 1e-6);
    EXPECT_LT((adcs::dcm_to_mrp(adcs::mrp_to_dcm(sf)).cast<double>() - sigma).norm(), 1e-6);
    const adcs::Vec3 ang = adcs::dcm_to_euler123(adcs::mrp_to_dcm(sigma));
    EXPECT_LT((adcs::dcm_to_euler123(adcs::mrp_to_dcm(sf)).cast<double>() - ang).norm(), 1e-5);
    // Quaternion round trip in float keeps unit norm to float precision.
    EXPECT_NEAR(adcs::mrp_to_quat(sf).norm(), 1.0f, 4.0f * std::numeric_limits<float>::epsilon());
  }
  static_assert(adcs::pi_v<float> == 3.14159265f);
}

TEST(ScalarFloat, SignalCastsRoundEachValueOnce) {
  adcs::AttitudeReference r;
  r.sigma_RN << 0.1, 1.0 / 3.0, -0.2;
  const adcs::AttitudeReferenceT<float> rf = r.cast<float>();
  EXPECT_EQ(rf.sigma_RN(1), static_cast<float>(1.0 / 3.0));
  EXPECT_EQ(rf.cast<double>().sigma_RN(1), static_cast<double>(static_cast<float>(1.0 / 3.0)));
  const adcs::MrpPdParams<4, float> pf = pd_params().cast<float>();
  EXPECT_EQ(pf.period_s, 0.1f);
  EXPECT_EQ(pf.on_failure, adcs::FailurePolicy::safe_command);
}

}  // namespace ADCS_UNITY_ID
