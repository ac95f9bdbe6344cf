// adcs-sim's command-line grammar on CLI11 (src/cli/command_line.hpp): the words CLI11 2.1 reads
// differently are read as adcs-sim always did, with the same messages, and the first bad word
// on the line is the one reported.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "cli/commands.hpp"

namespace adcs::sim::cli {
namespace ADCS_UNITY_ID {

std::string refusal(const std::string& command, const std::vector<std::string>& args) {
  try {
    parse_options(command, args);
  } catch (const UsageError& e) {
    return e.what();
  }
  return "(accepted)";
}

TEST(CliGrammar, WordsCli11ReadsDifferently) {
  const std::string unknown = "' for 'run' (see 'adcs-sim help')";
  // CLI11: end of options, a negative number as a positional, -h then -x / -5, "---x" as a
  // positional, "--opt=" as "take the next word", "--flag=true" / "--flag={}" as the flag.
  EXPECT_EQ(refusal("run", {"x", "--"}), "unknown option '--" + unknown);
  EXPECT_EQ(refusal("run", {"--", "x"}), "unknown option '--" + unknown);
  EXPECT_EQ(refusal("run", {"x", "-5"}), "unknown option '-5" + unknown);
  EXPECT_EQ(refusal("run", {"x", "-h5"}), "unknown option '-h5" + unknown);
  EXPECT_EQ(refusal("run", {"x", "-hx"}), "unknown option '-hx" + unknown);
  EXPECT_EQ(refusal("run", {"x", "-h=1"}), "unknown option '-h=1" + unknown);
  EXPECT_EQ(refusal("run", {"x", "---x"}), "unknown option '---x" + unknown);
  EXPECT_EQ(refusal("run", {"x", "--=1"}), "unknown option '--" + unknown);
  EXPECT_EQ(refusal("run", {"x", "--seed=", "5"}), "--seed needs a value");
  EXPECT_EQ(refusal("run", {"x", "--out=", "d"}), "--out needs a directory");
  EXPECT_EQ(refusal("run", {"x", "--set=", "k=1"}), "--set expects KEY=VALUE, got ''");
  EXPECT_EQ(refusal("run", {"x", "--progress=true"}), "--progress takes no value");
  EXPECT_EQ(refusal("run", {"x", "--progress={}"}), "--progress takes no value");
  EXPECT_EQ(refusal("run", {"x", "--progress="}), "--progress takes no value");
  EXPECT_EQ(refusal("run", {"x", "--help=0"}), "unknown option '--help" + unknown);
  EXPECT_EQ(refusal("list", {"++"}), "'list' takes no argument, got '++'");
  EXPECT_EQ(refusal("run", {"x", "++"}), "unexpected argument '++' (one scenario at a time)");
  // CLI11's integers: base 0 ("010" is 8), "-1" wrapped, overflow unnoticed.
  EXPECT_EQ(refusal("run", {"x", "--seed", "0x10"}),
            "--seed must be a non-negative integer, got '0x10'");
  EXPECT_EQ(refusal("run", {"x", "--seed", "-1"}),
            "--seed must be a non-negative integer, got '-1'");
  EXPECT_EQ(*parse_options("run", {"x", "--seed", "010"}).seed, 10u);
}

TEST(CliGrammar, ValuesAreTakenAsTheyAre) {
  const Options o = parse_options("run", {"--out", "--", "x", "--set", "-k=-1", "--set=a=b=c"});
  EXPECT_EQ(*o.out_dir, "--");
  EXPECT_EQ(o.scenario, "x");
  ASSERT_EQ(o.sets.size(), 2u);
  EXPECT_EQ(o.sets[0], (std::pair<std::string, std::string>{"-k", "-1"}));
  EXPECT_EQ(o.sets[1], (std::pair<std::string, std::string>{"a", "b=c"}));
  EXPECT_EQ(*parse_options("run", {"x", "--out", "-h"}).out_dir, "-h");
  EXPECT_EQ(*parse_options("run", {"x", "--out=--seed=5"}).out_dir, "--seed=5");
  EXPECT_EQ(parse_options("describe", {"-"}).scenario, "-");
}

TEST(CliGrammar, TheFirstBadWordIsReported) {
  EXPECT_EQ(refusal("run", {"x", "--bogus", "--seed", "y"}),
            "unknown option '--bogus' for 'run' (see 'adcs-sim help')");
  EXPECT_EQ(refusal("run", {"x", "--seed", "y", "--bogus"}),
            "--seed must be a non-negative integer, got 'y'");
  EXPECT_EQ(refusal("run", {"x", "extra", "--seed"}),
            "unexpected argument 'extra' (one scenario at a time)");
  EXPECT_EQ(refusal("run", {"x", "--seed"}), "option --seed needs a value");
  EXPECT_EQ(refusal("run", {"x", "--seed", "1", "--seed=2"}), "--seed given twice");
  EXPECT_EQ(refusal("montecarlo", {"x", "--seed=1"}),
            "montecarlo takes --seed0 S (each run's seed is drawn from S and its index), not --seed");
  EXPECT_EQ(refusal("describe", {"x", "--runs", "2"}),
            "option --runs belongs to 'montecarlo', not 'describe'");
  // --help skips only what needs the whole line; a bad word still counts.
  EXPECT_TRUE(parse_options("montecarlo", {"--help"}).help);
  EXPECT_EQ(refusal("run", {"--help", "--bogus"}),
            "unknown option '--bogus' for 'run' (see 'adcs-sim help')");
  EXPECT_EQ(refusal("run", {"x"}), "(accepted)");
  EXPECT_EQ(refusal("run", {}), "'run' needs a scenario NAME or a vehicle FILE");
  EXPECT_EQ(refusal("run", {"x", "--jobs", "2"}), "option --jobs belongs to 'montecarlo', not 'run'");
  EXPECT_EQ(refusal("montecarlo", {"x", "--runs", "2", "--shard", "2/2"}), "--shard 2/2: the index must be in 0..1");
  EXPECT_EQ(refusal("montecarlo", {"x", "--runs", "2", "--shard", "1"}), "--shard expects i/N, auto or auto/N, got '1'");
  EXPECT_EQ(refusal("montecarlo", {"x", "--runs", "2", "--jobs", "0"}), "--jobs must be between 1 and 1024, got 0");
  EXPECT_EQ(refusal("merge", {}), "'merge' needs the directories of the shard logs (DIR...)");
  EXPECT_EQ(refusal("merge", {"a", "b", "--out", "c"}), "(accepted)");
  EXPECT_EQ(refusal("montecarlo", {"x"}), "montecarlo needs --runs R");
  EXPECT_EQ(refusal("frobnicate", {}), "unknown command 'frobnicate' (see 'adcs-sim help')");
}

}  // namespace
using namespace ADCS_UNITY_ID;  // as an anonymous namespace would (CMakeLists.txt, adcs_unity)
}  // namespace adcs::sim::cli
