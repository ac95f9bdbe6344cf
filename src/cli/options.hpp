#pragma once
// What adcs-sim's command line says, once parsed (the grammar: commands.hpp and usage()).
// Each command declares its options in its own cmd_*.cpp file (declare_*), through the rules of
// command_line.hpp; parse_options() runs that declaration over the words after the command.
#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace adcs::sim::cli {

//! A bad command line (exit 2).
struct UsageError : std::runtime_error {
  using runtime_error::runtime_error;
};

//! Options after the command word. Forms: `--opt VALUE` or `--opt=VALUE`.
struct Options {
  std::string scenario;                                   // the one positional argument
  std::vector<std::pair<std::string, std::string>> sets;  // --set key=value, in order
  std::optional<std::uint64_t> seed;                      // run: --seed N (default 0)
  std::optional<std::uint64_t> runs;                      // montecarlo: --runs R (>= 1)
  std::optional<std::uint64_t> seed0;                     // montecarlo: --seed0 S (default 1)
  std::optional<std::string> out_dir;                     // --out DIR (default "out"; merge: the first DIR)
  // montecarlo (issue 18): docs/CAMPAIGNS.md
  std::vector<std::string> disperse;                      // --disperse KEY=EXPR, in order
  std::optional<std::uint64_t> jobs;                      // --jobs N (default: all cores)
  std::optional<std::string> shard;                       // --shard i/N | auto | auto/N
  bool resume = false;                                    // --resume
  std::vector<std::string> series;                        // --series COL[,COL...] (repeatable)
  std::optional<std::string> rank_by;                     // --rank-by METRIC
  std::vector<std::string> dirs;                          // merge: DIR...
  bool progress = false;                                  // run, montecarlo: --progress
  bool help = false;                                      // --help / -h
};

//! Parses the arguments of `command` ("run", "montecarlo", "describe", "list"); throws
//! UsageError (unknown command or option, missing value, duplicate option or --set key, --set
//! without '=', malformed integer, missing or extra positional, missing --runs). With --help
//! the checks of the whole line (missing positional, missing --runs) are skipped.
Options parse_options(const std::string& command, const std::vector<std::string>& args);

//! A non-negative decimal integer (digits only, no sign, no overflow); UsageError naming `what`.
std::uint64_t parse_uint(const std::string& what, const std::string& text);

}  // namespace adcs::sim::cli
