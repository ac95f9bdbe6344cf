// Issue 15 items 5-6: the JSON holds every value used (--seed draws), derived values that make
// no sense are refused before running (exit 2, nothing written), --progress on stderr only.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <unistd.h>

#include "cli/commands.hpp"
#include "cli/progress.hpp"
#include "cli_test_fixture.hpp"
#include "scenarios/registry.hpp"

namespace adcs::sim::cli {
namespace ADCS_UNITY_ID {
namespace fs = std::filesystem;

//! Declares the keys the shared checks look at; reports a used value for a declared key and
//! for an undeclared one when seed != 0.
class TolFake final : public Scenario {
 public:
  std::string name() const override { return "tol"; }
  std::string description() const override { return "fake with tolerances"; }
  void declare(ParamSet& p) const override {
    p.number("duration_s", 10.0, "s", "assumed: test");
    p.number("control_period_s", 0.5, "s", "assumed: test");
    p.name("integrator", "adams", {"adams", "bdf", "rk4"}, "assumed: test");
    p.number("rtol", 1e-10, "-", "assumed: test");
    p.number("atol", 1e-12, "-", "assumed: test");
    p.number("rk4_step_s", 0.1, "s", "assumed: test");
    p.vector("x0", {0.0, 0.0}, "m", "assumed: test");
  }
  RunResult run(const ParamSet&, const RunContext& ctx) const override {
    if (!ctx.csv_path.empty()) std::ofstream(ctx.csv_path) << "# units: t [s]\nt\n0\n";
    RunResult r;
    r.metrics = {{"m", 1.0}};
    if (ctx.seed != 0) {
      r.used.push_back(UsedValue::vector("x0", {1.5, -2.0}, "m", "drawn from --seed"));
      r.used.push_back(UsedValue::number("n_steps", 20.0, "-", "derived: duration/period"));
    }
    return r;
  }
};

class CliRunChecks : public adcs::sim::test::CliFixture {
 protected:
  void SetUp() override {
    make_root("adcs_cli_checks");
    catalog_.scenarios.push_back(&fake_);
    for (const char* n : {"rigid-rw-mrp-pd", "rigid-rw-torquefree", "hybrid-adaptive", "dragfree-estimators"}) {
      const Scenario* s = find_scenario(n);
      ASSERT_NE(s, nullptr) << n;
      catalog_.scenarios.push_back(s);
    }
  }
  //! The "parameters" member of `key` in a pretty JSON written by adcs-sim (one line each).
  static std::string param_line(const std::string& json, const std::string& key) {
    const auto at = json.find("\n    \"" + key + "\": {");
    if (at == std::string::npos) return "";
    return json.substr(at + 1, json.find('\n', at + 1) - at - 1);
  }

