#include <gtest/gtest.h>

#include <limits>

#include "adcs/actuator/steering.hpp"

namespace {
using adcs::Status;
using X7 = adcs::Mat<3, 7>;

X7 hybrid_like() {  // a well-conditioned 3x7 (CMG-like columns + weak wheel columns)
  X7 X;
  X << 0.5, -0.1, 0.2, 0.3, 0.01, 0, 0,  //
      0.1, 0.6, -0.3, 0.2, 0, 0.01, 0,   //
      -0.2, 0.1, 0.4, -0.5, 0, 0, 0.01;
  return X;
}

TEST(Steering, ExactMinimumNormWhenWellConditioned) {
  const X7 X = hybrid_like();
  const adcs::Vec3 v(1e-3, -2e-3, 5e-4);
  adcs::Vec<7> u;
  adcs::SteeringInfo info;
  ASSERT_EQ(adcs::steer<7>(X, v, adcs::SteeringParams{}, u, &info), Status::ok);
  EXPECT_EQ(info.mode, adcs::SteeringMode::pseudo_inverse);
  EXPECT_LT((X * u - v).norm(), 1e-15);
  // Minimum norm: u lies in the row space of X.
  const Eigen::Matrix<double, 7, 7> P_row =
      X.transpose() * (X * X.transpose()).inverse() * X;
  EXPECT_LT((P_row * u - u).norm(), 1e-15);
  EXPECT_GT(info.pinv.sigma_min, 0.0);
}

TEST(Steering, SingularGeometryFallsBackAndStaysBounded) {
  X7 X = hybrid_like();
  X.row(2) = 2.0 * X.row(0);  // rank 2: exactly singular
  const adcs::Vec3 v(1e-3, -2e-3, 5e-4);
  adcs::Vec<7> u;
  adcs::SteeringInfo info;
  const adcs::SteeringParams p{1e-3, 1e-2};
  ASSERT_EQ(adcs::steer<7>(X, v, p, u, &info), Status::ill_conditioned);
  EXPECT_EQ(info.mode, adcs::SteeringMode::singularity_robust);
  EXPECT_TRUE(adcs::all_finite(u));
  EXPECT_LE(u.norm(), v.norm() / (2.0 * p.lambda_max) + 1e-12);
  EXPECT_GT(info.pinv.damping, 0.0);
}

TEST(Steering, NoJumpAtTheSwitch) {
  // Scale one direction down through the threshold: u changes continuously.
  const adcs::Vec3 v(1e-3, -2e-3, 5e-4);
  const adcs::SteeringParams p{1e-3, 1e-2};
  adcs::Vec<7> prev = adcs::Vec<7>::Zero();
  bool first = true;
  for (double eps = 2e-3; eps > 5e-4; eps *= 0.999) {
    X7 X = hybrid_like();
    X.row(2) = X.row(0) + eps * adcs::Mat<1, 7>::Ones();
    adcs::Vec<7> u;
    ASSERT_TRUE(adcs::usable(adcs::steer<7>(X, v, p, u)));
    if (!first) {
      EXPECT_LT((u - prev).norm(), 0.05 * (1.0 + u.norm()));
    }
    prev = u;
    first = false;
  }
}

TEST(Steering, NonFiniteInputLeavesCommandUntouched) {
  X7 X = hybrid_like();
  adcs::Vec<7> u = adcs::Vec<7>::Constant(3.0);
  X(1, 4) = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(adcs::steer<7>(X, adcs::Vec3::Ones(), {}, u), Status::non_finite_input);
  EXPECT_EQ(u, adcs::Vec<7>::Constant(3.0));
  EXPECT_EQ(adcs::steer<7>(hybrid_like(), adcs::Vec3(0, std::numeric_limits<double>::infinity(), 0),
                           {}, u),
            Status::non_finite_input);
  EXPECT_EQ(u, adcs::Vec<7>::Constant(3.0));
}
// Failed actuators (FDIR mask): exactly zero command for them, the others solve X u = v alone,
// and the answer equals the pseudo-inverse of X without those columns.
TEST(Steering, UnavailableActuatorsGetExactlyZeroAndTheRestTakeOver) {
  const X7 X = hybrid_like();
  const adcs::Vec3 v(1e-3, -2e-3, 5e-4);
  const adcs::ActuatorMask mask = adcs::all_actuators<7>() & ~(1u << 1) & ~(1u << 5);  // gimbal 2, wheel 2
  adcs::Vec<7> u;
  adcs::SteeringInfo info;
  ASSERT_EQ(adcs::steer_available<7>(X, v, adcs::SteeringParams{}, mask, u, &info), Status::ok);
  EXPECT_EQ(u(1), 0.0);
  EXPECT_EQ(u(5), 0.0);
  EXPECT_LT((X * u - v).norm(), 1e-15);  // still exact on the remaining five
  Eigen::Matrix<double, 3, 5> Xr;
  Xr << X.col(0), X.col(2), X.col(3), X.col(4), X.col(6);
  const Eigen::Matrix<double, 5, 1> ur = Xr.transpose() * (Xr * Xr.transpose()).ldlt().solve(v);
  EXPECT_LT((adcs::Vec<5>(u(0), u(2), u(3), u(4), u(6)) - ur).norm(), 1e-12 * ur.norm());
  // All available: identical to steer().
  adcs::Vec<7> u_all, u_ref;
  ASSERT_EQ(adcs::steer_available<7>(X, v, {}, adcs::all_actuators<7>(), u_all), Status::ok);
  ASSERT_EQ(adcs::steer<7>(X, v, {}, u_ref), Status::ok);
  EXPECT_EQ(u_all, u_ref);
}

TEST(Steering, MaskThatCannotSpanThreeAxesIsBoundedAndFlagged) {
  const X7 X = hybrid_like();
  adcs::Vec<7> u = adcs::Vec<7>::Constant(7.0);
  adcs::SteeringInfo info;
  // Only wheel 1 (x axis) left: rank 1, the singularity-robust inverse answers.
  EXPECT_EQ(adcs::steer_available<7>(X, adcs::Vec3(1e-3, 1e-3, 1e-3), {}, 1u << 4, u, &info),
            Status::ill_conditioned);
  EXPECT_EQ(info.mode, adcs::SteeringMode::singularity_robust);
  for (int k = 0; k < 7; ++k) {
    if (k != 4) {
      EXPECT_EQ(u(k), 0.0) << k;
    }
  }
  EXPECT_TRUE(adcs::all_finite(u));
  // Nothing available: zero command, still bounded and flagged.
  EXPECT_EQ(adcs::steer_available<7>(X, adcs::Vec3(1e-3, 0, 0), {}, 0u, u), Status::ill_conditioned);
  EXPECT_EQ(u, adcs::Vec<7>::Zero());
  // A mask naming an 8th actuator is refused, u untouched.
  u.setConstant(3.0);
  EXPECT_EQ(adcs::steer_available<7>(X, adcs::Vec3::Ones(), {}, 1u << 7, u), Status::out_of_range);
  EXPECT_EQ(u, adcs::Vec<7>::Constant(3.0));
}

}  // namespace
