#pragma once
// adcs-sim's commands: for each, where its options are declared and what runs it. A new command
// is a cmd_NAME.cpp with declare_NAME() and cmd_NAME(), a row in command_table.cpp and a
// paragraph in usage().
#include <iosfwd>
#include <string>

#include "cli/options.hpp"

namespace adcs::sim::cli {

inline constexpr const char* kProg = "adcs-sim";

struct Catalog;
class CommandLine;

//! What a command runs against: the scenarios and the two output streams.
struct CommandIo {
  const Catalog& catalog;
  std::ostream& out;
  std::ostream& err;
  bool err_is_terminal;  // progress lines for long runs even without --progress
};

struct Command {
  const char* name;
  //! Declares the command's positional and options into `cl`, storing into `o`: the one place
  //! where a command's command line is defined.
  void (*declare)(CommandLine& cl, Options& o);
  //! Checks that need the whole line (a required option, a combination); not run with --help.
  //! May be null.
  void (*check)(const Options& o);
  //! Runs the command; returns the exit status. Throws UsageError or ParamError (exit 2),
  //! RunFailure or IoError (exit 1).
  int (*run)(const Options& o, const CommandIo& io);
};

//! The command named `name`, or nullptr. ("help" is not one: run_cli answers it first.)
const Command* find_command(const std::string& name);

// cmd_list.cpp, cmd_describe.cpp, cmd_run.cpp, cmd_montecarlo.cpp, cmd_merge.cpp
void declare_list(CommandLine& cl, Options& o);
int cmd_list(const Options& o, const CommandIo& io);
void declare_describe(CommandLine& cl, Options& o);
int cmd_describe(const Options& o, const CommandIo& io);
void declare_run(CommandLine& cl, Options& o);
int cmd_run(const Options& o, const CommandIo& io);
void declare_montecarlo(CommandLine& cl, Options& o);
void check_montecarlo(const Options& o);
int cmd_montecarlo(const Options& o, const CommandIo& io);
void declare_merge(CommandLine& cl, Options& o);
int cmd_merge(const Options& o, const CommandIo& io);

// options.cpp: declarations shared by several commands.
//! NAME, the scenario.
void declare_scenario_name(CommandLine& cl, Options& o);
//! --set KEY=VALUE (repeatable, each KEY once).
void declare_sets(CommandLine& cl, Options& o);
//! --out DIR.
void declare_out(CommandLine& cl, Options& o);
//! --progress.
void declare_progress(CommandLine& cl, Options& o);
//! Hints for montecarlo's options given to another command.
void declare_montecarlo_only(CommandLine& cl, const std::string& command);

}  // namespace adcs::sim::cli
