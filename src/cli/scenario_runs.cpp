#include "cli/scenario_runs.hpp"

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include "vehicle/vehicle_scenario.hpp"

#include <algorithm>
#include <cmath>
#include <exception>
#include <set>

#include "cli/command_table.hpp"
#include "cli/commands.hpp"
#include "cli/json_text.hpp"
#include "sim/sampled_data.hpp"

namespace adcs::sim::cli {
namespace ADCS_UNITY_ID {

void check_metrics(const Scenario& s, const RunResult& r) {
  std::set<std::string> seen;
  for (const auto& [name, value] : r.metrics) {
    (void)value;
    const bool bad = name.empty() || std::any_of(name.begin(), name.end(), [](char c) {
                       return c == ',' || c == '"' || static_cast<unsigned char>(c) < 0x20;
                     });
    if (bad)
      throw RunFailure("scenario '" + s.name() + "' returned an invalid metric name '" + name +
                       "'");
    if (!seen.insert(name).second)
      throw RunFailure("scenario '" + s.name() + "' returned metric '" + name + "' twice");
  }
}

}  // namespace
using namespace ADCS_UNITY_ID;  // as an anonymous namespace would (CMakeLists.txt, adcs_unity)

bool is_vehicle_file(const std::string& name) {
  return name.find('/') != std::string::npos || (name.size() > 5 && name.compare(name.size() - 5, 5, ".toml") == 0);
}

const Scenario& lookup(const Catalog& catalog, const std::string& name) {
  if (const Scenario* s = catalog.find(name)) return *s;
  if (is_vehicle_file(name) || std::filesystem::is_regular_file(name)) {
    // A vehicle file (docs/VEHICLE-FILES.md), loaded once per process and kept for its lifetime
    // (the commands hold the Scenario by reference). Its errors are ParamErrors naming FILE:LINE.
    static std::map<std::string, std::unique_ptr<Scenario>> loaded;
    auto& slot = loaded[name];
    if (!slot) slot = vehicle::load_vehicle_file(name);
    return *slot;
  }
  throw UsageError("unknown scenario '" + name + "' (see '" + kProg + " list', or give a vehicle file)");
}

std::string target_source_id(const std::string& name) {
  if (!is_vehicle_file(name) && !std::filesystem::is_regular_file(name)) return "registered";
  std::ifstream in(name, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  const std::string text = ss.str();
  std::uint64_t h = 0xcbf29ce484222325ULL;  // FNV-1a: the file's content, not its path
  for (char c : text) {
    h ^= static_cast<unsigned char>(c);
    h *= 0x100000001b3ULL;
  }
  char buf[32];
  std::snprintf(buf, sizeof buf, "file:%016llx", static_cast<unsigned long long>(h));
  return buf;
}

ParamSet declared_params(const Scenario& s,
                         const std::vector<std::pair<std::string, std::string>>& sets) {
  ParamSet ps;
  s.declare(ps);
  for (const auto& [key, text] : sets) {
    try {
      ps.set(key, text);
    } catch (const ParamError& e) {
      throw ParamError(std::string(e.what()) + " (see '" + kProg + " describe " + s.name() +
                       "')");
    }
  }
  check_run_parameters(ps);
  return ps;
}

RunResult run_scenario(const Scenario& s, const ParamSet& ps, const RunContext& ctx) {
  RunResult r;
  try {
    const ProgressScope progress(ctx.progress);
    r = s.run(ps, ctx);
  } catch (const ParamError&) {
    throw;  // an invalid value the scenario detected: exit 2
  } catch (const std::exception& e) {
    throw RunFailure("scenario '" + s.name() + "' failed (seed " + std::to_string(ctx.seed) +
                     "): " + e.what());
  } catch (...) {
    throw RunFailure("scenario '" + s.name() + "' failed (seed " + std::to_string(ctx.seed) +
                     "): unknown exception");
  }
  check_metrics(s, r);
  return r;
}

void commit_outputs(TempFile& csv, TempFile& json, OutputDir& dir,
                    const std::vector<std::unique_ptr<TempFile>>& extra) {
  csv.commit();
  std::size_t done = 0;
  try {
    for (; done < extra.size(); ++done) extra[done]->commit();
    json.commit();
  } catch (...) {
    for (std::size_t i = 0; i < done; ++i) extra[i]->uncommit();
    csv.uncommit();
    throw;
  }
  dir.keep();
}

std::string csv_number(double x) {
  if (std::isnan(x)) return "nan";
  if (std::isinf(x)) return x > 0 ? "inf" : "-inf";
  return json_number(x);
}

}  // namespace adcs::sim::cli
