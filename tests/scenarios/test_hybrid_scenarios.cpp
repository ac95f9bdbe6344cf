// Seed 001 paper claims on A-REF (spec §A.6 test criteria), end to end through the scenario:
// TP-FULL truth plant, 1 ms sampled adaptive law, 800 s. R1/R2/R8 are recorded, not asserted.
#include <gtest/gtest.h>

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "scenario_test_util.hpp"

namespace ADCS_UNITY_ID {
using adcs::sim::ParamSet;
using adcs::sim::RunResult;

using adcs::sim::test::metric;
using adcs::sim::test::run;
using adcs::sim::PaperVerdict;

//! The paper verdict of the claim whose text starts with `prefix` (a failure if not exactly one).
std::optional<PaperVerdict> verdict(const RunResult& r, const std::string& prefix) {
  const adcs::sim::Claim* c = adcs::sim::test::find_claim(r, prefix);
  return c ? c->paper_verdict : std::nullopt;
}
bool has_note(const RunResult& r, const std::string& prefix, const std::string& words) {
  const adcs::sim::Claim* c = adcs::sim::test::find_claim(r, prefix);
  return c && c->note.find(words) != std::string::npos;
}

// Issue 16: the paper's own numbers, judged separately from our criteria. On A-REF the bounds
// R3/R4 are reproduced but do not discriminate (the baseline meets them); R5's 100x / 10x is not
// reproduced (6.7x / 6.3x); R7's projection never acts; R9 cannot fail with three wheels.
// One test for everything the default A-REF runs show (the verdicts, our criteria R3-R9 and the
// baseline's PROTO values): each ctest test is its own process, and the 800-s adaptive run (with
// its baseline) is ~12 s of the sanitizer tree's ctest (docs/DECISIONS.md, "CI under 20
// minutes", item 24).
TEST(HybridAref, PaperVerdictsClaimsAndPrototype) {
  const RunResult r = run("hybrid-adaptive");
  EXPECT_EQ(verdict(r, "R3 "), PaperVerdict::reproduced);
  EXPECT_EQ(verdict(r, "R4 "), PaperVerdict::reproduced);
  EXPECT_TRUE(has_note(r, "R3 ", "not discriminating"));
  EXPECT_TRUE(has_note(r, "R4 ", "not discriminating"));
  EXPECT_EQ(verdict(r, "R5 "), PaperVerdict::not_reproduced);
  EXPECT_EQ(verdict(r, "R6 "), PaperVerdict::reproduced);
  EXPECT_EQ(verdict(r, "R7 "), PaperVerdict::reproduced);
  EXPECT_TRUE(has_note(r, "R7 ", "mechanism never active"));
  EXPECT_EQ(verdict(r, "R8 "), PaperVerdict::reproduced);
  EXPECT_EQ(verdict(r, "R9 "), PaperVerdict::reproduced);
  EXPECT_TRUE(has_note(r, "R9 ", "not discriminating"));
  // Our criteria R3-R7, R9 (the spec's bounds and PROTO values) on the same run.
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
  adcs::sim::test::expect_claims_hold(r);
  const RunResult b = run("hybrid-nonadaptive");
  EXPECT_EQ(verdict(b, "R1 "), PaperVerdict::not_reproduced);  // 8.35e-4 rad vs "0.3 rad order"
  EXPECT_EQ(verdict(b, "R2 "), PaperVerdict::not_reproduced);  // 3.95e-5 rad/s vs "1e-3 rad/s order"
  // R1/R2 are informative in the spec; the PROTO values pin our implementation of A-REF.
  EXPECT_NEAR(metric(b, "euler_err_ss_max_rad") / 8.35e-4, 1.0, 0.1);
  EXPECT_NEAR(metric(b, "rate_err_ss_max_rad_s") / 3.95e-5, 1.0, 0.1);
  EXPECT_EQ(metric(b, "proj_norm2_max"), 0.0);  // α = 0: estimates stay at zero
}

// Issue 19: the adaptive law in float (plant in double), α_F = 1e7 included. Θ̂_F's per-step
// increment is ~5e-6 of its value, ~50 float ulps, so each float sum rounds it by ~1 %, and
// the rounding accumulates as a random walk: over 200 s the float law tracks as the double one
// to 1e-3 relative, and the momentum estimate to 1e-4 N m s (tools/float-vs-double.py gives
// the 800 s table of every metric and claim: docs/TARGET.md).
TEST(HybridAref, FloatLawTracksAsTheDoubleLaw) {
  using Sets = std::vector<std::pair<std::string, std::string>>;
  const Sets o = {{"duration_s", "200"}, {"window_s", "[100, 200]"}, {"baseline", "skip"}};
  Sets of = o;
  of.push_back({"scalar", "float"});
  const RunResult d = run("hybrid-adaptive", o);
  const RunResult f = run("hybrid-adaptive", of);
  EXPECT_EQ(metric(f, "nonok_steps"), 0.0);
  EXPECT_EQ(metric(f, "proj_safeguard_count"), 0.0);
  EXPECT_NE(metric(f, "euler_err_ss_max_rad"), metric(d, "euler_err_ss_max_rad"));  // really float
  EXPECT_NEAR(metric(f, "euler_err_ss_max_rad"), metric(d, "euler_err_ss_max_rad"),
              1e-3 * metric(d, "euler_err_ss_max_rad"));
  EXPECT_NEAR(metric(f, "rate_err_ss_max_rad_s"), metric(d, "rate_err_ss_max_rad_s"),
              1e-2 * metric(d, "rate_err_ss_max_rad_s"));
  EXPECT_NEAR(metric(f, "momentum_est_err_final_Nms"), metric(d, "momentum_est_err_final_Nms"), 1e-4);
  EXPECT_NEAR(metric(f, "pinv_sigma_min"), metric(d, "pinv_sigma_min"), 1e-5);
}

// R7 with teeth: alpha_G = 1e8 drives |Θ̂_G|² into the projection band (β, β + δ) and the
// projection keeps it below β + δ = 0.15 without the safeguard.
TEST(HybridAref, ProjectionVariantExercisesR7) {
  const RunResult r = run("hybrid-adaptive-projection", {{"baseline", "skip"}});
  EXPECT_GT(metric(r, "proj_norm2_max"), 0.05);
  EXPECT_LE(metric(r, "proj_norm2_max"), 0.15 + 1e-9);
  EXPECT_EQ(metric(r, "proj_safeguard_count"), 0.0);
  EXPECT_EQ(verdict(r, "R7 "), PaperVerdict::reproduced);
  EXPECT_FALSE(has_note(r, "R7 ", "mechanism never active"));
  EXPECT_EQ(metric(r, "nonok_steps"), 0.0);
}

// Issue 16: seed 001 calibrated to the paper's own baseline (tools/calibrate-seed001.py, best
// grid point: h_cw 40 N m s, J x 0.25, a Mode-A draw, 150 rad/s unknown wheel bias). The baseline
// comes within 0.54 decades of R1's "0.3 rad order" and 0.4 of R2's "1e-3 rad/s"; on it the
// adaptive law meets R3's 0.003 rad but not R4 or R5's 100x / 10x. Recorded, whichever it is.
TEST(HybridCalibrated, BaselineNearThePapersOrdersAndWhatAdaptationThenDoes) {
  const RunResult b = run("hybrid-nonadaptive-calibrated");
  EXPECT_NEAR(metric(b, "euler_err_ss_max_rad"), 0.0855, 0.005);
  EXPECT_NEAR(metric(b, "rate_err_ss_max_rad_s"), 2.51e-3, 2e-4);
  EXPECT_EQ(verdict(b, "R1 "), PaperVerdict::partly);
  EXPECT_EQ(verdict(b, "R2 "), PaperVerdict::reproduced);
  const RunResult r = run("hybrid-adaptive-calibrated");
  EXPECT_EQ(verdict(r, "R3 "), PaperVerdict::reproduced);
  EXPECT_FALSE(has_note(r, "R3 ", "not discriminating"));  // the baseline is 0.0855 rad here
  EXPECT_EQ(verdict(r, "R4 "), PaperVerdict::not_reproduced);
  EXPECT_EQ(verdict(r, "R5 "), PaperVerdict::not_reproduced);
  EXPECT_NEAR(metric(r, "improvement_ratio_euler"), 33.5, 2.0);
  EXPECT_LT(metric(r, "improvement_ratio_rate"), 1.0);
}

}  // namespace

