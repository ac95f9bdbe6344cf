#pragma once
// What run and montecarlo share: finding the scenario, its parameters after --set, one run with
// its failures sorted into exit statuses, and committing the output files together.
#include <memory>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "cli/atomic_file.hpp"
#include "scenarios/scenario.hpp"

namespace adcs::sim::cli {

struct Catalog;

//! A failure of the scenario's run() or of its result (exit 1).
struct RunFailure : std::runtime_error {
  using runtime_error::runtime_error;
};

//! The scenario named `name`, or the vehicle file at path `name` (a path with '/' or ending in
//! .toml; vehicle/vehicle_scenario.hpp); UsageError if there is neither, ParamError
//! ("FILE:LINE: ...") for a bad file.
const Scenario& lookup(const Catalog& catalog, const std::string& name);

//! "registered" for a registered scenario; "file:<hash of its content>" for a vehicle file (so
//! the shards of a campaign agree on the vehicle whatever path each was given).
std::string target_source_id(const std::string& name);

//! The scenario's declared parameters with the --set values applied and checked
//! (check_run_parameters); ParamError naming the key.
ParamSet declared_params(const Scenario& s,
                         const std::vector<std::pair<std::string, std::string>>& sets);

//! s.run() with ctx.progress installed around it; a ParamError passes (exit 2), any other
//! exception becomes a RunFailure naming the scenario and seed, as do invalid or repeated
//! metric names.
RunResult run_scenario(const Scenario& s, const ParamSet& ps, const RunContext& ctx);

//! Renames the CSV, the extra files and the JSON into place together: if one cannot be
//! committed, those already renamed are taken back, so a run leaves all its files or none.
void commit_outputs(TempFile& csv, TempFile& json, OutputDir& dir,
                    const std::vector<std::unique_ptr<TempFile>>& extra = {});

//! A CSV number: as in JSON, but nan, inf and -inf spelled out.
std::string csv_number(double x);

}  // namespace adcs::sim::cli
