#include <gtest/gtest.h>

#include <limits>

#include "adcs/actuator/rw_allocation.hpp"

namespace {
using Alloc = adcs::RwTorqueAllocator<4>;

Alloc::Params params(double limit = 0.2) {
  Alloc::Params p;
  const double s = 1.0 / std::sqrt(3.0);
  p.G_s_B << 1, 0, 0, s, 0, 1, 0, s, 0, 0, 1, s;
  p.torque_limit = limit;
  return p;
}

TEST(RwAllocation, MinimumNormDeliversRequestedTorque) {
  const Alloc a(params(10.0));
  ASSERT_EQ(a.status(), adcs::Status::ok);
  const adcs::Vec3 L(0.05, -0.1, 0.02);
  adcs::Vec<4> us;
  ASSERT_EQ(a.allocate(L, us), adcs::Status::ok);
  EXPECT_LT((-params().G_s_B * us - L).norm(), 1e-15);
  // Minimum norm: us is in the row space of G_s (orthogonal to its null space).
  const adcs::Vec<4> null_dir = adcs::Vec<4>(1, 1, 1, -std::sqrt(3.0)).normalized();
  EXPECT_NEAR(us.dot(null_dir), 0.0, 1e-15);
}

TEST(RwAllocation, SaturationScalesAndKeepsDirection) {
  const Alloc a(params(0.2));
  const adcs::Vec3 L(3.0, -1.0, 0.5);
  adcs::Vec<4> us;
  ASSERT_EQ(a.allocate(L, us), adcs::Status::saturated);
  EXPECT_NEAR(us.cwiseAbs().maxCoeff(), 0.2, 1e-15);
  EXPECT_LE(us.cwiseAbs().maxCoeff(), 0.2);  // never above the limit, not even by a rounding
  const adcs::Vec3 delivered = -params().G_s_B * us;
  EXPECT_NEAR(delivered.normalized().dot(L.normalized()), 1.0, 1e-14);
}

TEST(RwAllocation, RejectsNonFiniteAndBadGeometry) {
  const Alloc a(params());
  adcs::Vec<4> us = adcs::Vec<4>::Constant(7.0);
  const adcs::Vec3 L(std::numeric_limits<double>::quiet_NaN(), 0, 0);
  EXPECT_EQ(a.allocate(L, us), adcs::Status::non_finite_input);
  EXPECT_EQ(us, adcs::Vec<4>::Constant(7.0));
  Alloc::Params coplanar = params();
  coplanar.G_s_B.row(2).setZero();  // every wheel in the x-y plane
  const Alloc b(coplanar);
  EXPECT_EQ(b.status(), adcs::Status::invalid_parameter);
  EXPECT_EQ(b.allocate(adcs::Vec3(0.1, 0, 0), us), adcs::Status::invalid_parameter);
  EXPECT_EQ(us, adcs::Vec<4>::Constant(7.0));
}
// Found by tests/fuzz (fuzz_seed001): a finite but absurd request overflowed G_s⁺ L to Inf and
// the scaling into the limit turned it into NaN with status saturated.
TEST(RwAllocation, OverflowingRequestIsRefusedNotTurnedIntoNaN) {
  const Alloc a(params());
  adcs::Vec<4> us = adcs::Vec<4>::Constant(7.0);
  const double big = std::numeric_limits<double>::max();
  EXPECT_EQ(a.allocate(adcs::Vec3(big, -big, big), us), adcs::Status::out_of_range);
  EXPECT_EQ(us, adcs::Vec<4>::Constant(7.0));
  // Large but representable requests are still scaled into the limit.
  EXPECT_EQ(a.allocate(adcs::Vec3(1e300, 0.0, 0.0), us), adcs::Status::saturated);
  EXPECT_TRUE(adcs::all_finite(us));
  EXPECT_LE(us.cwiseAbs().maxCoeff(), 0.2);
}
}  // namespace