  TolFake fake_;
};

TEST_F(CliRunChecks, RefusesDerivedValuesThatMakeNoSenseBeforeRunning) {
  struct Bad {
    std::vector<std::string> sets;
    std::string message;
  };
  const std::vector<Bad> bad = {
      {{"duration_s=1e300"},
       "duration_s / control_period_s = 1e+300 / 0.5 = 2e+300 control steps, more than the "
       "maximum 100000000 (lower duration_s or raise control_period_s)"},
      {{"duration_s=5.0000001e7"}, "control steps, more than the maximum 100000000"},
      {{"control_period_s=1e-300"}, "duration_s / control_period_s = 10 / 1e-300"},
      {{"duration_s=0"}, "parameter 'duration_s' must be > 0, got 0"},
      {{"duration_s=-1"}, "parameter 'duration_s' must be > 0, got -1"},
      {{"control_period_s=0"}, "parameter 'control_period_s' must be > 0, got 0"},
      {{"rtol=0"}, "parameter 'rtol' must be > 0 and < 1, got 0"},
      {{"rtol=-1e-9"}, "parameter 'rtol' must be > 0 and < 1, got -1e-09"},
      {{"rtol=1"}, "parameter 'rtol' must be > 0 and < 1, got 1"},
      {{"atol=-1"}, "parameter 'atol' must be > 0, got -1"},
      {{"atol=0"}, "parameter 'atol' must be > 0, got 0"},
      {{"rk4_step_s=0"}, "parameter 'rk4_step_s' must be > 0, got 0"},
      {{"integrator=rk4", "rk4_step_s=1e-8"},
       "duration_s / rk4_step_s = 10 / 1e-08 = 1000000000 RK4 steps, more than the maximum "
       "100000000 (lower duration_s or raise rk4_step_s)"},
  };
  for (const std::string cmd : {"run", "montecarlo"}) {
    for (const Bad& b : bad) {
      std::vector<std::string> args = {cmd, "tol", "--out", dir(), "--progress"};
      if (cmd == "montecarlo") args.insert(args.end(), {"--runs", "2"});
      std::string joined;
      for (const auto& s : b.sets) {
        args.insert(args.end(), {"--set", s});
        joined += s + " ";
      }
      EXPECT_EQ(cli(args), kExitUsage) << cmd << " " << joined;
      const std::string e = err_.str();
      EXPECT_EQ(e.rfind("adcs-sim: error: ", 0), 0u) << e;
      EXPECT_EQ(std::count(e.begin(), e.end(), '\n'), 1) << e;  // no progress line either
      EXPECT_NE(e.find(b.message), std::string::npos) << joined << "\n" << e;
      EXPECT_EQ(out_.str(), "");
      EXPECT_FALSE(fs::exists(root_ / "out")) << joined;
    }
  }
  // The same checks hold for the real scenarios (rtol/atol are declared by the rigid-rw ones).
  for (const char* set : {"duration_s=1e300", "rtol=0", "atol=-1"}) {
    EXPECT_EQ(cli({"run", "rigid-rw-mrp-pd", "--set", set, "--out", dir()}), kExitUsage) << set;
    EXPECT_FALSE(fs::exists(root_ / "out")) << set;
  }
}

TEST_F(CliRunChecks, AcceptsTheLimits) {
  ParamSet ps;
  fake_.declare(ps);
  ps.set("duration_s", "5e7");  // exactly 1e8 steps of 0.5 s
  EXPECT_NO_THROW(check_run_parameters(ps));
  ps.set("rk4_step_s", "1e-9");  // not used: integrator = adams
  EXPECT_NO_THROW(check_run_parameters(ps));
  ps.set("integrator", "rk4");
  EXPECT_THROW(check_run_parameters(ps), ParamError);
  ParamSet q;
  fake_.declare(q);
  q.set("rtol", "0.999");
  q.set("atol", "1e-300");
  EXPECT_NO_THROW(check_run_parameters(q));
  ASSERT_EQ(cli({"run", "tol", "--set", "duration_s=5e7", "--out", dir()}), kExitOk) << err_.str();
}

TEST_F(CliRunChecks, JsonHoldsTheUsedValues) {
  // seed 0: nothing drawn, the declared values as before.
  ASSERT_EQ(cli({"run", "tol", "--out", dir()}), kExitOk) << err_.str();
  std::string j = slurp(root_ / "out" / "tol.json");
  EXPECT_EQ(param_line(j, "x0"),
            R"(    "x0": {"value": [0, 0], "unit": "m", "source": "assumed: test"})");
  EXPECT_EQ(param_line(j, "n_steps"), "");
  // seed 3: the used value replaces the declared one, which is kept; undeclared ones follow.
  ASSERT_EQ(cli({"run", "tol", "--seed", "3", "--set", "x0=[7, 8]", "--out", dir()}), kExitOk);
  j = slurp(root_ / "out" / "tol.json");
  EXPECT_EQ(param_line(j, "x0"),
            R"j(    "x0": {"value": [1.5, -2], "unit": "m", "source": "drawn from --seed", )j"
            R"j("declared": [7, 8], "declared_source": "command line (--set)", "default": [0, 0], )j"
            R"j("default_source": "assumed: test"},)j");
  EXPECT_EQ(param_line(j, "n_steps"),
            R"(    "n_steps": {"value": 20, "unit": "-", "source": "derived: duration/period"})");
}

TEST_F(CliRunChecks, RigidRwSeedDrawIsInTheJson) {
  ASSERT_EQ(cli({"run", "rigid-rw-mrp-pd", "--seed", "3", "--set", "duration_s=1", "--out",
                 dir()}),
            kExitOk)
      << err_.str();
  const std::string j = slurp(root_ / "out" / "rigid-rw-mrp-pd.json");
  const std::string sigma = param_line(j, "sigma0_BN");
  EXPECT_EQ(sigma.find(R"("value": [0, 0, 0])"), std::string::npos) << sigma;
  EXPECT_NE(sigma.find(R"("source": "drawn from --seed 3: uniform over SO(3), short MRP set")"),
            std::string::npos)
      << sigma;
  EXPECT_NE(sigma.find(R"("declared": [0, 0, 0])"), std::string::npos) << sigma;
  const std::string omega = param_line(j, "omega0_BN_B");
  EXPECT_NE(omega.find(R"("source": "drawn from --seed 3: )"), std::string::npos) << omega;
  // The JSON value is the state the CSV starts from (row 1 after the units and header lines).
  std::istringstream csv(slurp(root_ / "out" / "rigid-rw-mrp-pd.csv"));
  std::string line;
  for (int i = 0; i < 3; ++i) std::getline(csv, line);
  std::vector<double> row;
  std::istringstream cells(line);
  for (std::string c; std::getline(cells, c, ',');) row.push_back(std::stod(c));
  ASSERT_GE(row.size(), 7u) << line;
  const std::string v = sigma.substr(sigma.find("[") + 1);
  std::istringstream vs(v);
  for (int i = 0; i < 3; ++i) {
    double x = 0.0;
    char sep = 0;
    vs >> x >> sep;
    EXPECT_DOUBLE_EQ(x, row[1 + static_cast<std::size_t>(i)]) << i << ": " << sigma;
  }
  // seed 0: as declared, no "declared" member.
  ASSERT_EQ(cli({"run", "rigid-rw-mrp-pd", "--set", "duration_s=1", "--out", dir()}), kExitOk);
  const std::string s0 = param_line(slurp(root_ / "out" / "rigid-rw-mrp-pd.json"), "sigma0_BN");
  EXPECT_EQ(s0.rfind(R"(    "sigma0_BN": {"value": [0, 0, 0], "unit": "-", "source": "initial MRP; )", 0),
            0u)
      << s0;
  EXPECT_EQ(s0.find("declared"), std::string::npos) << s0;
}

// Issue 15: every --seed draw and what it derives is in the JSON, for the VSCMG deviations and
// the drag-free noise streams as for the rigid-body initial state.
TEST_F(CliRunChecks, HybridAndDragFreeSeedDrawsAreInTheJson) {
  ASSERT_EQ(cli({"run", "hybrid-adaptive", "--seed", "3", "--set", "duration_s=0.01", "--out", dir()}), kExitOk)
      << err_.str();
  std::string j = slurp(root_ / "out" / "hybrid-adaptive.json");
  const std::string mode = param_line(j, "deviation");
  EXPECT_NE(mode.find(R"("value": "random")"), std::string::npos) << mode;
  EXPECT_NE(mode.find(R"("declared": "D1")"), std::string::npos) << mode;
  for (const char* key : {"dA_cs0", "dA_ct0", "dA_ws", "dA_cg"})
    EXPECT_NE(param_line(j, key).find(R"("source": "drawn from --seed 3: uniform in +-deviation_max)"),
              std::string::npos)
        << key << ": " << param_line(j, key);
  ASSERT_EQ(cli({"run", "hybrid-adaptive", "--seed", "3", "--set", "duration_s=0.01", "--set", "deviation=rigid",
                 "--out", dir()}),
            kExitOk)
      << err_.str();
  j = slurp(root_ / "out" / "hybrid-adaptive.json");
  EXPECT_NE(param_line(j, "phi_c_rad").find(R"("unit": "rad", "source": "drawn from --seed 3: )"), std::string::npos)
      << param_line(j, "phi_c_rad");
  EXPECT_NE(param_line(j, "dA_ws").find(R"("source": "derived from phi_c_rad, phi_w_rad)"), std::string::npos)
      << param_line(j, "dA_ws");
  ASSERT_EQ(cli({"run", "dragfree-estimators", "--seed", "2", "--set", "duration_s=0.5", "--out", dir()}), kExitOk)
      << err_.str();
  j = slurp(root_ / "out" / "dragfree-estimators.json");
  EXPECT_NE(param_line(j, "noise_seed").find(R"("value": 3, "unit": "-", "source": "derived: --seed + 1)"),
            std::string::npos)
      << param_line(j, "noise_seed");
}

TEST_F(CliRunChecks, ProgressGoesToStderrOnlyWhenAsked) {
  const std::vector<std::string> base = {"run", "rigid-rw-torquefree", "--set", "duration_s=5",
                                         "--out", dir()};
  ASSERT_EQ(cli(base), kExitOk) << err_.str();
  EXPECT_EQ(err_.str(), "");
  const std::string quiet_out = out_.str();
  std::vector<std::string> with = base;
  with.push_back("--progress");
  ASSERT_EQ(cli(with), kExitOk) << err_.str();
  EXPECT_EQ(out_.str(), quiet_out);  // stdout unchanged
  const std::string e = err_.str();
  EXPECT_EQ(e.rfind("adcs-sim: rigid-rw-torquefree: done, t = 5 / 5 s, wall ", 0), 0u) << e;
  EXPECT_EQ(e.back(), '\n');
  EXPECT_EQ(e.find('\r'), std::string::npos) << e;  // not a terminal: whole lines

  ASSERT_EQ(cli({"montecarlo", "rigid-rw-torquefree", "--runs", "2", "--set", "duration_s=2",
                 "--progress", "--out", dir()}),
            kExitOk)
      << err_.str();
  const std::string m = err_.str();  // a campaign reports runs, not simulated time
  EXPECT_NE(m.find("[2/2 runs] 0 invalid, 0 failed"), std::string::npos) << m;
  EXPECT_EQ(m.find('\r'), std::string::npos) << m;
}

TEST(CliProgress, OptionsAndHelp) {
  EXPECT_TRUE(parse_options("run", {"x", "--progress"}).progress);
  EXPECT_FALSE(parse_options("run", {"x"}).progress);
  EXPECT_TRUE(parse_options("montecarlo", {"x", "--runs", "2", "--progress"}).progress);
  EXPECT_THROW(parse_options("run", {"x", "--progress=1"}), UsageError);
  EXPECT_THROW(parse_options("run", {"x", "--progress", "--progress"}), UsageError);
  EXPECT_THROW(parse_options("describe", {"x", "--progress"}), UsageError);
  EXPECT_NE(usage().find("--progress"), std::string::npos);
  EXPECT_NE(usage().find("1e8 steps"), std::string::npos);
}

TEST(CliProgress, RateLimitedLinesWithEta) {
  double wall = 100.0;
  std::ostringstream err;
  {
    ProgressReporter p(err, "s", /*requested=*/true, /*terminal=*/false, [&] { return wall; });
    wall = 100.5;
    p.update(0.0, 10.0, 100.0);  // < 1 s: nothing yet
    EXPECT_EQ(err.str(), "");
    wall = 101.0;
    p.update(0.0, 20.0, 100.0);
    EXPECT_EQ(err.str(), "adcs-sim: s: t = 20 / 100 s (20.0%), wall 1.0 s, ETA 4.0 s\n");
    wall = 101.5;
    p.update(0.0, 30.0, 100.0);  // within a second of the last line
    wall = 102.0;
    p.update(0.0, 50.0, 100.0);
    wall = 102.2;
    p.finish();
  }
  EXPECT_EQ(err.str(),
            "adcs-sim: s: t = 20 / 100 s (20.0%), wall 1.0 s, ETA 4.0 s\n"
            "adcs-sim: s: t = 50 / 100 s (50.0%), wall 2.0 s, ETA 2.0 s\n"
            "adcs-sim: s: done, t = 50 / 100 s, wall 2.2 s\n");
}

TEST(CliProgress, TerminalShowsLongRunsInPlace) {
  double wall = 0.0;
  std::ostringstream err;
  {
    ProgressReporter p(err, "s", /*requested=*/false, /*terminal=*/true, [&] { return wall; });
    wall = 2.5;
    p.update(0.0, 1.0, 4.0);  // shorter than kAutoAfterS: nothing
    EXPECT_EQ(err.str(), "");
    wall = 3.0;
    p.update(0.0, 3.0, 4.0);
    EXPECT_EQ(err.str(), "\radcs-sim: s: t = 3 / 4 s (75.0%), wall 3.0 s, ETA 1.0 s");
    wall = 4.0;
    p.update(0.0, 1.0, 2.0);  // a second loop (e.g. a companion run) started at wall 3
    EXPECT_EQ(err.str(), "\radcs-sim: s: t = 3 / 4 s (75.0%), wall 3.0 s, ETA 1.0 s"
                         "\radcs-sim: s: t = 1 / 2 s (50.0%), wall 4.0 s, ETA 1.0 s");
  }  // destroyed without finish() (the run failed): the line is ended for the error message
  EXPECT_EQ(err.str().back(), '\n');

  std::ostringstream quiet;
  {
    ProgressReporter p(quiet, "s", false, true, [&] { return wall; });
    p.update(0.0, 4.0, 4.0);
    p.finish();  // a short run on a terminal: nothing at all
  }
  EXPECT_EQ(quiet.str(), "");
  std::ostringstream off;
  {
    ProgressReporter p(off, "s", false, false, [&] { return wall; });
    EXPECT_FALSE(p.enabled());
    wall = 100.0;
    p.update(0.0, 4.0, 4.0);
    p.finish();
  }
  EXPECT_EQ(off.str(), "");
  EXPECT_EQ(format_wall(3725.0), "1 h 02 min");
  EXPECT_EQ(format_wall(125.0), "2 min 05 s");
}

}  // namespace
using namespace ADCS_UNITY_ID;  // as an anonymous namespace would (CMakeLists.txt, adcs_unity)
}  // namespace adcs::sim::cli
