// adcs-sim describe NAME: the scenario's description and parameters (default, unit, source).
#include <algorithm>
#include <ostream>

#include "cli/command_line.hpp"
#include "cli/command_table.hpp"
#include "cli/commands.hpp"
#include "cli/scenario_runs.hpp"

namespace adcs::sim::cli {

void declare_describe(CommandLine& cl, Options& o) {
  declare_scenario_name(cl, o);
  declare_montecarlo_only(cl, "describe");
}

int cmd_describe(const Options& o, const CommandIo& io) {
  const Scenario& s = lookup(io.catalog, o.scenario);
  ParamSet ps;
  s.declare(ps);
  std::ostream& out = io.out;
  out << s.name() << ": " << s.description() << "\n\n";
  out << "parameters (override with: " << kProg << " run " << s.name() << " --set KEY=VALUE):\n";
  std::size_t wk = 0;
  for (const Param& p : ps) wk = std::max(wk, p.key.size());
  for (const Param& p : ps) {
    out << "  " << p.key << std::string(wk - p.key.size(), ' ') << " = " << format_value(p);
    if (!p.unit.empty()) out << " [" << p.unit << "]";
    out << "  (" << describe_kind(p) << ")\n";
    out << "  " << std::string(wk, ' ') << "   source: " << p.source << '\n';
  }
  out.flush();
  return kExitOk;
}

}  // namespace adcs::sim::cli
