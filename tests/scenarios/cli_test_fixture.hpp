#pragma once
// The fixture the adcs-sim command tests share: a fresh directory per test, a scenario catalogue
// the test fills in SetUp(), and run_cli() with stdout and stderr captured.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>
#include <vector>

#include "cli/commands.hpp"
#include "scenario_test_util.hpp"

namespace adcs::sim::test {

class CliFixture : public ::testing::Test {
 protected:
  //! Call from the derived SetUp(): an empty directory for this test.
  void make_root(const std::string& prefix) { root_ = fresh_test_dir(prefix); }
  void TearDown() override { std::filesystem::remove_all(root_); }

  //! adcs-sim with `args` on the catalogue; stdout and stderr go to out_ and err_.
  int cli(std::vector<std::string> args) {
    out_.str("");
    err_.str("");
    return cli::run_cli(args, catalog_, out_, err_);
  }
  std::string dir(const std::string& sub = "out") const { return (root_ / sub).string(); }
  static std::string slurp(const std::filesystem::path& p) {
    std::ifstream f(p);
    return std::string(std::istreambuf_iterator<char>(f), {});
  }

  cli::Catalog catalog_;
  std::filesystem::path root_;
  std::ostringstream out_, err_;
};

}  // namespace adcs::sim::test
