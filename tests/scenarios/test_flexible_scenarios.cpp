// Seed 002 paper claims (spec §B.6 test criteria) end to end through the scenarios: flexible
// truth plant with the disturbance, laws sampled at 1e-4 s, 100 s, U_rad. P1, P2, P3, P6 hard;
// P4, P7 as stated; P5, P8, P9 recorded and pinned to the spec's PROTO values. Each paper
// claim's two verdicts (issue 16) are asserted: the paper verdict against the paper's own words,
// and our criterion (holds), so a change in the physics shows up as a changed verdict.
#include <gtest/gtest.h>

#include <string>

#include "scenario_test_util.hpp"

namespace ADCS_UNITY_ID {
using adcs::sim::Claim;
using adcs::sim::RunResult;
using adcs::sim::test::metric;
using adcs::sim::test::expect_claims_hold;
using adcs::sim::test::run;
using adcs::sim::test::expect_rows_well_formed;
using adcs::sim::test::paper_verdict;
const adcs::sim::Claim* claim(const RunResult& r, const std::string& prefix) {
  return adcs::sim::test::find_claim(r, prefix);
}

//! The claim's criterion verdict as text: "holds", "fails" or "(none)".
std::string criterion(const RunResult& r, const std::string& prefix) {
  const Claim* c = claim(r, prefix);
  if (!c) return "(no such claim)";
  return c->holds ? (*c->holds ? "holds" : "fails") : "(none)";
}

TEST(FlexiblePpc, PaperClaimsP1P2P3P8P9) {
  const RunResult r = run("flexible-ppc");
  EXPECT_EQ(metric(r, "funnel_violations"), 0.0);                        // P1
  EXPECT_EQ(metric(r, "controller_flags"), 0.0);                         // P1: flag never raised
  EXPECT_NEAR(metric(r, "funnel_margin_min"), 0.167, 0.005);             // P1 PROTO
  for (const char* ax : {"err_ss_max_deg_x", "err_ss_max_deg_y", "err_ss_max_deg_z"}) {
    EXPECT_LE(metric(r, ax), 0.005) << ax;                               // P2
    EXPECT_NEAR(metric(r, ax), 2.87e-3, 0.05e-3) << ax;                  // P2 PROTO
  }
  EXPECT_LT(metric(r, "err_late_dev_from_half_rho_inf_deg"), 2e-5);     // P3
  EXPECT_NEAR(metric(r, "err_final_deg_z"), -0.0025, 2e-5);              // P3: axis 3 from below
  EXPECT_NEAR(metric(r, "eta_norm_max"), 3.3e-4, 0.2e-4);                // P8 PROTO
  EXPECT_LE(metric(r, "eta_norm_max_after_50s"), 2.0e-4);                // P8
  EXPECT_NEAR(metric(r, "torque_peak_Nm"), 38.5, 0.5);                   // P9 PROTO (U_rad)
  EXPECT_NEAR(metric(r, "torque_peak_after_5s_Nm"), 0.076, 0.002);       // P9 PROTO
  EXPECT_NEAR(metric(r, "z_peak_x"), 0.25 / 0.3, 1e-3);                  // B-S14
  EXPECT_GE(metric(r, "mu_hat_min"), 0.0);                               // B-S12
  EXPECT_LE(metric(r, "eta_norm_max_late_second_half"), metric(r, "eta_norm_max_late_first_half"));  // P8
  expect_claims_hold(r);
  expect_rows_well_formed(r);
  EXPECT_EQ(paper_verdict(r, "P1 PPATC"), "reproduced");
  EXPECT_EQ(paper_verdict(r, "P2 PPATC"), "reproduced");
  EXPECT_EQ(paper_verdict(r, "P3 "), "(none)");  // not stated in the paper: our criterion only
  EXPECT_EQ(criterion(r, "P3 "), "holds");
  EXPECT_EQ(paper_verdict(r, "P8 "), "reproduced");
  EXPECT_EQ(criterion(r, "P8 "), "holds");
  EXPECT_EQ(paper_verdict(r, "P9 "), "(none)");  // the paper gives no torque number
  EXPECT_EQ(criterion(r, "P9 "), "(none)");
}

// Issue 19: the PPATC law in float (plant in double): every claim keeps its two verdicts and the
// metrics their double values to the digits the claims read (tools/float-vs-double.py gives the
// table of every metric of the five seed-002 scenarios: docs/TARGET.md). The error e that the
// funnel transform divides is ϑ − ϑ_d, held in float to ~2e-9 rad against ρ∞ = 8.7e-5 rad.
TEST(FlexiblePpc, FloatLawKeepsEveryClaim) {
  const RunResult f = run("flexible-ppc", {{"scalar", "float"}});
  EXPECT_EQ(metric(f, "nonok_steps"), 0.0);
  EXPECT_EQ(metric(f, "funnel_violations"), 0.0);                        // P1
  EXPECT_NEAR(metric(f, "funnel_margin_min"), 0.167, 0.005);             // P1 PROTO
  for (const char* ax : {"err_ss_max_deg_x", "err_ss_max_deg_y", "err_ss_max_deg_z"})
    EXPECT_NEAR(metric(f, ax), 2.87e-3, 0.05e-3) << ax;                  // P2 PROTO, as in double
  EXPECT_LT(metric(f, "err_late_dev_from_half_rho_inf_deg"), 2e-5);     // P3
  EXPECT_NEAR(metric(f, "torque_peak_after_5s_Nm"), 0.076, 0.002);       // P9 PROTO
  expect_claims_hold(f);
  EXPECT_EQ(paper_verdict(f, "P1 PPATC"), "reproduced");
  EXPECT_EQ(paper_verdict(f, "P2 PPATC"), "reproduced");
  EXPECT_EQ(paper_verdict(f, "P8 "), "reproduced");
}

TEST(FlexibleAtc, ViolatesTheFunnelP4AndPitchMissesTheSpecP5) {
  const RunResult r = run("flexible-atc");
  EXPECT_GE(metric(r, "funnel_violations"), 1.0);                        // P4
  EXPECT_GE(metric(r, "zero_crossings"), 1.0);                           // P4
  EXPECT_NEAR(metric(r, "funnel_violations") / 1.0e6, 1.072, 0.01);     // PROTO 1,072,323 / 3e6 axis-samples
  EXPECT_NEAR(metric(r, "err_ss_max_deg_y"), 5.61e-3, 0.1e-3);           // P5: only pitch > 0.005
  EXPECT_LT(metric(r, "err_ss_max_deg_x"), 0.005);
  EXPECT_LT(metric(r, "err_ss_max_deg_z"), 0.005);
  expect_claims_hold(r);
  expect_rows_well_formed(r);
  EXPECT_EQ(paper_verdict(r, "P4 ATC"), "reproduced");
  // P5: the paper says all three axes miss 0.005 deg; only pitch does (as PROTO).
  EXPECT_EQ(paper_verdict(r, "P5 ATC"), "partly");
  EXPECT_EQ(criterion(r, "P5 ATC"), "holds");
  EXPECT_EQ(paper_verdict(r, "P8 "), "(none)");  // Figs. 5-8 are PPATC's
  EXPECT_EQ(paper_verdict(r, "P9 "), "(none)");
}

TEST(FlexibleHalfGain, PpcStillMeetsTheSpecP6AndAtcDegradesP7) {
  const RunResult p = run("flexible-ppc-halfgain");
  EXPECT_EQ(metric(p, "funnel_violations"), 0.0);                        // P6
  EXPECT_LE(metric(p, "err_ss_max_deg"), 0.005);                         // P6
  EXPECT_NEAR(metric(p, "torque_peak_Nm") / metric(p, "nominal_torque_peak_Nm"), 0.5, 0.02);  // P9
  EXPECT_NEAR(metric(p, "err_ss_max_deg") / metric(p, "nominal_err_ss_max_deg"), 1.0, 0.02);   // P6
  expect_claims_hold(p);
  expect_rows_well_formed(p);
  EXPECT_EQ(paper_verdict(p, "P6 PPATC error"), "reproduced");
  EXPECT_EQ(paper_verdict(p, "P6 PPATC steady"), "reproduced");
  EXPECT_EQ(paper_verdict(p, "P6 PPATC performance"), "reproduced");
  EXPECT_EQ(paper_verdict(p, "P9 "), "(none)");
  EXPECT_EQ(criterion(p, "P9 "), "holds");
  const RunResult a = run("flexible-atc-halfgain");
  EXPECT_GE(metric(a, "err_ss_ratio_to_nominal_y"), 2.0);                // P7
  EXPECT_GT(metric(a, "err_ss_max_deg_y"), 0.005);                       // P7
  EXPECT_NEAR(metric(a, "err_ss_max_deg_y"), 2.16e-2, 0.1e-2);           // P7 PROTO
  EXPECT_GT(metric(a, "zero_crossings"), metric(a, "nominal_zero_crossings"));  // P7: oscillation grows
  expect_claims_hold(a);
  expect_rows_well_formed(a);
  EXPECT_EQ(paper_verdict(a, "P4 ATC"), "reproduced");
  EXPECT_EQ(paper_verdict(a, "P7 "), "reproduced");
  EXPECT_EQ(criterion(a, "P7 "), "holds");
  EXPECT_EQ(criterion(a, "P9 "), "(none)");  // ATC's peak is not the initial one
}

TEST(FlexiblePpc, SampleRateStudyLimitIsTheStiffSLoop) {
  // Spec §B.3 step 15: R K reaches ~1.1e4 1/s as ρ → ρ∞, so the sampled law needs T·RK < 2:
  // stable at 1.6e-4 s with the 1e-4 s accuracy, diverges at 2e-4 s: the law then reports every
  // failed step (not usable) and, under the default failure policy, commands zero torque instead
  // of holding its diverged command, so the run ends with the failure counted rather than with
  // non-finite states (before issue 15 it threw).
  const RunResult ok = run("flexible-ppc", {{"control_period_s", "1.6e-4"}, {"record_every", "1000"}});
  EXPECT_EQ(metric(ok, "funnel_violations"), 0.0);
  EXPECT_LE(metric(ok, "err_ss_max_deg"), 0.005);
  const RunResult bad = run("flexible-ppc", {{"control_period_s", "2e-4"}, {"record_every", "1000"}});
  EXPECT_GT(metric(bad, "nonok_steps"), 1000.0);
  EXPECT_GT(metric(bad, "funnel_violations"), 1000.0);
  EXPECT_GT(metric(bad, "err_ss_max_deg"), 1.0);
}
}  // namespace

using namespace ADCS_UNITY_ID;  // as an anonymous namespace would (CMakeLists.txt, adcs_unity)
