// adcs-sim commands in-process with fake scenarios: outputs, exit statuses, all-or-nothing.
#include <gtest/gtest.h>

#include <algorithm>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include <unistd.h>

#include "cli/commands.hpp"
#include "cli_test_fixture.hpp"

namespace adcs::sim::cli {
namespace ADCS_UNITY_ID {
namespace fs = std::filesystem;

enum class Mode { ok, throws, no_csv, param_error, partial, dup_metric, chatty };

class Fake final : public Scenario {
 public:
  Fake(std::string name, Mode mode) : name_(std::move(name)), mode_(mode) {}
  std::string name() const override { return name_; }
  std::string description() const override { return "fake \"scenario\""; }
  void declare(ParamSet& p) const override {
    p.number("duration_s", 1.0, "s", "assumed: test");
    p.number("control_period_s", 0.5, "s", "assumed: test");
    p.vector("v", {1.0, 2.0}, "m", "paper Table 9");
    p.name("method", "adams", {"adams", "bdf"}, "assumed: test");
  }
  RunResult run(const ParamSet& p, const RunContext& ctx) const override {
    if (mode_ == Mode::throws) throw std::runtime_error("CVode failed\nat t = 1");
    if (mode_ == Mode::param_error) throw ParamError("parameter 'v' must be positive");
    if (mode_ == Mode::chatty && !ctx.quiet) std::cout << "chatter\n";
    if (!ctx.csv_path.empty() && mode_ != Mode::no_csv) {
      std::ofstream f(ctx.csv_path);
      f << "# units: t [s], x [m]\nt,x\n0,1\n";
    }
    if (mode_ == Mode::partial) throw std::runtime_error("diverged");
    RunResult r;
    r.metrics = {{"seed_metric", static_cast<double>(ctx.seed)},
                 {"duration", p.get_number("duration_s")},
                 {"v1", p.get_vector("v")[1]},
                 {"bad", std::nan("")}};
    if (mode_ == Mode::dup_metric) r.metrics.push_back({"v1", 0.0});
    r.claims.push_back({"check", "c", "1", "1", true});
    r.plots.push_back({"f.png", "t", "t", {"x"}, "m", true});
    return r;
  }

