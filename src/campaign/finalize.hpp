#pragma once
// A campaign's tables, from its logs (issue 18): DIR/NAME-montecarlo.csv (one row per run,
// sorted by run index: `run`, the drawn values, the metrics, then status, seed and error),
// DIR/NAME-montecarlo.json (the campaign, its counts, per-metric statistics, per-claim pass
// counts, the worst runs and every failed run with the one command that reruns it alone) and,
// when time series were kept, DIR/NAME-montecarlo-series.h5 (percentile envelopes). Built only
// from the rows sorted by run index, so an unsplit campaign and the merge of its shards write
// the same bytes.
#include <filesystem>
#include <string>
#include <vector>

#include "campaign/campaign_log.hpp"

namespace adcs::sim::campaign {

struct FinalizeResult {
  std::string name, csv_path, json_path, series_path;  //!< series_path empty: no series
  Json summary_line;                                   //!< the one-line stdout summary
};

//! Finds the logs of one campaign in `dirs` (an unsplit log, or every shard's), checks they make
//! one whole campaign, and writes its tables to `out_dir`. `name` empty: any campaign found
//! (there must be exactly one). Throws ParamError when the logs do not make one campaign:
//! shards of different campaigns, a shard missing or given twice, a run missing or in two
//! shards, no log at all; std::runtime_error for I/O. Nothing is written when it throws.
FinalizeResult finalize_from_dirs(const std::vector<std::filesystem::path>& dirs,
                                  const std::filesystem::path& out_dir, const std::string& name = "");

//! Shell-quoted `adcs-sim run` command that reruns one run alone (its seed, the campaign's
//! --set, the run's drawn values as --set).
std::string rerun_command(const Json& identity, const RunRow& row);

}  // namespace adcs::sim::campaign
