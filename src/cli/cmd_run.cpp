// adcs-sim run NAME: one run; writes DIR/NAME.csv (time series, written by the scenario),
// DIR/NAME.json and the run's extra tables, all or none; the last stdout line is the summary.
#include <memory>
#include <ostream>

#include "cli/command_line.hpp"
#include "cli/command_table.hpp"
#include "cli/commands.hpp"
#include "cli/progress.hpp"
#include "cli/run_json.hpp"
#include "cli/scenario_runs.hpp"
#include "sim/recorder.hpp"

namespace adcs::sim::cli {
namespace ADCS_UNITY_ID {

//! Writes each extra table of a run to its temporary file (same CSV format as the time series).
std::vector<std::unique_ptr<TempFile>> write_tables(const RunResult& r, OutputDir& dir) {
  std::vector<std::unique_ptr<TempFile>> files;
  for (const Table& t : r.tables) {
    if (t.names.size() != t.units.size() || t.names.size() != t.columns.size() || t.columns.empty())
      throw RunFailure("table " + t.file + ": names, units and columns disagree");
    files.push_back(std::make_unique<TempFile>(dir.path(), t.file));
    std::vector<sim::Column> cols;
    for (std::size_t i = 0; i < t.names.size(); ++i) cols.push_back({t.names[i], t.units[i]});
    sim::CsvRecorder rec(files.back()->temp_path(), cols);
    const std::size_t n = t.columns.front().size();
    std::vector<double> row(cols.size());
    for (std::size_t k = 0; k < n; ++k) {
      for (std::size_t c = 0; c < cols.size(); ++c) row[c] = t.columns[c].at(k);
      if (k + 1 == n) rec.record_final(row.data()); else rec.record(row.data());
    }
    rec.close();
  }
  return files;
}

}  // namespace
using namespace ADCS_UNITY_ID;  // as an anonymous namespace would (CMakeLists.txt, adcs_unity)

void declare_run(CommandLine& cl, Options& o) {
  declare_scenario_name(cl, o);
  declare_sets(cl, o);
  cl.once("--seed", [&o](const std::string& v) { o.seed = parse_uint("--seed", v); });
  declare_out(cl, o);
  declare_progress(cl, o);
  declare_montecarlo_only(cl, "run");
}

int cmd_run(const Options& o, const CommandIo& io) {
  const Scenario& s = lookup(io.catalog, o.scenario);
  const ParamSet ps = declared_params(s, o.sets);
  const std::uint64_t seed = o.seed.value_or(0);

  OutputDir dir(o.out_dir.value_or("out"));
  TempFile csv(dir.path(), s.name() + ".csv");
  TempFile json(dir.path(), s.name() + ".json");

  ProgressReporter progress(io.err, s.name(), o.progress, io.err_is_terminal);
  RunContext ctx;
  ctx.csv_path = csv.temp_path();
  ctx.seed = seed;
  ctx.quiet = false;
  if (progress.enabled())
    ctx.progress = [&progress](double t0, double t, double t_end) {
      progress.update(t0, t, t_end);
    };
  const RunResult r = run_scenario(s, ps, ctx);
  progress.finish();
  if (!csv.temp_exists())
    throw RunFailure("scenario '" + s.name() + "' did not write its time series to " +
                     ctx.csv_path);

  Json doc = Json::object();
  doc["scenario"] = s.name();
  doc["seed"] = seed;
  doc["description"] = s.description();
  doc["parameters"] = parameters_json(ps, r.used);
  doc["metrics"] = metrics_json(r.metrics);
  doc["claims"] = claims_json(r.claims);
  doc["plots"] = plots_json(r.plots);
  doc["csv"] = s.name() + ".csv";
  json.write(json_text(doc, /*pretty_depth=*/2) + "\n");

  const std::vector<std::unique_ptr<TempFile>> tables = write_tables(r, dir);
  commit_outputs(csv, json, dir, tables);

  Json line = Json::object();
  line["scenario"] = s.name();
  line["seed"] = seed;
  line["metrics"] = metrics_json(r.metrics);
  io.out << "wrote " << csv.final_path() << " and " << json.final_path() << '\n';
  io.out << json_text(line) << std::endl;
  return kExitOk;
}

}  // namespace adcs::sim::cli
