#pragma once
// The list of scenarios adcs-sim knows. To add one: implement
//   std::unique_ptr<Scenario> make_<name>();   (namespace adcs::sim, in src/scenarios/<name>.cpp)
// declare it at the top of registry.cpp and push it in build_registry() there; the order in
// that list is the order of `adcs-sim list`.
#include <memory>
#include <string>
#include <vector>

#include "scenarios/scenario.hpp"

namespace adcs::sim {

//! Every registered scenario, in `adcs-sim list` order (built once, on first use).
const std::vector<std::unique_ptr<Scenario>>& all_scenarios();

//! The scenario with this name, or nullptr.
const Scenario* find_scenario(const std::string& name);

//! Problems of one scenario against the rules of scenario.hpp that can be checked without
//! running it: a file-safe name, a description, declare() not throwing, `duration_s` and
//! `control_period_s` declared as positive numbers. Empty when fine.
std::vector<std::string> scenario_problems(const Scenario& s);

//! scenario_problems() of every registered scenario plus duplicate names, each prefixed by the
//! scenario name. Empty when fine (tested in tests/scenarios/test_cli_registry.cpp).
std::vector<std::string> registry_problems();

}  // namespace adcs::sim
