#pragma once
// Helpers shared by the scenario tests: look a metric up by name, run a scenario with overrides.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include <unistd.h>

#include "scenarios/registry.hpp"

namespace adcs::sim::test {

//! An empty directory of its own for the running test: <tmp>/<prefix>_<pid>_<test name>.
inline std::filesystem::path fresh_test_dir(const std::string& prefix) {
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() /
                       (prefix + "_" + std::to_string(::getpid()) + "_" +
                        ::testing::UnitTest::GetInstance()->current_test_info()->name());
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

inline double metric(const RunResult& r, const std::string& name) {
  if (!r.has_metric(name)) ADD_FAILURE() << "no metric " << name;
  return r.metric(name);
}

//! Every claim row with a verdict holds (rows without one are recorded, not asserted).
inline void expect_claims_hold(const RunResult& r) {
  for (const auto& c : r.claims) {
    if (c.holds.has_value()) {
      EXPECT_TRUE(*c.holds) << c.claim << ": " << c.ours;
    }
  }
}

//! The one claim whose text starts with `prefix` (nullptr, and a failure, unless exactly one).
inline const Claim* find_claim(const RunResult& r, const std::string& prefix) {
  const Claim* found = nullptr;
  int n = 0;
  for (const Claim& c : r.claims)
    if (c.claim.rfind(prefix, 0) == 0) {
      found = &c;
      ++n;
    }
  EXPECT_EQ(n, 1) << "claims starting with '" << prefix << "'";
  return n == 1 ? found : nullptr;
}

//! The claim's paper verdict as text (issue 16): "reproduced", "partly", "not reproduced" or
//! "(none)"; text, so that a failing comparison prints both sides.
inline std::string paper_verdict(const RunResult& r, const std::string& prefix) {
  const Claim* c = find_claim(r, prefix);
  if (!c) return "(no such claim)";
  return c->paper_verdict ? to_string(*c->paper_verdict) : "(none)";
}

//! Issue 16 form of every row: it quotes a paper value (or a requirement), a check has no paper
//! verdict, and a row whose criterion is judged states the criterion.
inline void expect_rows_well_formed(const RunResult& r) {
  for (const Claim& c : r.claims) {
    EXPECT_FALSE(c.paper_value.empty()) << c.claim;
    if (c.kind == "check") {
      EXPECT_FALSE(c.paper_verdict.has_value()) << c.claim;
    }
    if (c.kind == "paper" && c.holds.has_value()) {
      EXPECT_FALSE(c.criterion.empty()) << c.claim;
    }
  }
}

inline RunResult run(const std::string& scenario,
                     const std::vector<std::pair<std::string, std::string>>& sets = {},
                     std::uint64_t seed = 0) {
  const Scenario* s = find_scenario(scenario);
  EXPECT_NE(s, nullptr) << scenario;
  ParamSet p;
  s->declare(p);
  for (const auto& [k, v] : sets) p.set(k, v);
  RunContext ctx;
  ctx.seed = seed;
  ctx.quiet = true;
  return s->run(p, ctx);
}

}  // namespace adcs::sim::test
