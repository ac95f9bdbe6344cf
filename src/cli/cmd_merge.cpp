// adcs-sim merge DIR... [--out DIR]: joins the shard logs of one campaign (issue 18,
// docs/CAMPAIGNS.md) into DIR/NAME-montecarlo.csv, .json and -series.h5 — the same bytes the
// unsplit campaign writes — or refuses (exit 2, nothing written): shards of different campaigns,
// a shard missing or given twice, a run missing or recorded twice.
#include <ostream>

#include "campaign/finalize.hpp"
#include "cli/command_line.hpp"
#include "cli/command_table.hpp"
#include "cli/commands.hpp"
#include "cli/json_text.hpp"
#include "cli/scenario_runs.hpp"

namespace adcs::sim::cli {

void declare_merge(CommandLine& cl, Options& o) {
  cl.positionals("DIR", "the directories of the shard logs (DIR...)", o.dirs);
  declare_out(cl, o);
  declare_montecarlo_only(cl, "merge");
}

int cmd_merge(const Options& o, const CommandIo& io) {
  std::vector<std::filesystem::path> dirs(o.dirs.begin(), o.dirs.end());
  campaign::FinalizeResult r;
  try {
    r = campaign::finalize_from_dirs(dirs, o.out_dir.value_or(o.dirs.front()));
  } catch (const ParamError&) {
    throw;
  } catch (const std::runtime_error& e) {
    throw IoError(e.what());
  }
  io.out << "wrote " << r.csv_path << " and " << r.json_path << (r.series_path.empty() ? "" : " and " + r.series_path) << '\n';
  io.out << json_text(r.summary_line) << std::endl;
  return kExitOk;
}

}  // namespace adcs::sim::cli