 private:
  std::string name_;
  Mode mode_;
};

class CliTest : public adcs::sim::test::CliFixture {
 protected:
  void SetUp() override {
    make_root("adcs_cli_test");
    for (const Fake& f : fakes_) catalog_.scenarios.push_back(&f);
  }
  std::vector<std::string> files(const std::string& sub = "out") const {
    std::vector<std::string> v;
    if (!fs::exists(root_ / sub)) return v;
    for (const auto& e : fs::directory_iterator(root_ / sub)) v.push_back(e.path().filename());
    std::sort(v.begin(), v.end());
    return v;
  }
  std::string last_line() const {
    std::string s = out_.str(), line, last;
    std::istringstream in(s);
    while (std::getline(in, line)) last = line;
    return last;
  }
  int err_lines() const {
    const std::string s = err_.str();
    return static_cast<int>(std::count(s.begin(), s.end(), '\n'));
  }
  const std::vector<Fake> fakes_{{"fake", Mode::ok},          {"throws", Mode::throws},
                                 {"no-csv", Mode::no_csv},     {"param-error", Mode::param_error},
                                 {"partial", Mode::partial},   {"dup-metric", Mode::dup_metric},
                                 {"chatty", Mode::chatty}};
};

TEST_F(CliTest, ListAndHelp) {
  EXPECT_EQ(cli({"list"}), kExitOk);
  EXPECT_EQ(out_.str(), "fake\nthrows\nno-csv\nparam-error\npartial\ndup-metric\nchatty\n");
  EXPECT_EQ(cli({"help"}), kExitOk);
  EXPECT_NE(out_.str().find("usage: adcs-sim"), std::string::npos);
  EXPECT_EQ(cli({"--help"}), kExitOk);
  EXPECT_EQ(cli({"run", "--help"}), kExitOk);
  EXPECT_EQ(cli({}), kExitUsage);
  EXPECT_EQ(err_lines(), 1);
  EXPECT_EQ(cli({"frobnicate"}), kExitUsage);
  EXPECT_EQ(cli({"list", "extra"}), kExitUsage);
}

TEST_F(CliTest, Describe) {
  EXPECT_EQ(cli({"describe", "fake"}), kExitOk);
  const std::string s = out_.str();
  for (const char* want : {"duration_s", "= 1 [s]", "paper Table 9", "[1, 2] [m]",
                           "one of: adams, bdf", "a vector of 2 numbers"})
    EXPECT_NE(s.find(want), std::string::npos) << want << "\n" << s;
  EXPECT_EQ(cli({"describe", "nope"}), kExitUsage);
}

TEST_F(CliTest, RunWritesCsvJsonAndSummaryLine) {
  ASSERT_EQ(cli({"run", "fake", "--set", "duration_s=2", "--set=v=[3, 4]", "--seed", "7",
                 "--out", dir()}),
            kExitOk)
      << err_.str();
  EXPECT_EQ(err_.str(), "");
  EXPECT_EQ(files(), (std::vector<std::string>{"fake.csv", "fake.json"}));
  EXPECT_EQ(last_line(),
            R"({"scenario": "fake", "seed": 7, "metrics": {"seed_metric": 7, "duration": 2, "v1": 4, "bad": null}})");
  EXPECT_EQ(slurp(root_ / "out" / "fake.csv"), "# units: t [s], x [m]\nt,x\n0,1\n");
  const std::string j = slurp(root_ / "out" / "fake.json");
  for (const char* want :
       {R"("scenario": "fake")", R"("seed": 7)", R"("description": "fake \"scenario\"")",
        R"j("duration_s": {"value": 2, "unit": "s", "source": "command line (--set)", "default": 1, "default_source": "assumed: test"})j",
        R"("control_period_s": {"value": 0.5, "unit": "s", "source": "assumed: test"})",
        R"("v": {"value": [3, 4], "unit": "m")",
        R"("method": {"value": "adams", "unit": "", "source": "assumed: test"})",
        R"("bad": null)",
        R"({"kind": "check", "claim": "c", "paper_value": "1", "ours": "1", "paper_verdict": null, "criterion": "", "criterion_holds": true, "holds": true})",
        R"({"file": "f.png", "title": "t", "x": "t", "y": ["x"], "ylabel": "m", "logy": true})",
        R"("csv": "fake.csv")"})
    EXPECT_NE(j.find(want), std::string::npos) << want << "\n" << j;
}

TEST_F(CliTest, RunCreatesNestedOutDirAndOverwrites) {
  ASSERT_EQ(cli({"run", "fake", "--out", dir("a/b/c")}), kExitOk) << err_.str();
  EXPECT_EQ(files("a/b/c").size(), 2u);
  EXPECT_NE(last_line().find(R"("seed": 0)"), std::string::npos);  // default seed
  ASSERT_EQ(cli({"run", "fake", "--out", dir("a/b/c"), "--seed", "3"}), kExitOk);
  EXPECT_EQ(files("a/b/c").size(), 2u);
  EXPECT_NE(slurp(root_ / "a/b/c/fake.json").find(R"("seed": 3)"), std::string::npos);
}

TEST_F(CliTest, ScenarioChatterComesBeforeTheSummaryLine) {
  ASSERT_EQ(cli({"run", "chatty", "--out", dir()}), kExitOk);
  EXPECT_EQ(last_line().rfind(R"({"scenario": "chatty")", 0), 0u);
}

TEST_F(CliTest, UsageErrorsExit2WithOneLineAndNoFiles) {
  const std::vector<std::vector<std::string>> bad = {
      {"run", "nope"},
      {"run"},
      {"run", "fake", "fake"},
      {"run", "fake", "--set", "nokey=1"},
      {"run", "fake", "--set", "duration_s=abc"},
      {"run", "fake", "--set", "duration_s=1,2"},
      {"run", "fake", "--set", "duration_s=nan"},
      {"run", "fake", "--set", "duration_s=inf"},
      {"run", "fake", "--set", "duration_s=1x"},
      {"run", "fake", "--set", "duration_s="},
      {"run", "fake", "--set", "duration_s=0"},
      {"run", "fake", "--set", "control_period_s=-1"},
      {"run", "fake", "--set", "v=[1,2"},
      {"run", "fake", "--set", "v=[1,2,3]"},
      {"run", "fake", "--set", "v=[1,,2]"},
      {"run", "fake", "--set", "v=[[1,2]]"},
      {"run", "fake", "--set", "method=rk4"},
      {"run", "fake", "--set", "method=1"},
      {"run", "fake", "--set", "duration_s"},
      {"run", "fake", "--set", "=1"},
      {"run", "fake", "--set"},
      {"run", "fake", "--set", "duration_s=1", "--set", "duration_s=2"},
      {"run", "fake", "--seed", "1", "--seed", "2"},
      {"run", "fake", "--seed", "-1"},
      {"run", "fake", "--seed", "1.5"},
      {"run", "fake", "--seed", "99999999999999999999999"},
      {"run", "fake", "--seed"},
      {"run", "fake", "--out", "x", "--out", "y"},
      {"run", "fake", "--bogus"},
      {"run", "fake", "--runs", "3"},
      {"run", "param-error"},
      {"montecarlo", "fake"},
      {"montecarlo", "fake", "--runs", "0"},
      {"montecarlo", "fake", "--runs", "x"},
      {"montecarlo", "fake", "--runs", "2", "--seed", "1"},
      {"montecarlo", "fake", "--runs", "2", "--set", "v=1"},
      {"montecarlo", "nope", "--runs", "2"},
  };
  for (auto args : bad) {
    const bool has_out = std::find(args.begin(), args.end(), "--out") != args.end();
    if (!has_out) {
      args.push_back("--out");
      args.push_back(dir());
    }
    std::string joined;
    for (const auto& a : args) joined += a + " ";
    EXPECT_EQ(cli(args), kExitUsage) << joined;
    EXPECT_EQ(err_lines(), 1) << joined << "\n" << err_.str();
    EXPECT_EQ(err_.str().rfind("adcs-sim: error: ", 0), 0u) << err_.str();
    EXPECT_FALSE(fs::exists(root_ / "out")) << joined;  // not even the directory
    EXPECT_FALSE(fs::exists("x") || fs::exists("y"));
  }
}

TEST_F(CliTest, RunFailuresExit1WithNoFiles) {
  fs::create_directories(root_ / "out");
  for (const char* name : {"throws", "no-csv", "partial", "dup-metric"}) {
    EXPECT_EQ(cli({"run", name, "--out", dir()}), kExitFailure) << name;
    EXPECT_EQ(err_lines(), 1) << err_.str();
    EXPECT_TRUE(files().empty()) << name << ": " << files().front();
  }
  EXPECT_NE(err_.str().find("dup-metric"), std::string::npos);
  EXPECT_EQ(cli({"run", "throws", "--out", dir()}), kExitFailure);
  EXPECT_NE(err_.str().find("CVode failed at t = 1"), std::string::npos) << err_.str();
  // A directory created for the failed run is removed again.
  EXPECT_EQ(cli({"run", "partial", "--out", dir("new/sub")}), kExitFailure);
  EXPECT_FALSE(fs::exists(root_ / "new"));
  // An existing output of an earlier run is left untouched.
  ASSERT_EQ(cli({"run", "fake", "--out", dir()}), kExitOk);
  const std::string before = slurp(root_ / "out" / "fake.json");
  EXPECT_EQ(cli({"run", "fake", "--set", "v=[1]", "--out", dir()}), kExitUsage);
  EXPECT_EQ(slurp(root_ / "out" / "fake.json"), before);
  EXPECT_EQ(files().size(), 2u);
}

TEST_F(CliTest, OutIsAFile) {
  std::ofstream(root_ / "file") << "x";
  EXPECT_EQ(cli({"run", "fake", "--out", dir("file")}), kExitFailure);
  EXPECT_EQ(err_lines(), 1);
}

TEST_F(CliTest, MonteCarlo) {
  ASSERT_EQ(cli({"montecarlo", "fake", "--runs", "4", "--seed0", "10", "--out", dir(), "--set",
                 "duration_s=3", "--jobs", "2"}),
            kExitOk)
      << err_.str();
  // The tables, and the campaign's durable log (docs/CAMPAIGNS.md).
  EXPECT_EQ(files(), (std::vector<std::string>{"fake-montecarlo.csv", "fake-montecarlo.json",
                                                "fake-montecarlo.log.jsonl"}));
  // One row per run, sorted by run index: run, the drawn values (none here), the metrics,
  // status, seed, error. Run k's seed is drawn from (seed0, k).
  const std::string csv = slurp(root_ / "out" / "fake-montecarlo.csv");
  EXPECT_EQ(csv.rfind("run,seed_metric,duration,v1,bad,status,seed,error\n0,", 0), 0u) << csv;
  EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 5);
  EXPECT_NE(csv.find("\n3,"), std::string::npos) << csv;
  EXPECT_NE(csv.find(",3,2,nan,ok,"), std::string::npos) << csv;
  const std::string line = last_line();
  EXPECT_EQ(line.rfind(R"({"scenario": "fake", "runs": 4, "seed0": 10, "counts": {"ok": 4, "invalid": 0, "failed": 0}, "metrics": {)", 0), 0u) << line;
  EXPECT_NE(line.find(R"("duration": {"min": 3, "median": 3, "max": 3})"), std::string::npos) << line;
  EXPECT_NE(line.find(R"("bad": {"min": null, "median": null, "max": null, "nonfinite": 4})"), std::string::npos) << line;
  const std::string e = err_.str();
  EXPECT_NE(e.find("[4/4 runs] 0 invalid, 0 failed"), std::string::npos) << e;
  const std::string j = slurp(root_ / "out" / "fake-montecarlo.json");
  for (const char* want : {R"("runs": 4)", R"("seed0": 10)", R"("parameters": {)", R"("csv": "fake-montecarlo.csv")",
                           R"("p99": )", R"("worst_runs": {)", "adcs-sim run fake --seed "})
    EXPECT_NE(j.find(want), std::string::npos) << want << "\n" << j;
  // No per-run time series.
  EXPECT_FALSE(fs::exists(root_ / "out" / "fake.csv"));
  // The same campaign again in that directory needs --resume (the log is kept).
  EXPECT_EQ(cli({"montecarlo", "fake", "--runs", "4", "--seed0", "10", "--out", dir(), "--set", "duration_s=3"}), kExitUsage);
  EXPECT_EQ(cli({"montecarlo", "fake", "--runs", "4", "--seed0", "10", "--out", dir(), "--set", "duration_s=3",
                 "--resume", "--jobs", "1"}),
            kExitOk);
  EXPECT_EQ(slurp(root_ / "out" / "fake-montecarlo.csv"), csv);
}

