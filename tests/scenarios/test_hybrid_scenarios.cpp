// Seed 001 paper claims on A-REF (spec §A.6 test criteria), end to end through the scenario:
// TP-FULL truth plant, 1 ms sampled adaptive law, 800 s. R1/R2/R8 are recorded, not asserted.
#include <gtest/gtest.h>

#include <string>

#include "scenario_test_util.hpp"

namespace {
using adcs::sim::ParamSet;
using adcs::sim::RunResult;

using adcs::sim::test::metric;
using adcs::sim::test::run;

TEST(HybridAref, PaperClaimsR3toR7andR9) {
  const RunResult r = run("hybrid-adaptive");
  const double e_att = metric(r, "euler_err_ss_max_rad");
  EXPECT_LE(e_att, 3e-3);                     // R3: paper bound
  EXPECT_NEAR(e_att / 1.25e-4, 1.0, 0.3);     // R3: within ±30% of the spec's PROTO
  EXPECT_LE(metric(r, "rate_err_ss_max_rad_s"), 1e-4);        // R4
  EXPECT_GE(metric(r, "improvement_ratio_euler"), 5.0);       // R5 (paper says 100x; spec >= 5)
  EXPECT_GE(metric(r, "improvement_ratio_rate"), 4.0);        // R5 (paper says 10x; spec >= 4)
  EXPECT_LT(metric(r, "momentum_est_err_late_max_Nms"),       // R6 (soft)
            metric(r, "momentum_est_err_initial_Nms"));
  EXPECT_LE(metric(r, "proj_norm2_max"), 0.15 + 1e-9);        // R7 (hard)
  EXPECT_EQ(metric(r, "proj_safeguard_count"), 0.0);          // R7
  EXPECT_GT(metric(r, "pinv_sigma_min"), 0.0);                // R9
  EXPECT_NEAR(metric(r, "pinv_sigma_min"), 0.0170, 0.001);    // R9 PROTO
  EXPECT_LE(metric(r, "momentum_drift_rel"), 1e-10);          // S4 on TP-FULL, closed loop, 800 s
  EXPECT_EQ(metric(r, "nonok_steps"), 0.0);
  for (const auto& c : r.claims) {
    if (c.holds.has_value()) {
      EXPECT_TRUE(*c.holds) << c.claim << ": " << c.ours;
    }
  }
}

TEST(HybridAref, BaselineMatchesPrototype) {
  const RunResult r = run("hybrid-nonadaptive");
  // R1/R2 are informative in the spec; the PROTO values pin our implementation of A-REF.
  EXPECT_NEAR(metric(r, "euler_err_ss_max_rad") / 8.35e-4, 1.0, 0.1);
  EXPECT_NEAR(metric(r, "rate_err_ss_max_rad_s") / 3.95e-5, 1.0, 0.1);
  EXPECT_EQ(metric(r, "proj_norm2_max"), 0.0);  // α = 0: estimates stay at zero
}
}  // namespace

namespace {
// --seed N > 0 draws a Mode-A deviation set from our portable generator: same seed, same run
// bit for bit; another seed, another set.
TEST(HybridAref, SeedDrawsAReproducibleModeADeviationSet) {
  auto short_run = [](std::uint64_t seed) {
    return metric(run("hybrid-adaptive",
                      {{"duration_s", "30"}, {"window_s", "[10, 30]"}, {"baseline", "skip"}}, seed),
                  "euler_err_ss_max_rad");
  };
  const double a = short_run(7), b = short_run(7), c = short_run(8), d1 = short_run(0);
  EXPECT_EQ(a, b);
  EXPECT_NE(a, c);
  EXPECT_NE(a, d1);
}
}  // namespace

namespace {
// Spec §A.7 S11: with the true Θ and no adaptation, TP-FULL (J(γ) variation, gimbal momentum)
// still tracks to ~1.5e-7 rad over [100, 800] s: the truth-plant-only mismatch is negligible.
TEST(HybridAref, OracleOnTheFullPlantS11) {
  const RunResult r = run("hybrid-nonadaptive", {{"initial_estimates", "truth"}, {"window_s", "[100, 800]"}});
  EXPECT_NEAR(metric(r, "principal_err_ss_max_rad") / 1.5e-7, 1.0, 0.3);  // PROTO 1.5e-7
}
}  // namespace
