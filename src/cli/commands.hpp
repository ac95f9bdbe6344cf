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
  bool help = false;                                      // --help / -h
};

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
int run_cli(const std::vector<std::string>& args, const Catalog& catalog, std::ostream& out,
            std::ostream& err);

//! main() of adcs-sim: the registered scenarios, std::cout / std::cerr, signal cleanup.
int cli_main(int argc, char** argv);

}  // namespace adcs::sim::cli
