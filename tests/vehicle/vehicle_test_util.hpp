#pragma once
// Helpers of the vehicle-file tests: the example files' paths, a vehicle file written from a
// string (with lines replaced or removed), loading and running one with --set overrides.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <memory>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "../scenarios/scenario_test_util.hpp"
#include "scenarios/params.hpp"
#include "scenarios/scenario.hpp"
#include "vehicle/vehicle_scenario.hpp"

namespace adcs::sim::test {

inline std::string example_path(const std::string& file) {
  return std::string(ADCS_SOURCE_DIR) + "/examples/vehicles/" + file;
}

inline std::string read_text(const std::string& path) {
  std::ifstream in(path);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

//! Writes `text` to DIR/name and returns the path.
inline std::string write_file(const std::filesystem::path& dir, const std::string& name, const std::string& text) {
  const std::filesystem::path p = dir / name;
  std::ofstream(p) << text;
  return p.string();
}

//! The text with every line that starts with `prefix` replaced by `replacement` (fails unless
//! exactly one line matched).
inline std::string replace_line(const std::string& text, const std::string& prefix, const std::string& replacement) {
  std::istringstream in(text);
  std::string out, line;
  int n = 0;
  while (std::getline(in, line)) {
    if (line.rfind(prefix, 0) == 0) {
      ++n;
      line = replacement;
    }
    out += line + "\n";
  }
  EXPECT_EQ(n, 1) << "lines starting with '" << prefix << "'";
  return out;
}

//! The text without the tables whose header starts with one of `prefixes` (e.g. "[sensors"):
//! the header and every line up to the next table header.
inline std::string drop_tables(const std::string& text, const std::vector<std::string>& prefixes) {
  std::istringstream in(text);
  std::string out, line;
  bool dropping = false;
  while (std::getline(in, line)) {
    if (!line.empty() && line[0] == '[') {
      dropping = false;
      for (const std::string& p : prefixes) dropping = dropping || line.rfind(p, 0) == 0;
    }
    if (!dropping) out += line + "\n";
  }
  return out;
}

//! The 1-based line of the first line starting with `prefix`.
inline int line_of(const std::string& text, const std::string& prefix) {
  std::istringstream in(text);
  std::string line;
  for (int n = 1; std::getline(in, line); ++n)
    if (line.rfind(prefix, 0) == 0) return n;
  ADD_FAILURE() << "no line starts with '" << prefix << "'";
  return 0;
}

struct LoadedVehicle {
  std::unique_ptr<Scenario> scenario;
  ParamSet params;
};

inline LoadedVehicle load(const std::string& path, const std::vector<std::pair<std::string, std::string>>& sets = {}) {
  LoadedVehicle v{vehicle::load_vehicle_file(path), {}};
  v.scenario->declare(v.params);
  for (const auto& [k, text] : sets) v.params.set(k, text);
  return v;
}

inline RunResult run_file(const std::string& path, const std::vector<std::pair<std::string, std::string>>& sets = {},
                          std::uint64_t seed = 0, const std::string& csv = {}) {
  LoadedVehicle v = load(path, sets);
  RunContext ctx;
  ctx.seed = seed;
  ctx.quiet = true;
  ctx.csv_path = csv;
  return v.scenario->run(v.params, ctx);
}

}  // namespace adcs::sim::test
