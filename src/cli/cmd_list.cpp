// adcs-sim list: the scenario names, one a line.
#include <ostream>

#include "cli/command_line.hpp"
#include "cli/command_table.hpp"
#include "cli/commands.hpp"

namespace adcs::sim::cli {

void declare_list(CommandLine& cl, Options&) {
  // No positional and no options (but -h/--help).
  declare_montecarlo_only(cl, "list");
}

int cmd_list(const Options&, const CommandIo& io) {
  for (const Scenario* s : io.catalog.scenarios) io.out << s->name() << '\n';
  io.out.flush();
  return kExitOk;
}

}  // namespace adcs::sim::cli
