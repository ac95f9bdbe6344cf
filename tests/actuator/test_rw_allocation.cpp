#include <gtest/gtest.h>

#include <limits>

#include "adcs/actuator/rw_allocation.hpp"

namespace ADCS_UNITY_ID {
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
  adcs::WheelTorques<4> out;
  Alloc::Diagnostics diag;
  diag.scale = 7.0;
  ASSERT_EQ(a.step(adcs::BodyTorque{L}, out, &diag), adcs::Status::ok);
  EXPECT_EQ(diag.scale, 1.0);  // within the limit: not scaled
  const adcs::Vec<4>& us = out.u_s_Nm;
  EXPECT_LT((-params().G_s_B * us - L).norm(), 1e-15);
  // Minimum norm: us is in the row space of G_s (orthogonal to its null space).
  const adcs::Vec<4> null_dir = adcs::Vec<4>(1, 1, 1, -std::sqrt(3.0)).normalized();
  EXPECT_NEAR(us.dot(null_dir), 0.0, 1e-15);
}

TEST(RwAllocation, SaturationScalesAndKeepsDirection) {
  const Alloc a(params(0.2));
  const adcs::Vec3 L(3.0, -1.0, 0.5);
  adcs::WheelTorques<4> out;
  Alloc::Diagnostics diag;
  ASSERT_EQ(a.step(adcs::BodyTorque{L}, out, &diag), adcs::Status::saturated);
  const adcs::Vec<4>& us = out.u_s_Nm;
  EXPECT_NEAR(us.cwiseAbs().maxCoeff(), 0.2, 1e-15);
  EXPECT_LE(us.cwiseAbs().maxCoeff(), 0.2);  // never above the limit, not even by a rounding
  const adcs::Vec3 delivered = -params().G_s_B * us;
  EXPECT_NEAR(delivered.normalized().dot(L.normalized()), 1.0, 1e-14);
  // The common factor applied: the delivered torque is that fraction of the request.
  EXPECT_GT(diag.scale, 0.0);
  EXPECT_LT(diag.scale, 1.0);
  EXPECT_NEAR(delivered.norm(), diag.scale * L.norm(), 1e-14);
}

// On failure the allocator outputs zero wheel torques (the wheels coast), never a stale or
// made-up command (core/component.hpp: an actuation stage's failure output is zero).
TEST(RwAllocation, RejectsNonFiniteAndBadGeometry) {
  const Alloc a(params());
  adcs::WheelTorques<4> out;
  out.u_s_Nm.setConstant(7.0);
  const adcs::Vec3 L(std::numeric_limits<double>::quiet_NaN(), 0, 0);
  EXPECT_EQ(a.step(adcs::BodyTorque{L}, out), adcs::Status::non_finite_input);
  EXPECT_EQ(out.u_s_Nm, adcs::Vec<4>::Zero());
  Alloc::Params coplanar = params();
  coplanar.G_s_B.row(2).setZero();  // every wheel in the x-y plane
  const Alloc b(coplanar);
  EXPECT_EQ(b.status(), adcs::Status::invalid_parameter);
  out.u_s_Nm.setConstant(7.0);
  EXPECT_EQ(b.step(adcs::BodyTorque{adcs::Vec3(0.1, 0, 0)}, out), adcs::Status::invalid_parameter);
  EXPECT_EQ(out.u_s_Nm, adcs::Vec<4>::Zero());
}
// Found by tests/fuzz (fuzz_seed001): a finite but absurd request overflowed G_s⁺ L to Inf and
// the scaling into the limit turned it into NaN with status saturated.
TEST(RwAllocation, OverflowingRequestIsRefusedNotTurnedIntoNaN) {
  const Alloc a(params());
  adcs::WheelTorques<4> out;
  out.u_s_Nm.setConstant(7.0);
  const double big = std::numeric_limits<double>::max();
  EXPECT_EQ(a.step(adcs::BodyTorque{adcs::Vec3(big, -big, big)}, out), adcs::Status::out_of_range);
  EXPECT_EQ(out.u_s_Nm, adcs::Vec<4>::Zero());
  // Large but representable requests are still scaled into the limit.
  EXPECT_EQ(a.step(adcs::BodyTorque{adcs::Vec3(1e300, 0.0, 0.0)}, out), adcs::Status::saturated);
  EXPECT_TRUE(adcs::all_finite(out.u_s_Nm));
  EXPECT_LE(out.u_s_Nm.cwiseAbs().maxCoeff(), 0.2);
}
}  // namespace

using namespace ADCS_UNITY_ID;  // as an anonymous namespace would (CMakeLists.txt, adcs_unity)
