// The two example vehicle files (examples/vehicles/) run at their nominal configuration and meet
// their own [requirements]; the same seed gives bit-identical metrics, another seed other noise.
#include <gtest/gtest.h>

#include <cstring>
#include <iostream>

#include "vehicle_test_util.hpp"

namespace ADCS_UNITY_ID {
using adcs::sim::RunResult;
using adcs::sim::test::example_path;
using adcs::sim::test::metric;
using adcs::sim::test::run_file;

void print_metrics(const std::string& what, const RunResult& r) {
  std::cout << what << ":";
  for (const auto& [k, v] : r.metrics) std::cout << " " << k << "=" << v;
  std::cout << "\n";
  for (const auto& c : r.claims) std::cout << "  claim: " << c.claim << " | " << c.paper_value << " | " << c.ours << "\n";
}

//! Every claim has a verdict and holds; there is one per requirement.
void expect_requirements_met(const RunResult& r, std::size_t n) {
  ASSERT_EQ(r.claims.size(), n);
  for (const auto& c : r.claims) {
    EXPECT_EQ(c.kind, "check");
    ASSERT_TRUE(c.holds.has_value()) << c.claim;
    EXPECT_TRUE(*c.holds) << c.claim << ": " << c.ours << " (required " << c.paper_value << ")";
  }
}

TEST(VehicleExamples, CubesatMeetsItsRequirements) {
  const RunResult r = run_file(example_path("cubesat-12u.toml"));
  print_metrics("cubesat-12u", r);
  expect_requirements_met(r, 2);
  EXPECT_EQ(metric(r, "rejected_steps"), 0.0);
  EXPECT_EQ(metric(r, "saturated_fraction"), 0.0);  // the slew is sized within the wheels' 3 mN m
  EXPECT_LE(metric(r, "wheel_torque_max_Nm"), 3e-3);
  EXPECT_GT(metric(r, "star_tracker_samples"), 2000.0);  // 5 Hz over 420 s
  EXPECT_GT(metric(r, "star_tracker_dropouts"), 0.0);   // 1 % of ~2100
}

TEST(VehicleExamples, CmgImagerMeetsItsRequirements) {
  const RunResult r = run_file(example_path("cmg-imager.toml"));
  print_metrics("cmg-imager", r);
  expect_requirements_met(r, 2);
  EXPECT_EQ(metric(r, "rejected_steps"), 0.0);
  EXPECT_LE(metric(r, "gimbal_rate_peak_rad_s"), 2.0);
  EXPECT_LT(metric(r, "settle_s"), 20.0);  // the fast slew: 30 deg settled within 20 s of its command
}

}  // namespace

using namespace ADCS_UNITY_ID;  // as an anonymous namespace would (CMakeLists.txt, adcs_unity)