TEST_F(CliTest, MonteCarloDefaultSeed0AndFailure) {
  ASSERT_EQ(cli({"montecarlo", "fake", "--runs=1", "--out=" + dir()}), kExitOk) << err_.str();
  EXPECT_NE(last_line().find(R"("seed0": 1)"), std::string::npos);
  fs::remove_all(root_ / "out");
  // A run that fails is recorded with its error and the campaign goes on (issue 18).
  EXPECT_EQ(cli({"montecarlo", "throws", "--runs", "3", "--out", dir()}), kExitOk) << err_.str();
  EXPECT_NE(last_line().find(R"("counts": {"ok": 0, "invalid": 0, "failed": 3})"), std::string::npos) << last_line();
  const std::string csv = slurp(root_ / "out" / "throws-montecarlo.csv");
  EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 4);
  EXPECT_NE(csv.find(",failed,"), std::string::npos) << csv;
  // A bad dispersion or shard is refused before anything runs, with nothing written.
  fs::remove_all(root_ / "out");
  EXPECT_EQ(cli({"montecarlo", "fake", "--runs", "3", "--disperse", "v1=normal(0)", "--out", dir()}), kExitUsage);
  EXPECT_EQ(cli({"montecarlo", "fake", "--runs", "3", "--disperse", "nope=normal(0,1)", "--out", dir()}), kExitUsage);
  EXPECT_EQ(cli({"montecarlo", "fake", "--runs", "3", "--shard", "3/3", "--out", dir()}), kExitUsage);
  EXPECT_EQ(cli({"merge", dir()}), kExitUsage);
  EXPECT_FALSE(fs::exists(root_ / "out"));
}

TEST(CliOptions, Parse) {
  const Options o = parse_options(
      "run", {"--seed=5", "x", "--set", "a=[1, 2]", "--set=b=c=d", "--out", "o"});
  EXPECT_EQ(o.scenario, "x");
  EXPECT_EQ(*o.seed, 5u);
  ASSERT_EQ(o.sets.size(), 2u);
  EXPECT_EQ(o.sets[0], (std::pair<std::string, std::string>{"a", "[1, 2]"}));
  EXPECT_EQ(o.sets[1], (std::pair<std::string, std::string>{"b", "c=d"}));
  EXPECT_EQ(*o.out_dir, "o");
  EXPECT_EQ(parse_uint("n", "18446744073709551615"), 18446744073709551615ull);
  EXPECT_THROW(parse_uint("n", "18446744073709551616"), UsageError);
  EXPECT_THROW(parse_uint("n", "+1"), UsageError);
  EXPECT_THROW(parse_uint("n", ""), UsageError);
  EXPECT_EQ(one_line("a\nb\r\tc"), "a b  c");
}

}  // namespace
using namespace ADCS_UNITY_ID;  // as an anonymous namespace would (CMakeLists.txt, adcs_unity)
}  // namespace adcs::sim::cli
