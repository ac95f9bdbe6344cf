#include "cli/options.hpp"

#include <limits>

#include "cli/command_line.hpp"
#include "cli/command_table.hpp"

namespace adcs::sim::cli {

Options parse_options(const std::string& command, const std::vector<std::string>& args) {
  const Command* c = find_command(command);
  if (!c) throw UsageError("unknown command '" + command + "' (see '" + kProg + " help')");
  Options o;
  CommandLine cl(command);
  c->declare(cl, o);
  o.help = cl.parse(args);
  if (!o.help && c->check) c->check(o);
  return o;
}

// Not CLI11's integer conversion: CLI11 2.1 reads integers with strtoull base 0, so it takes
// "010" as 8, "0x10", "+1", wraps "-1" to 2^64 - 1 and does not notice overflow.
std::uint64_t parse_uint(const std::string& what, const std::string& text) {
  if (text.empty()) throw UsageError(what + " needs a value");
  std::uint64_t v = 0;
  for (char c : text) {
    if (c < '0' || c > '9')
      throw UsageError(what + " must be a non-negative integer, got '" + text + "'");
    const auto d = static_cast<std::uint64_t>(c - '0');
    if (v > (std::numeric_limits<std::uint64_t>::max() - d) / 10)
      throw UsageError(what + " is too large: '" + text + "'");
    v = v * 10 + d;
  }
  return v;
}

// ---- declarations shared by several commands --------------------------------------------------

void declare_scenario_name(CommandLine& cl, Options& o) {
  cl.positional("NAME", "a scenario NAME or a vehicle FILE", "one scenario at a time", o.scenario);
}

void declare_sets(CommandLine& cl, Options& o) {
  // KEY=VALUE is split here: CLI11 2.1 has no such value type (its pairs take two words).
  cl.repeatable("--set", [&o](const std::string& text) {
    const auto eq = text.find('=');
    if (eq == std::string::npos) throw UsageError("--set expects KEY=VALUE, got '" + text + "'");
    std::string key = text.substr(0, eq);
    if (key.empty())
      throw UsageError("--set expects KEY=VALUE, got an empty key in '" + text + "'");
    for (const auto& kv : o.sets)
      if (kv.first == key) throw UsageError("parameter '" + key + "' is set twice");
    o.sets.emplace_back(std::move(key), text.substr(eq + 1));
  });
}

void declare_out(CommandLine& cl, Options& o) {
  cl.once("--out", [&o](const std::string& dir) {
    if (dir.empty()) throw UsageError("--out needs a directory");
    o.out_dir = dir;
  });
}

void declare_progress(CommandLine& cl, Options& o) { cl.flag("--progress", o.progress); }

void declare_montecarlo_only(CommandLine& cl, const std::string& command) {
  for (const char* option : {"--runs", "--seed0", "--disperse", "--jobs", "--shard", "--resume", "--series", "--rank-by"})
    cl.misplaced(option, std::string("option ") + option + " belongs to 'montecarlo', not '" +
                             command + "'");
}

}  // namespace adcs::sim::cli
