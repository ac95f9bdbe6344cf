// Seed 004 checklist (spec §B.9) end to end through the scenarios. Item 1 open loop (60,000
// steps); items 2, 4, 6, 7, 8, 9 from one closed-loop run (3e5 steps, attitude steps at 1e4 and
// 2e4 s); item 5 (PID vs PID + compensation, 5000 s); item 3 recorded. Values are pinned to the
// spec's prototype (PROTO) where it gives them. Each paper claim's two verdicts (issue 16) are
// asserted: the paper verdict against the paper's own statement, and our criterion (holds), so a
// change in the physics shows up as a changed verdict.
#include <gtest/gtest.h>

#include <string>

#include "scenario_test_util.hpp"

namespace ADCS_UNITY_ID {
using adcs::sim::Claim;
using adcs::sim::RunResult;
using adcs::sim::test::expect_claims_hold;
using adcs::sim::test::metric;
using adcs::sim::test::run;
using adcs::sim::test::expect_rows_well_formed;
using adcs::sim::test::paper_verdict;
const adcs::sim::Claim* claim(const RunResult& r, const std::string& prefix) {
  return adcs::sim::test::find_claim(r, prefix);
}
// The paper verdicts of items 2-7 on the paper's gains (dragfree-adrc), asserted on that run by
// ClosedLoopChecklistItems2To9; the retuned loop must give the same ones. A table rather than a
// second 3e5-step run in TunedLoopMeetsTheSpectrumOverTheWholeBand: each ctest test is its own
// process, and that run is ~11 s of the sanitizer tree's ctest (docs/DECISIONS.md, "CI under 20
// minutes", item 24).
struct ItemVerdict {
  const char* id;
  const char* verdict;
};
constexpr ItemVerdict kPaperGainVerdicts[] = {
    {"B.9-2", "reproduced"}, {"B.9-3", "partly"}, {"B.9-4", "reproduced"}, {"B.9-6", "reproduced"},
    {"B.9-7", "partly"}};  // why each: the metric checks beside them in ClosedLoopChecklistItems2To9

TEST(DragFree, SaturatedUpdateBeatsSkippingItem1) {
  const RunResult r = run("dragfree-estimators");
  const double L1 = metric(r, "dist_rmse_L1"), L2 = metric(r, "dist_rmse_L2"), L3 = metric(r, "dist_rmse_L3");
  EXPECT_LT(L2, L1);
  EXPECT_LT(L1, L3);
  EXPECT_NEAR(L1, 2.60e-3, 0.3e-3);  // PROTO 2.60e-3 / 1.08e-3 / 5.68e-3 N
  EXPECT_NEAR(L2, 1.08e-3, 0.15e-3);
  EXPECT_NEAR(L3, 5.68e-3, 0.5e-3);
  EXPECT_NEAR(metric(r, "accel_saturated_fraction"), 0.59, 0.02);
  expect_claims_hold(r);
  expect_rows_well_formed(r);
  EXPECT_EQ(paper_verdict(r, "B.9-1"), "reproduced");  // both orderings of Fig. 5 shown
}

// Issue 20: the U-D filter equals the Joseph-form filter it replaced (run as a shadow on the same
// inputs) to 1e-9 of each state's scale once the Joseph form has recovered from the first updates,
// where it loses ~13 digits and projects once (tests/estimate/test_drag_free_eskf.cpp measures both
// against quadruple precision). The whole 30,000 s run: 6.3e-10 from 30 s on (docs/DECISIONS.md).
TEST(DragFree, UdFilterIsTheJosephFilterAfterItsTransient) {
  const RunResult r = run("dragfree-adrc", {{"duration_s", "300"}, {"joseph_shadow", "on"}});
  EXPECT_LT(metric(r, "alg1_vs_joseph_max_rel_after_transient"), 1e-9);
  EXPECT_EQ(metric(r, "psd_projections"), 0.0);
  EXPECT_EQ(metric(r, "psd_projections_joseph"), 1.0);
}

TEST(DragFree, ClosedLoopChecklistItems2To9) {
  const RunResult r = run("dragfree-adrc");
  // 2: Algorithm 2 alone drifts (PROTO 1.4e-2 -> 0.21 -> 1.05 m), Algorithm 1 does not (1.3e-8 m).
  EXPECT_GT(metric(r, "alg2_pos_rmse_growth"), 10.0);
  EXPECT_GE(metric(r, "alg2_pos_rmse_1000_5000"), 1e3 * metric(r, "alg1_pos_rmse_1000_5000"));
  // 4: fusion < 0.1x both (PROTO 2.2e-8 vs 3.3e-5 vs 2.2e-4..1.1e-3 N).
  EXPECT_LT(metric(r, "fusion_dist_rmse"), 0.1 * metric(r, "alg1_dist_rmse"));
  EXPECT_LT(metric(r, "fusion_dist_rmse"), 0.1 * metric(r, "alg2_dist_rmse"));
  // 6: steady operation < 1e-6 (PROTO 1.4e-7).
  EXPECT_LT(metric(r, "steady_max_abs"), 1e-6);
  // 7: steps reached and relative attitude recovered (PROTO settling 103/361/660 s up).
  EXPECT_LT(metric(r, "att_step_final_err_rad"), 1e-5);
  EXPECT_EQ(metric(r, "rel_att_recovered"), 1.0);
  EXPECT_NEAR(metric(r, "att_settle_up_s_x"), 103.0, 20.0);
  // 8: median ASD below 3e-14 in 1-30 mHz; the max sits at the ~11 mHz loop resonance.
  EXPECT_LT(metric(r, "asd_tm_acc_median_1_30mHz"), 3e-14);
  EXPECT_NEAR(metric(r, "asd_tm_acc_peak_freq_Hz"), 0.011, 0.0015);
  // 9: commands within the cube; a handful of saturated accelerometer samples at start-up.
  EXPECT_LE(metric(r, "command_max_abs"), 0.03);
  EXPECT_LT(metric(r, "accel_saturated_samples"), 50.0);
  EXPECT_EQ(metric(r, "nonok_steps"), 0.0);
  EXPECT_EQ(metric(r, "psd_projections"), 0.0);  // issue 20: the U-D filter never projects
  expect_claims_hold(r);
  expect_rows_well_formed(r);
  // Paper verdicts (issue 16), each against the paper's own words (kPaperGainVerdicts).
  for (const ItemVerdict& v : kPaperGainVerdicts) EXPECT_EQ(paper_verdict(r, v.id), v.verdict) << v.id;
  // 2: Alg. 2 accumulates (above), Alg. 1 does not.
  EXPECT_LE(metric(r, "alg1_pos_rmse_1000_5000"), 2.0 * metric(r, "alg1_pos_rmse_0_100"));
  EXPECT_LE(metric(r, "alg1_pos_rmse_100_1000"), 2.0 * metric(r, "alg1_pos_rmse_0_100"));
  // 3: "worse later" only; "better early" is not seen on [0,100) s (as in PROTO).
  EXPECT_GT(metric(r, "alg2_dist_rmse_0_100"), metric(r, "alg1_dist_rmse_0_100"));
  // 7: reached and recovered, but phi_rel settles (2 % of its peak) after the attitude does:
  // "adjusts quickly" is not shown.
  EXPECT_GT(metric(r, "rel_att_settle_2pct_s_step1"), metric(r, "att_settle_up_s_z"));
  // 8: the paper's "below 3e-14 across 1-30 mHz" is judged on the band max (every axis): the
  // ~11 mHz loop resonance exceeds it by more than x2 on each axis; our median criterion holds.
  EXPECT_EQ(paper_verdict(r, "B.9-8"), "not reproduced");
  for (const char* m : {"asd_tm_acc_max_1_30mHz", "asd_tm_acc_max_1_30mHz_y", "asd_tm_acc_max_1_30mHz_z"})
    EXPECT_GT(metric(r, m), 2.0 * 3e-14) << m;
  for (const char* m : {"asd_tm_acc_peak_freq_Hz_y", "asd_tm_acc_peak_freq_Hz_z"})
    EXPECT_NEAR(metric(r, m), 0.011, 0.0015) << m;
  EXPECT_EQ(paper_verdict(r, "B.9-9"), "(none)");  // a check of ours
}

// Issue 16: the 11 mHz peak is the drag-free loop's resonance (linear zone: omega_n =
// sqrt(5/1050), damping 0.13, noise gain 1/(2 zeta) ~ 4); our retuning (k_d 1.9 -> 10, damping
// 0.69) keeps the TM residual ASD below 3e-14 over all of 1-30 mHz on every axis, and every
// other B.9 item keeps its verdicts and criteria.
TEST(DragFree, TunedLoopMeetsTheSpectrumOverTheWholeBand) {
  const RunResult r = run("dragfree-adrc-tuned");
  expect_rows_well_formed(r);
  for (const char* m : {"asd_tm_acc_max_1_30mHz", "asd_tm_acc_max_1_30mHz_y", "asd_tm_acc_max_1_30mHz_z"})
    EXPECT_LT(metric(r, m), 3e-14) << m;
  EXPECT_EQ(paper_verdict(r, "B.9-8"), "reproduced");
  EXPECT_NEAR(metric(r, "loop_resonance_Hz"), 0.011, 0.0005);
  EXPECT_NEAR(metric(r, "loop_noise_gain_peak_paper_kd"), 3.97, 0.05);
  EXPECT_LT(metric(r, "loop_noise_gain_peak_run_kd"), 1.3);
  for (const ItemVerdict& v : kPaperGainVerdicts) EXPECT_EQ(paper_verdict(r, v.id), v.verdict) << v.id;
  for (const auto& c : r.claims) EXPECT_TRUE(c.holds.value_or(true)) << c.claim << ": " << c.ours;
  const Claim* c8 = claim(r, "B.9-8");
  ASSERT_NE(c8, nullptr);
  EXPECT_NE(c8->note.find("OUR retuned"), std::string::npos);  // labelled ours, not the paper's gains
}

// Issue 19: seed 004's flight side in float (Algorithms 1-3 and the ADRC, DragFreeFlightT<float>;
// the plant, sensors and metrics double). The retuned loop, whose spectrum claim holds in double,
// keeps it in float over the whole band on every axis, and every other B.9 item keeps the double
// run's verdicts and criteria: float's rounding of the 1.3e-2 N disturbance estimate (~1e-9 N) is
// far below the filter's own error (~1e-5 N), and the test mass's residual acceleration is set by
// the relative displacement, which the loop holds at ~1e-8 m either way.
TEST(DragFree, FloatLoopKeepsEveryVerdictAndTheSpectrum) {
  const RunResult r = run("dragfree-adrc-tuned", {{"scalar", "float"}});
  expect_rows_well_formed(r);
  EXPECT_EQ(metric(r, "nonok_steps"), 0.0);
  for (const char* m : {"asd_tm_acc_max_1_30mHz", "asd_tm_acc_max_1_30mHz_y", "asd_tm_acc_max_1_30mHz_z"})
    EXPECT_LT(metric(r, m), 3e-14) << m;
  EXPECT_EQ(paper_verdict(r, "B.9-8"), "reproduced");
  for (const ItemVerdict& v : kPaperGainVerdicts) EXPECT_EQ(paper_verdict(r, v.id), v.verdict) << v.id;
  for (const auto& c : r.claims) EXPECT_TRUE(c.holds.value_or(true)) << c.claim << ": " << c.ours;
  // As in double (the float run of this commit: 8.64e-15 median, fusion 2.24e-8 N, steady 1.22e-7).
  EXPECT_LT(metric(r, "asd_tm_acc_median_1_30mHz"), 3e-14);
  EXPECT_LT(metric(r, "fusion_dist_rmse"), 0.1 * metric(r, "alg1_dist_rmse"));
  EXPECT_LT(metric(r, "steady_max_abs"), 1e-6);
  EXPECT_LT(metric(r, "att_step_final_err_rad"), 1e-5);
}

// Item 1 in float: the three Algorithm 2 copies keep the ordering L2 < L1 < L3.
TEST(DragFree, FloatEstimatorsKeepItem1) {
  const RunResult r = run("dragfree-estimators", {{"scalar", "float"}});
  EXPECT_LT(metric(r, "dist_rmse_L2"), metric(r, "dist_rmse_L1"));
  EXPECT_LT(metric(r, "dist_rmse_L1"), metric(r, "dist_rmse_L3"));
  EXPECT_EQ(paper_verdict(r, "B.9-1"), "reproduced");
  for (const auto& c : r.claims) EXPECT_TRUE(c.holds.value_or(true)) << c.claim << ": " << c.ours;
}

TEST(DragFree, AdrcBeatsPidOnXItem5) {
  const RunResult r = run("dragfree-pid");
  EXPECT_NEAR(metric(r, "rx_max_m"), 3.69e-3, 0.3e-3);  // PROTO PID 3.69e-3 m
  EXPECT_NEAR(metric(r, "rx_mean_m"), 2.48e-3, 0.2e-3);  // 12.8 mN / 5.55 N/m
  EXPECT_LT(metric(r, "rx_max_ratio_compensated_to_pid"), 1e-3);
  expect_claims_hold(r);
  expect_rows_well_formed(r);
  EXPECT_EQ(paper_verdict(r, "B.9-5"), "reproduced");
}
}  // namespace

using namespace ADCS_UNITY_ID;  // as an anonymous namespace would (CMakeLists.txt, adcs_unity)
