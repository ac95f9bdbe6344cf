// Every registered scenario follows the rules of src/scenarios/scenario.hpp.
#include <gtest/gtest.h>

#include <set>

#include "scenarios/registry.hpp"

namespace adcs::sim {
namespace ADCS_UNITY_ID {

TEST(Registry, EveryScenarioDeclaresDurationAndControlPeriod) {
  const auto problems = registry_problems();
  for (const auto& p : problems) ADD_FAILURE() << p;
  EXPECT_TRUE(problems.empty());
}

TEST(Registry, AtLeastTheFoundationScenarios) {
  ASSERT_GE(all_scenarios().size(), 2u);
  EXPECT_NE(find_scenario("rigid-rw-torquefree"), nullptr);
  EXPECT_NE(find_scenario("rigid-rw-mrp-pd"), nullptr);
  EXPECT_EQ(find_scenario("no-such-scenario"), nullptr);
  EXPECT_EQ(all_scenarios()[0]->name(), "rigid-rw-torquefree");  // list order
}

TEST(Registry, NamesAreUniqueAndFindable) {
  std::set<std::string> names;
  for (const auto& s : all_scenarios()) {
    EXPECT_TRUE(names.insert(s->name()).second) << s->name();
    EXPECT_EQ(find_scenario(s->name()), s.get());
  }
}

// Issue 19: `--set scalar=float|double` on every paper scenario (seeds 001-004: hybrid-*,
// flexible-*, se3-*, dragfree-*; not the cross pairings of issue 17, whose descriptions say so).
TEST(Registry, EveryPaperScenarioTakesScalar) {
  int paper = 0;
  for (const auto& s : all_scenarios()) {
    const std::string n = s->name();
    auto starts = [&n](const char* prefix) { return n.rfind(prefix, 0) == 0; };
    if (!starts("hybrid-") && !starts("flexible-") && !starts("se3-") && !starts("dragfree-")) continue;
    if (s->description().rfind("cross pairing", 0) == 0) continue;
    ++paper;
    ParamSet p;
    s->declare(p);
    ASSERT_TRUE(p.has("scalar")) << n;
    EXPECT_NO_THROW(p.set("scalar", "double")) << n;
    EXPECT_NO_THROW(p.set("scalar", "float")) << n;
    EXPECT_THROW(p.set("scalar", "half"), ParamError) << n;
  }
  EXPECT_GE(paper, 20);
}

TEST(Registry, ProblemsAreDetected) {
  struct Bad final : Scenario {
    std::string name() const override { return "Bad Name"; }
    std::string description() const override { return ""; }
    void declare(ParamSet& p) const override {
      p.number("duration_s", 0.0, "s", "assumed");
      p.vector("control_period_s", {1.0}, "s", "");
    }
    RunResult run(const ParamSet&, const RunContext&) const override { return {}; }
  };
  const auto problems = scenario_problems(Bad{});
  EXPECT_EQ(problems.size(), 5u);  // name, description, duration > 0, period kind, no source
  struct Missing final : Scenario {
    std::string name() const override { return "missing"; }
    std::string description() const override { return "d"; }
    void declare(ParamSet&) const override {}
    RunResult run(const ParamSet&, const RunContext&) const override { return {}; }
  };
  EXPECT_EQ(scenario_problems(Missing{}).size(), 2u);
}

}  // namespace
using namespace ADCS_UNITY_ID;  // as an anonymous namespace would (CMakeLists.txt, adcs_unity)
}  // namespace adcs::sim
