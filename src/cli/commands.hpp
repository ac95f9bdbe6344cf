#pragma once
// adcs-sim: list, describe, run, montecarlo, help (contract in docs/ARCHITECTURE.md, "The
// user's contract", and docs/CONTRACTS.md, "Output files").
//
// Exit status: 0 success; 2 bad command line (unknown command/option/scenario/parameter,
// malformed or mistyped value) with nothing written; 1 simulation or I/O failure with nothing
// written. Every error is one line on stderr: "adcs-sim: error: ...".
#include <iosfwd>
#include <string>
#include <vector>

#include "cli/options.hpp"  // Options, parse_options, parse_uint, UsageError
#include "scenarios/scenario.hpp"

namespace adcs::sim::cli {

constexpr int kExitOk = 0;
constexpr int kExitFailure = 1;
constexpr int kExitUsage = 2;

//! The scenarios the CLI offers (the registry in adcs-sim; fakes in tests).
struct Catalog {
  std::vector<const Scenario*> scenarios;
  const Scenario* find(const std::string& name) const;
  static Catalog registered();
};

//! The most simulation steps a run may take: duration_s / control_period_s (and, with
//! integrator=rk4, duration_s / rk4_step_s) above this is refused before running (exit 2).
constexpr double kMaxSteps = 1e8;

//! The checks every scenario's parameters pass before a run (the one place for them; throws
//! ParamError naming the key): duration_s > 0 and control_period_s > 0; duration_s /
//! control_period_s <= kMaxSteps; when declared: rtol in (0, 1), atol > 0, rk4_step_s > 0 and,
//! with integrator=rk4, duration_s / rk4_step_s <= kMaxSteps.
void check_run_parameters(const ParamSet& ps);

//! The usage text (`adcs-sim help`).
std::string usage();

//! `msg` on one line: control characters (newlines included) become spaces.
std::string one_line(const std::string& msg);

//! Runs one command line (args exclude the program name); returns the exit status.
//! `err_is_terminal`: err is a terminal (progress lines are then shown for long runs even
//! without --progress, rewritten in place).
int run_cli(const std::vector<std::string>& args, const Catalog& catalog, std::ostream& out,
            std::ostream& err, bool err_is_terminal = false);

//! main() of adcs-sim: the registered scenarios, std::cout / std::cerr, signal cleanup.
int cli_main(int argc, char** argv);

}  // namespace adcs::sim::cli
