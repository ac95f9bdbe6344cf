#include "cli/command_table.hpp"

namespace adcs::sim::cli {

const Command* find_command(const std::string& name) {
  // In usage() order.
  static const Command kCommands[] = {
      {"list", declare_list, nullptr, cmd_list},
      {"describe", declare_describe, nullptr, cmd_describe},
      {"run", declare_run, nullptr, cmd_run},
      {"montecarlo", declare_montecarlo, check_montecarlo, cmd_montecarlo},
      {"merge", declare_merge, nullptr, cmd_merge},
  };
  for (const Command& c : kCommands)
    if (name == c.name) return &c;
  return nullptr;
}

}  // namespace adcs::sim::cli
