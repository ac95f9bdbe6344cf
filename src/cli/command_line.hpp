#pragma once
// One adcs-sim command's options, parsed by CLI11 with adcs-sim's rules and messages.
//
// adcs-sim's grammar (commands.hpp, usage()): `adcs-sim COMMAND [ARGS]`; after the command word
// a word is an option when it starts with '-' and is longer than one character; options are
// `--NAME VALUE` or `--NAME=VALUE`, flags `--NAME`, and -h/--help; each option is given once
// unless it says otherwise; the first bad word is reported as one UsageError (exit 2).
//
// CLI11 does the reading: which word is which option, its value in either form, a value missing
// at the end, the positionals, the words nobody declared. This class fixes what CLI11 2.1 does
// differently from that grammar (command_line.cpp says how):
//   - CLI11's help flag, help text and exit codes: not used (usage() is the help, run_cli the
//     exit status);
//   - every error is adcs-sim's own one-line text, for the first bad word on the line;
//   - words CLI11 gives a meaning adcs-sim never had: "--" (end of options), "-5" (a negative
//     number, taken as a positional), "-hx" (-h then -x), "--flag=VALUE" (accepted for
//     flags), "--opt=" (an empty value, read as "take the next word").
// Each command is its own CLI::App rather than a CLI11 subcommand: the command word is always
// the first word, and CLI11's subcommands would add rules adcs-sim never had (options before
// the command word, "++" ending a subcommand, words after "--" returning to the parent).
#include <functional>
#include <memory>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace CLI {
class App;
}

namespace adcs::sim::cli {

class CommandLine {
 public:
  //! `command`: the command word (named in messages). Every command accepts -h/--help.
  explicit CommandLine(std::string command);
  ~CommandLine();
  CommandLine(const CommandLine&) = delete;
  CommandLine& operator=(const CommandLine&) = delete;

  //! The one positional argument. Missing (without --help): "'CMD' needs " + `what`; a second
  //! one: "unexpected argument 'X' (" + `extra_note` + ")". (A list, as in `merge DIR...`,
  //! would be a CLI11 option with expected(1, -1) next to it.)
  void positional(const std::string& name, const std::string& what, const std::string& extra_note,
                  std::string& out);
  //! One or more positional arguments (`merge DIR...`), in order. Missing (without --help):
  //! "'CMD' needs " + `what`.
  void positionals(const std::string& name, const std::string& what, std::vector<std::string>& out);
  //! An option with one value, given at most once ("--opt given twice"); `on_value` checks and
  //! stores the value (throws UsageError).
  void once(const std::string& option, std::function<void(const std::string& value)> on_value);
  //! An option with one value that may be repeated; `on_value` is called for each, in order.
  void repeatable(const std::string& option,
                  std::function<void(const std::string& value)> on_value);
  //! A flag: no value ("--opt takes no value"), at most once ("--opt given twice").
  void flag(const std::string& option, bool& out);
  //! `option` is not one of this command's, but the user probably meant something else:
  //! `message` replaces "unknown option '...' for 'CMD' (see 'adcs-sim help')".
  void misplaced(const std::string& option, const std::string& message);

  //! Parses the words after the command word; throws UsageError. Returns true when --help was
  //! given (the positional is then not required).
  bool parse(const std::vector<std::string>& args);

 private:
  void add(const std::string& names, std::function<void(const std::string& raw)> on_word,
           bool is_flag);
  //! Throws UsageError for the first word no option or positional took, if any.
  void refuse_leftover() const;
  //! The message for such a word (an option: unknown or misplaced; else an extra positional).
  std::string leftover_message(const std::string& word) const;

  std::string command_;
  std::unique_ptr<CLI::App> app_;
  std::set<std::string> given_;                         // options given so far (once())
  std::vector<std::pair<std::string, std::string>> misplaced_;
  bool help_ = false;
  bool has_positional_ = false, have_positional_ = false;
  std::string positional_what_, positional_extra_note_;
};

}  // namespace adcs::sim::cli
