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
}  // namespace
