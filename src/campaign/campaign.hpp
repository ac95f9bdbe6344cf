#pragma once
// A Monte Carlo campaign (issue 18): runs 0 .. runs-1 of one scenario (registered, or a vehicle
// file), each with its dispersed parameters drawn from (seed0, run, key) (seeding.hpp), over
// --jobs worker threads, one shard of a split campaign (--shard i/N: the runs k with
// k mod N = i), durably (campaign_log.hpp: every finished run is on disk before the next is
// counted) and resumably. An unsplit campaign ends by writing its tables (finalize.hpp); the
// shards of a split one are joined by merge_campaign(), giving the same bytes.
#include <cstdint>
#include <filesystem>
#include <iosfwd>
#include <string>
#include <utility>
#include <vector>

#include "campaign/campaign_log.hpp"
#include "campaign/dispersion.hpp"
#include "campaign/finalize.hpp"
#include "campaign/series.hpp"
#include "scenarios/scenario.hpp"

namespace adcs::sim::campaign {

//! What is run: identical for every shard of a campaign (it is the campaign's identity).
struct CampaignPlan {
  const Scenario* scenario = nullptr;
  std::string name;        //!< output stem NAME (the scenario's or the file's name)
  std::string run_target;  //!< what `adcs-sim run` takes to rerun one run: the name or the file path
  std::string source_id;   //!< "registered", or the vehicle file's content hash (shards must agree)
  ParamSet params;         //!< declared, with the campaign's --set applied: the nominal values
  std::vector<std::pair<std::string, std::string>> sets;  //!< --set, in order
  std::vector<Dispersion> dispersions;                     //!< --disperse, in order
  std::uint64_t runs = 0, seed0 = 1;
  std::vector<std::string> series;  //!< time-series columns to keep for envelopes (may be empty)
  std::size_t series_samples = 400; //!< per run, at most (evenly decimated)
  std::string rank_metric;          //!< the metric the "worst runs" are ranked by (empty: the first)
};

//! How this process runs its part.
struct ExecOptions {
  unsigned jobs = 1;
  std::uint64_t shard_index = 0, shard_count = 1;
  bool resume = false;
  std::filesystem::path out_dir = "out";
  std::ostream* progress = nullptr;  //!< stderr: runs done / total, failures, ETA
  bool progress_is_terminal = false;
};

struct CampaignCounts {
  std::uint64_t ok = 0, invalid = 0, failed = 0, resumed = 0;
  FinalizeResult tables;  //!< the tables written at the end of an unsplit campaign (empty for a shard)
};

//! The campaign's identity (what every shard's log header holds).
Json campaign_identity(const CampaignPlan& plan);

//! One run, alone: the draws, the scenario run, its metrics, claims and series. Never throws for
//! a run's own failure (recorded in the row); `series` receives the chosen columns when asked.
RunRow execute_run(const CampaignPlan& plan, std::uint64_t run, SeriesRecord* series);

//! Checks a plan before anything runs (throws ParamError: an unknown or unfit dispersion key,
//! runs = 0, a shard outside its range, an unknown series column or rank metric is found by the
//! first run).
void check_plan(const CampaignPlan& plan, const ExecOptions& exec);

//! Runs this shard's missing runs and, for an unsplit campaign, writes the tables. Throws
//! ParamError for a plan or resume mismatch (nothing run), std::runtime_error for I/O.
CampaignCounts run_campaign(const CampaignPlan& plan, const ExecOptions& exec);

}  // namespace adcs::sim::campaign
