// adcs-sim's entry: the command word, the exit status and the one-line error of every failure.
#include "cli/commands.hpp"

#include <exception>
#include <iostream>
#include <ostream>

#include <unistd.h>

#include "cli/atomic_file.hpp"
#include "cli/command_table.hpp"
#include "cli/scenario_runs.hpp"
#include "scenarios/registry.hpp"

namespace adcs::sim::cli {

const Scenario* Catalog::find(const std::string& name) const {
  for (const Scenario* s : scenarios)
    if (s->name() == name) return s;
  return nullptr;
}

Catalog Catalog::registered() {
  Catalog c;
  for (const auto& s : all_scenarios()) c.scenarios.push_back(s.get());
  return c;
}

std::string one_line(const std::string& msg) {
  std::string s = msg;
  for (char& c : s)
    if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) c = ' ';
  return s;
}

int run_cli(const std::vector<std::string>& args, const Catalog& catalog, std::ostream& out,
            std::ostream& err, bool err_is_terminal) {
  const auto fail = [&](int status, const std::string& msg) {
    out.flush();
    err << kProg << ": error: " << one_line(msg) << std::endl;
    return status;
  };
  const auto help = [&] {
    out << usage();
    out.flush();
    return kExitOk;
  };
  try {
    // The command is the first word (usage: adcs-sim COMMAND [ARGS]); "help", --help and -h
    // there answer with the usage whatever follows.
    if (args.empty()) return fail(kExitUsage, std::string("no command (see '") + kProg + " help')");
    const std::string& word = args.front();
    if (word == "help" || word == "--help" || word == "-h") return help();
    const Command* command = find_command(word);
    if (!command)
      return fail(kExitUsage, "unknown command '" + word + "' (see '" + kProg + " help')");
    const Options o = parse_options(word, std::vector<std::string>(args.begin() + 1, args.end()));
    if (o.help) return help();
    return command->run(o, CommandIo{catalog, out, err, err_is_terminal});
  } catch (const UsageError& e) {
    return fail(kExitUsage, e.what());
  } catch (const ParamError& e) {
    return fail(kExitUsage, e.what());
  } catch (const RunFailure& e) {
    return fail(kExitFailure, e.what());
  } catch (const IoError& e) {
    return fail(kExitFailure, e.what());
  } catch (const std::exception& e) {
    return fail(kExitFailure, std::string("internal error: ") + e.what());
  } catch (...) {
    return fail(kExitFailure, "internal error: unknown exception");
  }
}

int cli_main(int argc, char** argv) {
  install_cleanup_signal_handlers();
  std::vector<std::string> args;
  for (int i = 1; i < argc; ++i) args.emplace_back(argv[i]);
  try {
    return run_cli(args, Catalog::registered(), std::cout, std::cerr, ::isatty(2) == 1);
  } catch (const std::exception& e) {  // e.g. a scenario factory throwing
    std::cerr << kProg << ": error: internal error: " << one_line(e.what()) << std::endl;
    return kExitFailure;
  } catch (...) {
    std::cerr << kProg << ": error: internal error while starting" << std::endl;
    return kExitFailure;
  }
}

}  // namespace adcs::sim::cli
