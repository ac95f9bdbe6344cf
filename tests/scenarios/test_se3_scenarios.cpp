// Seed 003 checklist (spec §A.9) end to end through the se3-ptc / se3-ftsmc scenarios. Values are
// pinned to the spec's prototype (PROTO, Appendix C.3) with the spec's tolerances: ±15 %, settling
// times ±10 s; hard requirements t_s(β) < T, t_s(β) increasing in T and N_tx ≤ 3072. Each 200 s run
// takes ~0.3 s; the state-1 BsPdTC run is shared.
// Issue 16: the paper verdicts (against the paper's own numbers, src/scenarios/verdicts.hpp) are
// asserted per claim, found by a stable prefix of the claim text, so a change in the physics that
// moves a claim across a verdict boundary fails here visibly.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include "scenario_test_util.hpp"

namespace ADCS_UNITY_ID {
using adcs::sim::Claim;
using adcs::sim::PaperVerdict;
using adcs::sim::RunResult;
using adcs::sim::test::expect_claims_hold;
using adcs::sim::test::metric;
using adcs::sim::test::run;

//! se3-ptc, state 1, T = 120 s, every default (the spec's reference run).
const RunResult& ptc_state1() {
  static const RunResult r = run("se3-ptc");
  return r;
}

void expect_within15(double ours, double proto, const char* what) {
  EXPECT_NEAR(ours, proto, 0.15 * proto) << what;
}

//! The claim's paper verdict is `v` (compared as text, so a failure prints both).
using adcs::sim::test::find_claim;

void expect_verdict(const RunResult& r, const std::string& prefix, PaperVerdict v) {
  const Claim* c = find_claim(r, prefix);
  if (c == nullptr) return;
  ASSERT_TRUE(c->paper_verdict.has_value()) << c->claim;
  EXPECT_STREQ(to_string(*c->paper_verdict), to_string(v)) << c->claim << ": " << c->ours << " (paper "
                                                           << c->paper_value << ")";
}

void expect_no_verdict(const RunResult& r, const std::string& prefix) {
  const Claim* c = find_claim(r, prefix);
  if (c != nullptr) {
    EXPECT_FALSE(c->paper_verdict.has_value()) << c->claim << ": " << c->note;
  }
}

//! Issue 16 rules every row follows: checks carry no paper verdict; no fixed verdict words in the
//! texts (the verdicts are the computed fields); a criterion is stated wherever one is judged.
void expect_verdict_fields_consistent(const RunResult& r) {
  for (const Claim& c : r.claims) {
    if (c.kind == "check") {
      EXPECT_FALSE(c.paper_verdict.has_value()) << c.claim;
    }
    if (c.holds.has_value()) {
      EXPECT_FALSE(c.criterion.empty()) << c.claim;
    }
    for (const std::string* text : {&c.claim, &c.paper_value, &c.ours, &c.criterion}) {
      EXPECT_EQ(text->find("reproduced"), std::string::npos) << c.claim << ": " << *text;
      EXPECT_EQ(text->find("not met"), std::string::npos) << c.claim << ": " << *text;
    }
  }
}

TEST(Se3Scenarios, PtcState1MatchesPrototypeItems1To5And10) {
  const RunResult& r = ptc_state1();
  // 1, 2: settling (PROTO 30.5 / 57.1 s; ours 30.5 / 56.6 s, CVODE and RK4 agree to 0.5 s).
  EXPECT_NEAR(metric(r, "settle_att_s"), 30.5, 10.0);
  EXPECT_NEAR(metric(r, "settle_pos_s"), 57.1, 10.0);
  EXPECT_NEAR(metric(r, "settle_att_s"), 30.5, 2.0);  // tighter: regression guard
  EXPECT_NEAR(metric(r, "settle_pos_s"), 57.1, 2.0);
  EXPECT_LT(metric(r, "settle_pos_s"), 120.0);
  EXPECT_DOUBLE_EQ(metric(r, "settle_s"), std::max(metric(r, "settle_att_s"), metric(r, "settle_pos_s")));
  // 3-5: steady bounds over [150, 200] s.
  expect_within15(metric(r, "att_err_ss_deg"), 8.6e-3, "att_err_ss_deg");
  expect_within15(metric(r, "pos_err_ss_m"), 1.3e-5, "pos_err_ss_m");
  expect_within15(metric(r, "rate_err_ss_deg_s"), 3.5e-3, "rate_err_ss_deg_s");
  expect_within15(metric(r, "vel_err_ss_m_s"), 5.5e-6, "vel_err_ss_m_s");
  // 10: ψ̂ peaks early (PROTO 3.2e-4 at 9.6 s), then decays (to 1e-8..5e-7) before t_s(β).
  expect_within15(metric(r, "psi_hat_peak"), 3.2e-4, "psi_hat_peak");
  EXPECT_LT(metric(r, "psi_hat_peak_time_s"), metric(r, "settle_pos_s"));
  EXPECT_LT(metric(r, "disturbance_bound_est_final"), 1e-2 * metric(r, "psi_hat_peak"));
  EXPECT_GE(metric(r, "disturbance_bound_est_final"), 0.0);
  // Actuators: limits reached (saturation-limited transient) but never exceeded; no failed tick.
  EXPECT_DOUBLE_EQ(metric(r, "torque_max_Nm"), 0.5);
  EXPECT_DOUBLE_EQ(metric(r, "force_max_N"), 5.0);
  EXPECT_EQ(metric(r, "nonok_steps"), 0.0);
  expect_claims_hold(r);
}

TEST(Se3Scenarios, TransmissionsItem8) {
  const RunResult& r = ptc_state1();
  EXPECT_EQ(metric(r, "transmissions_unquantized"), 9600.0);  // 8 Hz x 6 channels x 200 s
  EXPECT_LE(metric(r, "transmissions"), 3072.0);              // hard: 0.32 x 9600
  EXPECT_GE(metric(r, "tx_reduction"), 0.65);
  expect_within15(metric(r, "transmissions"), 2957.0, "transmissions");
}

// Issue 16: state 1, T = 120 s against the paper's own numbers (§3.1). Our criteria (PROTO ±15 %,
// N_tx <= 3072) hold throughout; the paper verdicts differ where the reconstruction differs.
TEST(Se3Scenarios, PtcState1PaperVerdicts) {
  const RunResult& r = ptc_state1();
  // Before T as stated, but 0.40 x / 0.63 x the paper's 75.8 s / 90.5 s (verdict_value: partly or not).
  expect_verdict(r, "A.9-1 attitude converges", PaperVerdict::partly);
  expect_verdict(r, "A.9-2/6/7 position converges", PaperVerdict::partly);
  // 8.8e-3 deg and 3.7e-3 deg/s: more than twice the paper's bounds 3.72e-3 deg, 1.60e-3 deg/s.
  expect_verdict(r, "A.9-3 steady attitude error", PaperVerdict::not_reproduced);
  expect_verdict(r, "A.9-4 steady position error", PaperVerdict::reproduced);
  expect_verdict(r, "A.9-5 steady rate error", PaperVerdict::not_reproduced);
  expect_verdict(r, "A.9-5 steady velocity error", PaperVerdict::reproduced);
  // 69.2 % fewer transmissions against the paper's "> 70 %", though N_tx <= 3072 (68 %) holds.
  expect_verdict(r, "A.9-8 transmissions", PaperVerdict::partly);
  const Claim* tx = find_claim(r, "A.9-8 transmissions");
  ASSERT_NE(tx, nullptr);
  EXPECT_EQ(tx->holds, std::optional<bool>(true));
  EXPECT_LT(metric(r, "tx_reduction"), 0.70);
  expect_verdict(r, "A.9-10 psi_hat overshoots", PaperVerdict::reproduced);
  // Dwell: torque ~7 s yes, force ~10 s no (24.9 s), steady "mostly > one period" no (46 %).
  expect_verdict(r, "A.9-9 dwell times", PaperVerdict::partly);
  expect_no_verdict(r, "A.9-14 initial errors");  // the paper's values are for state 4
  expect_verdict_fields_consistent(r);
}

TEST(Se3Scenarios, EveryInitialStateSettlesBeforeTItems6And14) {
  const double proto[4] = {57.1, 74.8, 86.5, 116.4};
  std::vector<double> settle{metric(ptc_state1(), "settle_pos_s")};
  for (int s = 2; s <= 4; ++s) {
    const RunResult r = run("se3-ptc", {{"initial_state", std::to_string(s)}});
    const double ts = metric(r, "settle_pos_s");
    EXPECT_LT(ts, 120.0) << "state " << s;
    EXPECT_NEAR(ts, proto[s - 1], 10.0) << "state " << s;
    settle.push_back(ts);
    if (s == 4) {  // 14: |θ(0)| = 165.48°, ‖β(0)‖ = 71.2 m in [55, 81] (A.10-9), ‖R_e(0)‖ = 55.45 m
      EXPECT_NEAR(metric(r, "eta0_att_deg"), 165.48, 0.05);
      EXPECT_NEAR(metric(r, "eta0_pos_m"), 71.2, 0.1);
      EXPECT_NEAR(metric(r, "Re0_m"), 55.45, 0.01);
      // 165.48 deg and 71.2 m against the paper's 165.5 deg and 79.9 m (verdict_value, 30 %).
      expect_verdict(r, "A.9-14 initial errors", PaperVerdict::reproduced);
      // 116 s < T and 1.2 x the paper's 96.8 s.
      expect_verdict(r, "A.9-2/6/7 position converges", PaperVerdict::reproduced);
    }
    expect_no_verdict(r, "A.9-3 steady attitude error");  // the paper's bound is for state 1
    expect_no_verdict(r, "A.9-8 transmissions");
    expect_verdict_fields_consistent(r);
    expect_claims_hold(r);
  }
  // 11 (informational, not gated): the paper's < 10 s spread is not reproduced (PROTO 59 s).
  const auto [lo, hi] = std::minmax_element(settle.begin(), settle.end());
  RecordProperty("settle_pos_spread_s", std::to_string(*hi - *lo));
}

// se3-campaign: the multi-run claims (6, 7, 11, 12) from one fixed gain set, on the same closed
// loop as the single runs (bit-identical metrics), with the T sweep and the FTSMC per state.
TEST(Se3Scenarios, CampaignItems6To7And11To12) {
  const RunResult c = run("se3-campaign");
  const RunResult& p1 = ptc_state1();
  EXPECT_EQ(metric(c, "settle_pos_s_ptc_s1"), metric(p1, "settle_pos_s"));
  EXPECT_EQ(metric(c, "settle_att_s_ptc_s1"), metric(p1, "settle_att_s"));
  EXPECT_EQ(metric(c, "transmissions_ptc_s1"), metric(p1, "transmissions"));
  // 6: every state before T = 120 s, within ±10 s of PROTO.
  const double proto_states[4] = {57.1, 74.8, 86.5, 116.4};
  for (int s = 1; s <= 4; ++s) {
    const double ts = metric(c, "settle_pos_s_ptc_s" + std::to_string(s));
    EXPECT_LT(ts, 120.0) << "state " << s;
    EXPECT_NEAR(ts, proto_states[s - 1], 10.0) << "state " << s;
    EXPECT_EQ(metric(c, "nonok_steps_ptc_s" + std::to_string(s)), 0.0);
    EXPECT_EQ(metric(c, "nonok_steps_ftsmc_s" + std::to_string(s)), 0.0);
  }
  // 7: T sweep (state 1): each below its T, strictly increasing, within ±10 s of PROTO.
  const char* Ts[4] = {"80", "100", "120", "140"};
  const double T[4] = {80.0, 100.0, 120.0, 140.0}, proto_T[4] = {46.5, 51.0, 57.1, 62.8};
  double previous = 0.0;
  for (int i = 0; i < 4; ++i) {
    const double ts = metric(c, std::string("settle_pos_s_ptc_T") + Ts[i]);
    EXPECT_LT(ts, T[i]) << "T = " << T[i];
    EXPECT_GT(ts, previous) << "T = " << T[i] << ": t_s(beta) must increase with T";
    EXPECT_NEAR(ts, proto_T[i], 10.0) << "T = " << T[i];
    previous = ts;
  }
  EXPECT_EQ(metric(c, "settle_pos_s_ptc_T120"), metric(c, "settle_pos_s_ptc_s1"));  // shared run
  // 12: FTSMC no later than the BsPdTC from state 1; its state-4 time is informational (PROTO 105.8 s,
  // paper 127.6 s: the "> 120 s" is not reproduced), as is the spread (11; PROTO 59 s).
  EXPECT_LE(metric(c, "settle_pos_s_ftsmc_s1"), metric(c, "settle_pos_s_ptc_s1"));
  EXPECT_NEAR(metric(c, "settle_pos_s_ftsmc_s4"), 105.8, 10.0);
  EXPECT_NEAR(metric(c, "settle_pos_spread_ptc_s"), 59.0, 10.0);
  RecordProperty("ftsmc_state4_settle_pos_s", std::to_string(metric(c, "settle_pos_s_ftsmc_s4")));
  int gated = 0;
  for (const auto& claim : c.claims) gated += claim.holds.has_value() ? 1 : 0;
  EXPECT_EQ(gated, 4 + 1 + 1 + 1);  // 6 (x4), 7, 12 first part, the no-failure check
  expect_claims_hold(c);
  // Issue 16, paper verdicts. 6: all before T; state 1 at 0.63 x the paper's 90.5 s (partly),
  // states 3, 4 within 30 % of 95.2 / 96.8 s, state 2 has no paper time.
  expect_verdict(c, "A.9-6 BsPdTC position settles before T, initial state 1", PaperVerdict::partly);
  expect_verdict(c, "A.9-6 BsPdTC position settles before T, initial state 2", PaperVerdict::reproduced);
  expect_verdict(c, "A.9-6 BsPdTC position settles before T, initial state 3", PaperVerdict::reproduced);
  expect_verdict(c, "A.9-6 BsPdTC position settles before T, initial state 4", PaperVerdict::reproduced);
  // 7: below T and increasing as stated, at 0.61-0.66 x the paper's times.
  expect_verdict(c, "A.9-7 T sweep", PaperVerdict::partly);
  // 11: 59 s against the paper's "< 10 s".
  expect_verdict(c, "A.9-11 BsPdTC spread", PaperVerdict::not_reproduced);
  expect_verdict(c, "A.9-12 FTSMC position settles no later", PaperVerdict::reproduced);
  // 12: the FTSMC settles from state 4 inside 120 s (paper 127.6 s); spread 56 s vs "close to 40 s".
  expect_verdict(c, "A.9-12 FTSMC from state 4 exceeds", PaperVerdict::not_reproduced);
  expect_verdict(c, "A.9-12 FTSMC spread", PaperVerdict::partly);
  // The paper's "BsPdTC slightly more accurate than the FTSMC" is reversed here in every state.
  expect_verdict(c, "BsPdTC steady errors below the FTSMC's", PaperVerdict::not_reproduced);
  expect_verdict_fields_consistent(c);
}

// Figs 8-9: the dwell table has, per channel, one entry per constant interval of u_c; the
// intervals tile the run and there is one per transmission (a transmission starts an interval).
TEST(Se3Scenarios, DwellTableTilesTheRunItem9) {
  const RunResult& r = ptc_state1();
  const adcs::sim::Table* dwell = nullptr;
  for (const auto& t : r.tables)
    if (t.file == "se3-ptc-dwell.csv") dwell = &t;
  ASSERT_NE(dwell, nullptr);
  ASSERT_EQ(dwell->names.size(), 7u);
  double intervals = 0.0;
  for (std::size_t ch = 1; ch < 7; ++ch) {
    double total = 0.0;
    for (double d : dwell->columns[ch])
      if (!std::isnan(d)) {
        EXPECT_GE(d, 0.125);
        total += d;
        intervals += 1.0;
      }
    EXPECT_DOUBLE_EQ(total, 200.0) << dwell->names[ch];
  }
  EXPECT_EQ(intervals, metric(r, "transmissions"));
  // Spec A.9 #9 (informational): PROTO 3.0-5.9 s torque, 13.8-24.9 s force before 60 s.
  EXPECT_GT(metric(r, "max_dwell_force_s"), metric(r, "max_dwell_torque_s"));
}

TEST(Se3Scenarios, FtsmcSettlesNoLaterThanPtcItem12) {
  const RunResult f = run("se3-ftsmc", {{"companion", "skip"}});
  const RunResult& p = ptc_state1();
  EXPECT_LE(metric(f, "settle_pos_s"), metric(p, "settle_pos_s"));
  EXPECT_NEAR(metric(f, "settle_pos_s"), 50.8, 10.0);          // PROTO 50.8 s
  EXPECT_NEAR(metric(f, "settle_att_s_band001"), 23.6, 10.0);  // PROTO 23.6 s (0.01 deg band)
  // PROTO: about twice the transmissions of the BsPdTC (6416); no bound estimate.
  EXPECT_GT(metric(f, "transmissions"), 1.5 * metric(p, "transmissions"));
  EXPECT_FALSE(f.has_metric("disturbance_bound_est_final"));
  EXPECT_EQ(metric(f, "nonok_steps"), 0.0);
}

// The BsPdTC companion of se3-ftsmc (same state, Table 1 gains, T = 120 s) gives the paper's
// accuracy comparison: the FTSMC's steady errors are ~8x (attitude) and ~3.6x (position) lower,
// the reverse of the paper's conclusion 4.
TEST(Se3Scenarios, FtsmcCompanionPaperVerdictsItem12) {
  const RunResult f = run("se3-ftsmc");
  const RunResult& p = ptc_state1();
  EXPECT_EQ(metric(f, "ptc_settle_pos_s"), metric(p, "settle_pos_s"));  // the companion is se3-ptc's run
  EXPECT_EQ(metric(f, "ptc_transmissions"), metric(p, "transmissions"));
  EXPECT_GT(metric(p, "att_err_ss_deg"), 4.0 * metric(f, "att_err_ss_deg"));
  EXPECT_GT(metric(p, "pos_err_ss_m"), 2.0 * metric(f, "pos_err_ss_m"));
  expect_verdict(f, "BsPdTC steady errors below the FTSMC's", PaperVerdict::not_reproduced);
  expect_verdict(f, "A.9-12 FTSMC position settles no later", PaperVerdict::reproduced);
  expect_verdict(f, "FTSMC steady errors and settling", PaperVerdict::reproduced);  // below 4.77e-3 deg ...
  expect_no_verdict(f, "A.9-12 FTSMC from state 4 exceeds");                      // state 1 run
  expect_no_verdict(f, "A.9-9 dwell times");  // the paper gives the BsPdTC's only
  expect_verdict_fields_consistent(f);
  expect_claims_hold(f);  // 12 (first part), the PROTO transmission check, the actuator check
  // Without the companion the comparison is not computed, so it has no verdict.
  const RunResult skip = run("se3-ftsmc", {{"companion", "skip"}});
  expect_no_verdict(skip, "BsPdTC steady errors below the FTSMC's");
  expect_no_verdict(skip, "A.9-12 FTSMC position settles no later");
  // State 4: the FTSMC settles inside 120 s, against the paper's "exceeds" (127.6 s).
  const RunResult f4 = run("se3-ftsmc", {{"initial_state", "4"}, {"companion", "skip"}});
  EXPECT_NEAR(metric(f4, "settle_pos_s"), 105.8, 10.0);  // PROTO 105.8 s
  expect_verdict(f4, "A.9-12 FTSMC from state 4 exceeds", PaperVerdict::not_reproduced);
  expect_claims_hold(f4);
}

TEST(Se3Scenarios, WithoutQuantizerMoreTransmissions) {
  const RunResult r = run("se3-ptc", {{"quantize", "0"}});
  // Not the paper's conditions: no claim gets a paper verdict.
  for (const Claim& c : r.claims) EXPECT_FALSE(c.paper_verdict.has_value()) << c.claim;
  expect_verdict_fields_consistent(r);
  EXPECT_GT(metric(r, "transmissions"), metric(ptc_state1(), "transmissions"));
  EXPECT_LE(metric(r, "transmissions"), 9600.0);
  EXPECT_LT(metric(r, "settle_pos_s"), 120.0);
  EXPECT_LE(metric(r, "force_max_N"), 5.0);
}

TEST(Se3Scenarios, NegativeUncertaintyStillSettles) {
  const RunResult r = run("se3-ptc", {{"uncertainty_sign", "-1"}});
  EXPECT_LT(metric(r, "settle_pos_s"), 120.0);
  EXPECT_LT(metric(r, "settle_att_s"), 120.0);
  EXPECT_LT(metric(r, "pos_err_ss_m"), 1e-4);
  EXPECT_EQ(metric(r, "nonok_steps"), 0.0);
}

TEST(Se3Scenarios, CvodeTruthMatchesRk4CrossCheck) {
  const RunResult k = run("se3-ptc", {{"integrator", "rk4"}});
  const RunResult& c = ptc_state1();
  EXPECT_NEAR(metric(k, "settle_att_s"), metric(c, "settle_att_s"), 0.5);
  EXPECT_NEAR(metric(k, "settle_pos_s"), metric(c, "settle_pos_s"), 0.5);
  EXPECT_NEAR(metric(k, "att_err_ss_deg"), metric(c, "att_err_ss_deg"), 0.05 * metric(c, "att_err_ss_deg"));
  EXPECT_NEAR(metric(k, "pos_err_ss_m"), metric(c, "pos_err_ss_m"), 0.05 * metric(c, "pos_err_ss_m"));
}

TEST(Se3Scenarios, BadOptionsAreParamErrors) {
  EXPECT_THROW(run("se3-ptc", {{"initial_state", "5"}}), adcs::sim::ParamError);
  EXPECT_THROW(run("se3-ptc", {{"quantize", "2"}}), adcs::sim::ParamError);
  EXPECT_THROW(run("se3-ftsmc", {{"uncertainty_sign", "0"}}), adcs::sim::ParamError);
}
const adcs::sim::Claim* claim_of(const RunResult& r, const char* prefix) {
  const adcs::sim::Claim* c = adcs::sim::test::find_claim(r, prefix);
  EXPECT_NE(c, nullptr) << prefix;
  return c;
}

// Issue 19: both laws in float (plant in double, `--set scalar=float`). What holds and what does
// not, and why (tools/float-vs-double.py gives the whole table, docs/TARGET.md):
// - attitude: settling, steady attitude and rate errors as in double (to ~5 %), every attitude
//   criterion holds; the laws never fail a tick and stay within the actuator limits;
// - position: the law reads R − R_d from two ECI positions of ~6.8e6 m rounded to float (0.5 m
//   ulp) and v_e from inertial velocities of ~7.7 km/s (4.9e-4 m/s ulp). The orbital motion
//   dithers that rounding from tick to tick and the loop averages it, so the steady position error
//   is mm-level (2-6 mm), not 0.5 m, but 20-60x the 1e-4 m band of spec A.9: the position
//   criteria fail in float, and the test says so, so a change that fixes or worsens it is seen.
TEST(Se3Scenarios, FloatLawsKeepTheAttitudeClaimsAndLoseThePositionBandToFloatEci) {
  const RunResult ptc_f = run("se3-ptc", {{"scalar", "float"}});
  for (const char* name : {"se3-ptc", "se3-ftsmc"}) {
    SCOPED_TRACE(name);
    const bool ptc = std::string(name) == "se3-ptc";
    const RunResult d = ptc ? ptc_state1() : run(name);
    const RunResult f = ptc ? ptc_f : run(name, {{"scalar", "float"}});
    EXPECT_EQ(metric(f, "nonok_steps"), 0.0);
    EXPECT_LE(metric(f, "torque_max_Nm"), 0.5);
    EXPECT_LE(metric(f, "force_max_N"), 5.0);
    EXPECT_NEAR(metric(f, "settle_att_s"), metric(d, "settle_att_s"), 1.0);
    EXPECT_NEAR(metric(f, "att_err_ss_deg"), metric(d, "att_err_ss_deg"), 0.1 * metric(d, "att_err_ss_deg"));
    EXPECT_NEAR(metric(f, "rate_err_ss_deg_s"), metric(d, "rate_err_ss_deg_s"), 0.1 * metric(d, "rate_err_ss_deg_s"));
    // Position: mm-level in float (measured 2.0 mm BsPdTC, 6.0 mm FTSMC), µm-level in double.
    EXPECT_GT(metric(f, "pos_err_ss_m"), 1e-4);
    EXPECT_LT(metric(f, "pos_err_ss_m"), 2e-2);
    EXPECT_LT(metric(d, "pos_err_ss_m"), 1e-4);
    EXPECT_LT(metric(f, "vel_err_ss_m_s"), 2e-2);
    const adcs::sim::Claim* limits = claim_of(f, "commands within the actuator limits");
    if (limits && limits->holds) EXPECT_TRUE(*limits->holds);
  }
  const adcs::sim::Claim* att = claim_of(ptc_f, "A.9-3 steady attitude error");
  const adcs::sim::Claim* pos = claim_of(ptc_f, "A.9-4 steady position error");
  ASSERT_TRUE(att && pos && att->holds && pos->holds);
  EXPECT_TRUE(*att->holds);
  EXPECT_FALSE(*pos->holds);
}

}  // namespace

using namespace ADCS_UNITY_ID;  // as an anonymous namespace would (CMakeLists.txt, adcs_unity)
