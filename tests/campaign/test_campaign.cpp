// Monte Carlo campaigns (src/campaign/campaign.hpp, finalize.hpp): the tables do not depend on
// --jobs, on the shard split or on a kill and --resume; failures are recorded and the campaign
// goes on; merge refuses logs that do not make one campaign.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

#include "campaign/campaign.hpp"
#include "campaign/finalize.hpp"
#include "campaign_test_scenario.hpp"

namespace adcs::sim::campaign {
namespace ADCS_UNITY_ID {

namespace fs = std::filesystem;

std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

fs::path fresh_dir(const std::string& name) {
  const fs::path d = fs::temp_directory_path() / ("adcs_campaign_" + name + "_" + std::to_string(::getpid()));
  fs::remove_all(d);
  fs::create_directories(d);
  return d;
}

class Campaign : public ::testing::Test {
 protected:
  test::DecayScenario scenario;
  CampaignPlan plan() {
    CampaignPlan p;
    p.scenario = &scenario;
    p.name = "decay";
    p.run_target = "decay";
    p.source_id = "registered";
    scenario.declare(p.params);
    p.runs = 24;
    p.seed0 = 5;
    p.dispersions = {parse_dispersion("gain=uniform(0.2, 2)"), parse_dispersion("spacecraft.J_kgm2=inertia(0.1, 1)"),
                     parse_dispersion("bias=normal(0, 0.001)")};
    p.series = {"err"};
    return p;
  }
  static std::string outputs(const fs::path& d) {
    return slurp(d / "decay-montecarlo.csv") + slurp(d / "decay-montecarlo.json") + slurp(d / "decay-montecarlo-series.h5");
  }
};

TEST_F(Campaign, TablesDoNotDependOnJobs) {
  const fs::path a = fresh_dir("jobs1"), b = fresh_dir("jobs3");
  ExecOptions e;
  e.out_dir = a;
  const CampaignCounts ca = run_campaign(plan(), e);
  EXPECT_EQ(ca.ok, 24u);
  e.out_dir = b;
  e.jobs = 3;
  run_campaign(plan(), e);
  EXPECT_TRUE(outputs(a) == outputs(b));  // (not EXPECT_EQ: the HDF5 bytes would flood the log)
  const std::string csv = slurp(a / "decay-montecarlo.csv");
  EXPECT_EQ(csv.rfind("run,gain,spacecraft.J_kgm2[0][0]", 0), 0u) << csv.substr(0, 200);
  EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 25);
  const Json j = Json::parse(slurp(a / "decay-montecarlo.json"));
  EXPECT_EQ(j["counts"]["ok"], 24);
  EXPECT_EQ(j["metrics"]["err_final"]["count"], 24);
  EXPECT_TRUE(j["metrics"]["err_final"].contains("p99"));
  EXPECT_EQ(j["worst_runs"]["metric"], "err_final");
  EXPECT_EQ(j["worst_runs"]["runs"].size(), 5u);
  EXPECT_NE(j["worst_runs"]["runs"][0]["command"].get<std::string>().find("adcs-sim run decay --seed "), std::string::npos);
  ASSERT_EQ(j["claims"].size(), 2u);
  EXPECT_EQ(j["claims"][0]["held"].get<int>() + j["claims"][0]["failed"].get<int>(), 24);
}

TEST_F(Campaign, MergedShardsEqualTheUnsplitCampaignByteForByte) {
  const fs::path whole = fresh_dir("whole"), shards = fresh_dir("shards"), merged = fresh_dir("merged");
  ExecOptions e;
  e.out_dir = whole;
  run_campaign(plan(), e);
  for (std::uint64_t i = 0; i < 3; ++i) {
    ExecOptions s;
    s.out_dir = shards;
    s.shard_index = i;
    s.shard_count = 3;
    s.jobs = 2;
    run_campaign(plan(), s);
  }
  EXPECT_FALSE(fs::exists(shards / "decay-montecarlo.csv"));  // a shard writes only its log
  finalize_from_dirs({shards}, merged);
  EXPECT_TRUE(outputs(whole) == outputs(merged));
}

TEST_F(Campaign, ResumeAfterAKillRerunsNothingAndLosesNothing) {
  const fs::path whole = fresh_dir("ref"), killed = fresh_dir("killed");
  ExecOptions e;
  e.out_dir = whole;
  run_campaign(plan(), e);
  // A kill after 10 runs, in the middle of writing the 11th row: 10 rows and a torn line.
  const CampaignPlan p = plan();
  {
    LogHeader h;
    h.identity = campaign_identity(p);
    h.campaign_id = campaign_id_of(h.identity);
    LogWriter log((killed / log_file_name("decay", 0, 1)).string(), h);
    SeriesWriter series((killed / series_file_name("decay", 0, 1)).string(), false);
    for (std::uint64_t k = 0; k < 10; ++k) {
      SeriesRecord s;
      const RunRow r = execute_run(p, k, &s);
      series.append(s);
      log.append(r);
    }
  }
  std::ofstream((killed / log_file_name("decay", 0, 1)).string(), std::ios::app) << "{\"run\": 10, \"se";
  ExecOptions r;
  r.out_dir = killed;
  EXPECT_THROW(run_campaign(plan(), r), ParamError);  // an existing log needs --resume
  r.resume = true;
  scenario.runs = 0;
  const CampaignCounts c = run_campaign(plan(), r);
  EXPECT_EQ(c.resumed, 10u);
  EXPECT_EQ(scenario.runs.load(), 14);  // only the missing runs
  EXPECT_TRUE(outputs(whole) == outputs(killed));
  // Resuming a finished campaign runs nothing and rewrites the same tables.
  scenario.runs = 0;
  run_campaign(plan(), r);
  EXPECT_EQ(scenario.runs.load(), 0);
  EXPECT_TRUE(outputs(whole) == outputs(killed));
  // Another campaign's log is refused.
  CampaignPlan other = plan();
  other.seed0 = 6;
  EXPECT_THROW(run_campaign(other, r), ParamError);
}

TEST_F(Campaign, FailedAndInvalidRunsAreRecordedAndTheCampaignGoesOn) {
  const fs::path d = fresh_dir("failures");
  CampaignPlan p = plan();
  p.dispersions = {parse_dispersion("gain=uniform(-50, 150)")};  // < 0: invalid; > 100: failed
  p.runs = 40;
  ExecOptions e;
  e.out_dir = d;
  e.jobs = 2;
  const CampaignCounts c = run_campaign(p, e);
  EXPECT_GT(c.invalid, 0u);
  EXPECT_GT(c.failed, 0u);
  EXPECT_EQ(c.ok + c.invalid + c.failed, 40u);
  const Json j = Json::parse(slurp(d / "decay-montecarlo.json"));
  EXPECT_EQ(j["counts"]["failed"].get<std::uint64_t>(), c.failed);
  ASSERT_FALSE(j["failed_runs"].empty());
  bool invalid_reason = false, failure_reason = false;
  for (const auto& f : j["failed_runs"]) {
    const std::string e = f["error"].get<std::string>();
    invalid_reason = invalid_reason || (f["status"] == "invalid" && e == "gain must be >= 0");
    failure_reason = failure_reason || (f["status"] == "failed" && e == "closed loop diverged (test)");
  }
  EXPECT_TRUE(invalid_reason && failure_reason);
  const std::string csv = slurp(d / "decay-montecarlo.csv");
  EXPECT_NE(csv.find(",invalid,"), std::string::npos);
  EXPECT_NE(csv.find(",failed,"), std::string::npos);
  // An unphysical drawn inertia is an invalid run with its reason, never fixed.
  p.dispersions = {parse_dispersion("spacecraft.J_kgm2=rel_normal(0.8)")};
  p.series.clear();
  const fs::path d2 = fresh_dir("unphysical");
  e.out_dir = d2;
  const CampaignCounts c2 = run_campaign(p, e);
  EXPECT_GT(c2.invalid, 0u);
  EXPECT_NE(slurp(d2 / "decay-montecarlo.csv").find("spacecraft.J_kgm2: drawn inertia"), std::string::npos);
}

TEST_F(Campaign, MergeRefusesWhatIsNotOneWholeCampaign) {
  const fs::path a = fresh_dir("mergeA"), b = fresh_dir("mergeB"), out = fresh_dir("mergeOut");
  ExecOptions s;
  s.shard_count = 2;
  s.out_dir = a;
  run_campaign(plan(), s);
  EXPECT_THROW(finalize_from_dirs({a}, out), ParamError);  // shard 1 of 2 missing
  CampaignPlan other = plan();
  other.seed0 = 99;
  s.shard_index = 1;
  s.out_dir = b;
  run_campaign(other, s);
  try {
    finalize_from_dirs({a, b}, out);
    FAIL();
  } catch (const ParamError& e) {
    EXPECT_NE(std::string(e.what()).find("different campaigns"), std::string::npos) << e.what();
  }
  EXPECT_TRUE(fs::is_empty(out));  // nothing written
  EXPECT_THROW(finalize_from_dirs({fresh_dir("empty")}, out), ParamError);
}

TEST_F(Campaign, RefusesBadPlansBeforeWritingAnything) {
  const fs::path d = fresh_dir("refused");
  ExecOptions e;
  e.out_dir = d;
  CampaignPlan p = plan();
  p.series = {"no_such_column"};
  EXPECT_THROW(run_campaign(p, e), ParamError);
  p = plan();
  p.rank_metric = "no_such_metric";
  EXPECT_THROW(run_campaign(p, e), ParamError);
  e.shard_index = 3;
  e.shard_count = 3;
  EXPECT_THROW(run_campaign(plan(), e), ParamError);
  EXPECT_TRUE(fs::is_empty(d));
  // The same with workers running the next runs while the first one decides (their rows are
  // held, then dropped): nothing written either.
  e = ExecOptions{};
  e.out_dir = d;
  e.jobs = 3;
  scenario.sleep_ms = 20;
  p = plan();
  p.series = {"no_such_column"};
  EXPECT_THROW(run_campaign(p, e), ParamError);
  p = plan();
  p.rank_metric = "no_such_metric";
  EXPECT_THROW(run_campaign(p, e), ParamError);
  // Nominal parameters the scenario refuses, without dispersions: a bad command line.
  p = plan();
  p.dispersions.clear();
  p.params.set("gain", "-1");
  try {
    run_campaign(p, e);
    FAIL();
  } catch (const ParamError& err) {
    EXPECT_EQ(std::string(err.what()), "gain must be >= 0");
  }
  EXPECT_TRUE(fs::is_empty(d));
}

TEST_F(Campaign, TheFirstRunRunsInThePoolNotAloneBeforeIt) {
  // It decides whether the campaign may run (a bad --series, --rank-by or nominal configuration
  // is refused), but not by running alone: with --jobs 2, runs 0 and 1 overlap.
  const fs::path a = fresh_dir("pool_j1"), b = fresh_dir("pool_j2");
  ExecOptions e;
  e.out_dir = a;
  run_campaign(plan(), e);
  EXPECT_EQ(scenario.max_in_flight.load(), 1);
  CampaignPlan p = plan();
  p.runs = 2;
  scenario.sleep_ms = 300;
  scenario.max_in_flight = 0;
  e.out_dir = b;
  e.jobs = 2;
  run_campaign(p, e);
  EXPECT_EQ(scenario.max_in_flight.load(), 2);
  // Many workers, many runs: the rows held while run 0 decided are all logged, once.
  scenario.sleep_ms = 5;
  const fs::path c = fresh_dir("pool_j4");
  e.out_dir = c;
  e.jobs = 4;
  run_campaign(plan(), e);
  EXPECT_TRUE(outputs(a) == outputs(c));
  EXPECT_EQ(read_log((c / log_file_name("decay", 0, 1)).string()).rows.size(), 24u);
}

TEST_F(Campaign, TablesAreTheRowsSortedByRunThoughNotHeldInMemory) {
  // finalize reads the rows back one at a time; what it writes must be what the rows, all in
  // memory and sorted by run, give: metrics in order of first appearance (one that appears only
  // in later runs, at any position), the first failing runs of each claim, the worst runs with
  // ties in run order (J_trace is the same in every run here), the first failed runs.
  scenario.extra_metrics = true;
  CampaignPlan p = plan();
  p.runs = 60;
  p.dispersions = {parse_dispersion("gain=uniform(-0.3, 2.5)")};  // < 0: invalid
  p.rank_metric = "J_trace";
  p.series.clear();
  const fs::path d = fresh_dir("streamed");
  ExecOptions e;
  e.out_dir = d;
  e.jobs = 3;
  run_campaign(p, e);
  const std::string log_path = (d / log_file_name("decay", 0, 1)).string();
  LogContents all = read_log(log_path);
  std::vector<RunRow>& rows = all.rows;
  ASSERT_EQ(rows.size(), 60u);
  // scan_log sees the same rows, and read_row_at reads each back from where scan_log found it.
  std::size_t scanned = 0;
  scan_log(log_path, [&](RunRow&& r, const RowSpan& span) {
    EXPECT_EQ(to_json(r).dump(), to_json(rows[scanned]).dump());
    EXPECT_EQ(to_json(read_row_at(log_path, span)).dump(), to_json(rows[scanned]).dump());
    ++scanned;
  });
  EXPECT_EQ(scanned, 60u);
  std::sort(rows.begin(), rows.end(), [](const RunRow& a, const RunRow& b) { return a.run < b.run; });

  std::vector<std::string> metric_names;
  std::set<std::string> seen;
  for (const RunRow& r : rows)
    for (const auto& m : r.metrics)
      if (seen.insert(m.first).second) metric_names.push_back(m.first);
  ASSERT_TRUE(seen.count("fast") && seen.count("slow"));
  std::string header = "run,gain";
  for (const auto& m : metric_names) header += "," + m;
  header += ",status,seed,error\n";
  const std::string csv = slurp(d / "decay-montecarlo.csv");
  EXPECT_EQ(csv.substr(0, csv.find('\n') + 1), header);

  const Json j = Json::parse(slurp(d / "decay-montecarlo.json"));
  Json metrics_order = Json::array();
  for (const auto& [k, v] : j["metrics"].items()) metrics_order.push_back(k);
  EXPECT_EQ(metrics_order, Json(metric_names));
  std::vector<std::uint64_t> failing;
  for (const RunRow& r : rows)
    if (failing.size() < 3 && r.claims.size() == 2 && r.claims[0].holds == false) failing.push_back(r.run);
  ASSERT_EQ(failing.size(), 3u);
  ASSERT_EQ(j["claims"][0]["failing_runs"].size(), 3u);
  for (std::size_t i = 0; i < 3; ++i) {
    EXPECT_EQ(j["claims"][0]["failing_runs"][i]["run"], failing[i]);
    EXPECT_EQ(j["claims"][0]["failing_runs"][i]["command"], rerun_command(all.header.identity, rows[failing[i]]));
  }
  std::vector<std::uint64_t> ok_runs, not_ok;
  for (const RunRow& r : rows) (r.status == RunStatus::ok ? ok_runs : not_ok).push_back(r.run);
  ASSERT_GE(ok_runs.size(), 5u);
  ASSERT_FALSE(not_ok.empty());
  ASSERT_EQ(j["worst_runs"]["runs"].size(), 5u);
  for (std::size_t i = 0; i < 5; ++i) EXPECT_EQ(j["worst_runs"]["runs"][i]["run"], ok_runs[i]);  // all tie
  ASSERT_EQ(j["failed_runs"].size(), std::min<std::size_t>(20, not_ok.size()));
  for (std::size_t i = 0; i < j["failed_runs"].size(); ++i) EXPECT_EQ(j["failed_runs"][i]["run"], not_ok[i]);
}

TEST_F(Campaign, ARunIsReproducedAloneFromItsIndex) {
  const CampaignPlan p = plan();
  const RunRow a = execute_run(p, 17, nullptr), b = execute_run(p, 17, nullptr);
  EXPECT_EQ(to_json(a).dump(), to_json(b).dump());
  EXPECT_NE(to_json(execute_run(p, 16, nullptr)).dump(), to_json(a).dump());
  // The rerun command's --set values, applied as a user would, give the same metrics.
  ParamSet ps = p.params;
  for (const std::string& s : a.drawn_sets) ps.set(s.substr(0, s.find('=')), s.substr(s.find('=') + 1));
  RunContext ctx;
  ctx.seed = a.seed;
  const RunResult r = scenario.run(ps, ctx);
  EXPECT_EQ(r.metrics, a.metrics);
}

}  // namespace
using namespace ADCS_UNITY_ID;  // as an anonymous namespace would (CMakeLists.txt, adcs_unity)
}  // namespace adcs::sim::campaign
