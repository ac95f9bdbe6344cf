// Seed 003 checklist (spec §A.9) end to end through the se3-ptc / se3-ftsmc scenarios. Values are
// pinned to the spec's prototype (PROTO, Appendix C.3) with the spec's tolerances: ±15 %, settling
// times ±10 s; hard requirements t_s(β) < T, t_s(β) increasing in T and N_tx ≤ 3072. Each 200 s run
// takes ~0.3 s; the state-1 BsPdTC run is shared.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "scenario_test_util.hpp"

namespace {
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
    }
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

TEST(Se3Scenarios, WithoutQuantizerMoreTransmissions) {
  const RunResult r = run("se3-ptc", {{"quantize", "0"}});
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
}  // namespace