using namespace ADCS_UNITY_ID;  // as an anonymous namespace would (CMakeLists.txt, adcs_unity)

namespace ADCS_UNITY_ID {
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

using namespace ADCS_UNITY_ID;  // as an anonymous namespace would (CMakeLists.txt, adcs_unity)

namespace ADCS_UNITY_ID {
// Spec §A.7 S11: with the true Θ and no adaptation, TP-FULL (J(γ) variation, gimbal momentum)
// still tracks to ~1.5e-7 rad over [100, 800] s: the truth-plant-only mismatch is negligible.
TEST(HybridAref, OracleOnTheFullPlantS11) {
  const RunResult r = run("hybrid-nonadaptive", {{"initial_estimates", "truth"}, {"window_s", "[100, 800]"}});
  EXPECT_NEAR(metric(r, "principal_err_ss_max_rad") / 1.5e-7, 1.0, 0.3);  // PROTO 1.5e-7
}
}  // namespace

using namespace ADCS_UNITY_ID;  // as an anonymous namespace would (CMakeLists.txt, adcs_unity)

namespace ADCS_UNITY_ID {
// Beyond the paper: the paper's explicit-Euler adaptation is unstable at T_c = 10 ms (spec §A.5:
// ≥ 5 ms); the normalized step (adapt/normalized_step.hpp) is stable at 10 ms and at 10 Hz with
// the 1 ms accuracy (measured 1.245e-4 / 1.225e-4 rad vs 1.246e-4 at 1 ms).
TEST(HybridAref, NormalizedAdaptationIsStableAtFlightRates) {
  const RunResult unstable = run("hybrid-adaptive", {{"control_period_s", "0.01"}, {"baseline", "skip"}});
  EXPECT_GT(metric(unstable, "proj_safeguard_count"), 0.0);
  EXPECT_GT(metric(unstable, "euler_err_ss_max_rad"), 1e-2);
  for (const char* T : {"0.01", "0.1"}) {
    const RunResult r = run("hybrid-adaptive", {{"control_period_s", T}, {"adaptation_step", "normalized"}});
    EXPECT_NEAR(metric(r, "euler_err_ss_max_rad") / 1.25e-4, 1.0, 0.1) << T;
    EXPECT_LE(metric(r, "rate_err_ss_max_rad_s"), 1e-5) << T;
    EXPECT_GE(metric(r, "improvement_ratio_euler"), 5.0) << T;
    EXPECT_GE(metric(r, "improvement_ratio_rate"), 4.0) << T;
    EXPECT_EQ(metric(r, "proj_safeguard_count"), 0.0) << T;
    EXPECT_EQ(metric(r, "nonok_steps"), 0.0) << T;
  }
}

// Spec §A.5 robustness case: constant τ_ext = 1e-5 N m per axis. The inertial momentum then
// changes by ∫Cᵀτ dt (S4); the drift metric measures the plant against that integral.
TEST(HybridAref, ExternalTorqueRobustnessCase) {
  const RunResult r = run("hybrid-adaptive", {{"tau_ext_Nm", "[1e-5, 1e-5, 1e-5]"}, {"baseline", "skip"}});
  EXPECT_LE(metric(r, "momentum_drift_rel"), 1e-10);
  EXPECT_LE(metric(r, "euler_err_ss_max_rad"), 3e-3);  // R3 still holds (measured 1.24e-4)
  EXPECT_LE(metric(r, "rate_err_ss_max_rad_s"), 1e-4);
}

// Spec A.2.3 Mode B (rigid rotation of each actuator): the paper's claims R3, R4, R7 hold.
TEST(HybridAref, ModeBRigidDeviationsKeepTheClaims) {
  const RunResult r = run("hybrid-adaptive", {{"deviation", "rigid"}, {"baseline", "skip"}}, 3);
  EXPECT_LE(metric(r, "euler_err_ss_max_rad"), 3e-3);  // measured 1.36e-4
  EXPECT_LE(metric(r, "rate_err_ss_max_rad_s"), 1e-4);
  EXPECT_LE(metric(r, "proj_norm2_max"), 0.15 + 1e-9);
  EXPECT_EQ(metric(r, "proj_safeguard_count"), 0.0);
}

// Spec §A.5 optional actuator limits: the suggested ones (1 rad/s, 50 rad/s²) are never reached
// on A-REF (peaks 3.1e-3 rad/s, 8e-6 rad/s²) and change nothing; a limit below the need is
// flagged (metric and a failing "check" claim).
TEST(HybridAref, ActuatorLimitsAreFlaggedWhenHit) {
  const std::vector<std::pair<std::string, std::string>> quick{
      {"duration_s", "60"}, {"window_s", "[30, 60]"}, {"baseline", "skip"}};
  auto with = [&](std::vector<std::pair<std::string, std::string>> extra) {
    extra.insert(extra.begin(), quick.begin(), quick.end());
    return run("hybrid-adaptive", extra);
  };
  const RunResult free = with({});
  const RunResult loose = with({{"gimbal_rate_max_rad_s", "1"}, {"wheel_accel_max_rad_s2", "50"}});
  EXPECT_EQ(metric(loose, "actuator_limit_hits"), 0.0);
  EXPECT_EQ(metric(loose, "euler_err_ss_max_rad"), metric(free, "euler_err_ss_max_rad"));
  EXPECT_LE(metric(free, "gimbal_rate_peak_rad_s"), 1e-2);
  const RunResult tight = with({{"gimbal_rate_max_rad_s", "1e-3"}});
  EXPECT_GT(metric(tight, "actuator_limit_hits"), 0.0);
  bool flagged = false;
  for (const auto& c : tight.claims)
    if (c.kind == "check" && c.holds.has_value() && !*c.holds) flagged = true;
  EXPECT_TRUE(flagged);
}
}  // namespace

using namespace ADCS_UNITY_ID;  // as an anonymous namespace would (CMakeLists.txt, adcs_unity)
