#pragma once
// adcs-sim: list, describe, run, montecarlo, help (contract in docs/ARCHITECTURE.md, "The
// user's contract", and docs/CONTRACTS.md, "Output files").
//
// Exit status: 0 success; 2 bad command line (unknown command/option/scenario/parameter,
// malformed or mistyped value) with nothing written; 1 simulation or I/O failure with nothing
// written. Every error is one line on stderr: "adcs-sim: error: ...".
#include <cstdint>
#include <iosfwd>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "scenarios/scenario.hpp"

namespace adcs::sim::cli {

constexpr int kExitOk = 0;
constexpr int kExitFailure = 1;
constexpr int kExitUsage = 2;

//! A bad command line (exit 2).
struct UsageError : std::runtime_error {
  using runtime_error::runtime_error;
};

//! The scenarios the CLI offers (the registry in adcs-sim; fakes in tests).
struct Catalog {
  std::vector<const Scenario*> scenarios;
  const Scenario* find(const std::string& name) const;
  static Catalog registered();
};

//! Options after the command word. Forms: `--opt VALUE` or `--opt=VALUE`.
struct Options {
  std::string scenario;                                   // the one positional argument
  std::vector<std::pair<std::string, std::string>> sets;  // --set key=value, in order
  std::optional<std::uint64_t> seed;                      // run: --seed N (default 0)
  std::optional<std::uint64_t> runs;                      // montecarlo: --runs R (>= 1)
  std::optional<std::uint64_t> seed0;                     // montecarlo: --seed0 S (default 1)
  std::optional<std::string> out_dir;                     // --out DIR (default "out")
  bool progress = false;                                  // run, montecarlo: --progress
  bool help = false;                                      // --help / -h
};

//! The most simulation steps a run may take: duration_s / control_period_s (and, with
//! integrator=rk4, duration_s / rk4_step_s) above this is refused before running (exit 2).
constexpr double kMaxSteps = 1e8;

//! The checks every scenario's parameters pass before a run (the one place for them; throws
//! ParamError naming the key): duration_s > 0 and control_period_s > 0; duration_s /
//! control_period_s <= kMaxSteps; when declared: rtol in (0, 1), atol > 0, rk4_step_s > 0 and,
//! with integrator=rk4, duration_s / rk4_step_s <= kMaxSteps.
void check_run_parameters(const ParamSet& ps);

//! Parses the arguments of `command` ("run", "montecarlo", "describe", "list"); throws
//! UsageError (unknown option, missing value, duplicate option or --set key, --set without
//! '=', malformed integer, missing or extra positional, missing --runs).
Options parse_options(const std::string& command, const std::vector<std::string>& args);

//! A non-negative decimal integer (digits only, no sign, no overflow); UsageError naming `what`.
std::uint64_t parse_uint(const std::string& what, const std::string& text);

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
