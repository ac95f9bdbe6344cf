// seed 001 eq. (27) reference, spec §A.7 S3.
#include <gtest/gtest.h>

#include "adcs/reference/sinusoidal_rate.hpp"

namespace ADCS_UNITY_ID {
using adcs::Vec3;
using adcs::Vec4;

const adcs::SinusoidalRateReference kRef;

// RK4 on σ̇_d = G(σ_d) ω_f(t).
Vec3 rk4_sigma(double t, const Vec3& s, double h) {
  const Vec3 k1 = kRef.sigma_dot(t, s);
  const Vec3 k2 = kRef.sigma_dot(t + 0.5 * h, Vec3(s + 0.5 * h * k1));
  const Vec3 k3 = kRef.sigma_dot(t + 0.5 * h, Vec3(s + 0.5 * h * k2));
  const Vec3 k4 = kRef.sigma_dot(t + h, Vec3(s + h * k3));
  return s + h / 6.0 * (k1 + 2 * k2 + 2 * k3 + k4);
}

// Independent reference: the quaternion kinematics q̇ = ½ q ⊗ [0; ω] (Schaub's B matrix form).
Vec4 qdot(double t, const Vec4& q) {
  const Vec3 w = kRef.omega(t);
  Eigen::Matrix<double, 4, 3> B;
  B << -q(1), -q(2), -q(3),  //
      q(0), -q(3), q(2),     //
      q(3), q(0), -q(1),     //
      -q(2), q(1), q(0);
  return 0.5 * B * w;
}
Vec4 rk4_quat(double t, const Vec4& q, double h) {
  const Vec4 k1 = qdot(t, q);
  const Vec4 k2 = qdot(t + 0.5 * h, Vec4(q + 0.5 * h * k1));
  const Vec4 k3 = qdot(t + 0.5 * h, Vec4(q + 0.5 * h * k2));
  const Vec4 k4 = qdot(t + h, Vec4(q + h * k3));
  return q + h / 6.0 * (k1 + 2 * k2 + 2 * k3 + k4);
}

TEST(SinusoidalRateReference, RateAndDerivativeMatchEq27) {
  EXPECT_LT(kRef.omega(0.0).norm(), 1e-18);
  EXPECT_NEAR(kRef.omega(200.0)(0), 0.02, 1e-15);  // sin(π/2) on the 800 s axis
  for (double t : {0.0, 37.5, 123.0, 611.0}) {
    const double h = 1e-3;
    const Vec3 fd = (kRef.omega(t + h) - kRef.omega(t - h)) / (2 * h);
    EXPECT_LT((fd - kRef.omega_dot(t)).norm(), 1e-10);
  }
}

TEST(SinusoidalRateReference, SigmaDdotMatchesFiniteDifferenceAlongTheTrajectory) {
  Vec3 s = Vec3::Zero();
  const double h = 1e-3;
  double t = 0.0;
  for (int k = 0; k < 150000; ++k, t += h) s = rk4_sigma(t, s, h);  // to t = 150 s
  const Vec3 s_plus = rk4_sigma(t, s, h);
  const Vec3 s_minus = rk4_sigma(t, s, -h);
  const adcs::MrpReferenceSample r = kRef.sample(t, s);
  const Vec3 fd_dot = (s_plus - s_minus) / (2 * h);
  EXPECT_LT((fd_dot - r.sigma_dot).norm(), 1e-9);
  const Vec3 fd_ddot = (kRef.sigma_dot(t + h, s_plus) - kRef.sigma_dot(t - h, s_minus)) / (2 * h);
  EXPECT_LT((fd_ddot - r.sigma_ddot).norm(), 1e-9);
}

TEST(SinusoidalRateReference, MrpIntegrationAgreesWithQuaternionIntegration) {  // S3
  Vec3 s = Vec3::Zero();
  Vec4 q(1, 0, 0, 0);
  const double h = 1e-3;
  double t = 0.0, worst = 0.0;
  for (int k = 0; k < 200000; ++k, t += h) {  // 200 s at the spec's 1 ms step
    s = rk4_sigma(t, s, h);
    q = rk4_quat(t, q, h);
    if (k % 1000 == 999) {
      const Vec4 qn = q.normalized();
      Vec3 sq = qn.tail<3>() / (1.0 + qn(0));  // same branch while the rotation is < 180 deg
      worst = std::max(worst, (sq - s).norm());
    }
  }
  EXPECT_LT(worst, 1e-9);
}

TEST(SinusoidalRateReference, FullPeriodReachesThePrintedPeakAndReturns) {  // S3
  Vec3 s = Vec3::Zero();
  const double h = 1e-2;  // 10 ms: ample for 3 digits of the peak
  double t = 0.0, peak = 0.0;
  for (int k = 0; k < 240000; ++k, t += h) {
    s = rk4_sigma(t, s, h);
    peak = std::max(peak, s.norm());
  }
  EXPECT_NEAR(peak, 3.69, 0.01);                          // spec: max |σ_d| = 3.69 (299.4 deg)
  EXPECT_NEAR(4.0 * std::atan(peak) * 180.0 / M_PI, 299.4, 0.3);  // principal angle < 360 deg
  EXPECT_LT(s.norm(), 1e-6);                              // 2400 s-periodic: σ_d(2400) ≈ 0
}
}  // namespace

using namespace ADCS_UNITY_ID;  // as an anonymous namespace would (CMakeLists.txt, adcs_unity)
