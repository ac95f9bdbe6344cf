#include "cli/command_line.hpp"

#include <algorithm>

#include <CLI/CLI.hpp>

#include "cli/command_table.hpp"
#include "cli/options.hpp"

namespace adcs::sim::cli {
namespace ADCS_UNITY_ID {

// CLI11 2.1 reads some option words differently from adcs-sim's grammar (command_line.hpp).
// Rather than re-implement its reading, each word is marked so that CLI11's own rules give
// adcs-sim's answer: a NUL byte is inserted, which no command-line word can contain (argv
// strings are C strings), CLI11 carries through untouched, and unmark() removes exactly.
//  - "--NAME=VALUE": NUL after '='. CLI11 would read "--opt=" as "--opt" (then take the next
//    word as its value) and accept "--flag=true" or "--flag={}" as the flag; a marked value is
//    never empty, never a flag value, so the option's handler sees it and refuses or takes it.
//  - any other option word that is not -h ("--", "-5", "-hx", "---x", "-x=1"): NUL after the
//    first '-'. CLI11 then sees an unknown short option and keeps the whole word as a leftover
//    (reported as "unknown option"), instead of ending the options ("--"), taking a negative
//    number as a positional ("-5"), splitting short flags ("-hx") or taking "---x" as a
//    positional.
// Plain words (scenario names, values) are not touched; words CLI11 takes as values of a
// preceding option are unmarked with them.
std::string mark(const std::string& word) {
  if (word.size() < 2 || word[0] != '-' || word == "-h") return word;
  std::string name, value, marked = word;
  if (CLI::detail::split_long(word, name, value)) {  // CLI11's own test for "--NAME[=VALUE]"
    if (const auto eq = word.find('='); eq != std::string::npos) marked.insert(eq + 1, 1, '\0');
  } else {
    marked.insert(1, 1, '\0');
  }
  return marked;
}

std::string unmark(std::string word) {
  word.erase(std::remove(word.begin(), word.end(), '\0'), word.end());
  return word;
}

bool has_inline_value(const std::string& raw_flag_result) {
  return raw_flag_result.find('\0') != std::string::npos;  // see mark(): "--flag=VALUE"
}

}  // namespace
using namespace ADCS_UNITY_ID;  // as an anonymous namespace would (CMakeLists.txt, adcs_unity)

CommandLine::CommandLine(std::string command)
    : command_(std::move(command)), app_(std::make_unique<CLI::App>("", kProg + (" " + command_))) {
  app_->set_help_flag();  // no CLI11 help: usage() is the help and run_cli prints it
  app_->allow_extras();   // words nobody took are reported by refuse_leftover(), our way
  add(
      "-h,--help",
      [this](const std::string& raw) {
        // "--help=VALUE" has never been an option of adcs-sim (and -h takes no value).
        if (has_inline_value(raw)) throw UsageError(leftover_message("--help"));
        help_ = true;  // may be repeated
      },
      /*is_flag=*/true);
}

CommandLine::~CommandLine() = default;

void CommandLine::add(const std::string& names,
                      std::function<void(const std::string& raw)> on_word, bool is_flag) {
  CLI::Option* opt = app_->add_option(names, [on_word](const CLI::results_t& r) {
    on_word(r.front());
    return true;
  });
  // Run the handler where the option stands on the line (CLI11 otherwise runs it after the
  // whole line is read), so that the first bad word is the one reported, as it always was.
  // CLI11 then hands over one occurrence at a time; repeats are the handlers' business.
  opt->trigger_on_parse();
  if (is_flag) opt->expected(0);
}

void CommandLine::positional(const std::string& name, const std::string& what,
                             const std::string& extra_note, std::string& out) {
  has_positional_ = true;
  positional_what_ = what;
  positional_extra_note_ = extra_note;
  // One value: a second positional word is a leftover (CLI11 keeps it in line order).
  app_->add_option(name, [this, &out](const CLI::results_t& r) {
    out = unmark(r.front());
    have_positional_ = true;
    return true;
  });
}

void CommandLine::positionals(const std::string& name, const std::string& what,
                              std::vector<std::string>& out) {
  has_positional_ = true;
  positional_what_ = what;
  app_->add_option(name, [this, &out](const CLI::results_t& r) {
         for (const std::string& w : r) out.push_back(unmark(w));
         have_positional_ = !out.empty();
         return true;
       })
      ->expected(1, CLI::detail::expected_max_vector_size)
      ->allow_extra_args();  // CLI11 2.1 fills a positional list only with this
}

void CommandLine::once(const std::string& option,
                       std::function<void(const std::string& value)> on_value) {
  add(
      option,
      [this, option, on_value](const std::string& raw) {
        if (!given_.insert(option).second) throw UsageError(option + " given twice");
        on_value(unmark(raw));
      },
      /*is_flag=*/false);
}

void CommandLine::repeatable(const std::string& option,
                             std::function<void(const std::string& value)> on_value) {
  add(
      option, [on_value](const std::string& raw) { on_value(unmark(raw)); }, /*is_flag=*/false);
}

void CommandLine::flag(const std::string& option, bool& out) {
  add(
      option,
      [this, option, &out](const std::string& raw) {
        if (has_inline_value(raw)) throw UsageError(option + " takes no value");
        if (!given_.insert(option).second) throw UsageError(option + " given twice");
        out = true;
      },
      /*is_flag=*/true);
}

void CommandLine::misplaced(const std::string& option, const std::string& message) {
  misplaced_.emplace_back(option, message);
}

bool CommandLine::parse(const std::vector<std::string>& args) {
  std::vector<std::string> words;  // CLI11 takes the words last first
  words.reserve(args.size());
  for (auto it = args.rbegin(); it != args.rend(); ++it) words.push_back(mark(*it));
  // A handler or CLI11 stops at the first bad option; an unknown word before it was the first
  // mistake on the line, so it is the one reported (refuse_leftover() first).
  try {
    app_->parse(words);
  } catch (const UsageError&) {
    refuse_leftover();
    throw;
  } catch (const CLI::ArgumentMismatch&) {
    // The only mismatch our options allow: a value option as the last word (an inline value
    // is never empty, see mark()), so that word is the option.
    refuse_leftover();
    throw UsageError("option " + args.back() + " needs a value");
  } catch (const CLI::ParseError& e) {
    refuse_leftover();
    throw UsageError(e.what());  // not expected with the options above; still a bad line
  }
  refuse_leftover();
  if (!help_ && has_positional_ && !have_positional_)
    throw UsageError("'" + command_ + "' needs " + positional_what_);
  return help_;
}

void CommandLine::refuse_leftover() const {
  const std::vector<std::string> left = app_->remaining();
  if (!left.empty()) throw UsageError(leftover_message(unmark(left.front())));
}

std::string CommandLine::leftover_message(const std::string& word) const {
  if (word.size() > 1 && word[0] == '-') {  // an option word (the grammar, command_line.hpp)
    const std::string option = word.rfind("--", 0) == 0 ? word.substr(0, word.find('=')) : word;
    for (const auto& [name, message] : misplaced_)
      if (name == option) return message;
    return "unknown option '" + option + "' for '" + command_ + "' (see '" + kProg + " help')";
  }
  if (!has_positional_) return "'" + command_ + "' takes no argument, got '" + word + "'";
  return "unexpected argument '" + word + "' (" + positional_extra_note_ + ")";
}

}  // namespace adcs::sim::cli
