#pragma once
// The members of adcs-sim's JSON outputs (docs/CONTRACTS.md, "Output files"), each in output
// order; cmd_run.cpp and cmd_montecarlo.cpp put them together, json_text() writes them.
#include <string>
#include <utility>
#include <vector>

#include "cli/json_text.hpp"
#include "scenarios/scenario.hpp"

namespace adcs::sim::cli {

//! "parameters": every declared parameter {"value", "unit", "source"}; after --set also
//! "default" and "default_source". A value the run reports in `used` replaces the declared
//! "value" (its "source" says how it was obtained; the declared value moves to "declared" /
//! "declared_source"); used values of undeclared keys follow the declared ones.
Json parameters_json(const ParamSet& ps, const std::vector<UsedValue>& used = {});

//! "metrics": name -> number (null when not finite), in the run's order.
Json metrics_json(const std::vector<std::pair<std::string, double>>& metrics);

//! "claims": {"kind", "claim", "paper_value", "ours", "paper_verdict", "criterion",
//! "criterion_holds", "holds"[, "note"]} each.
Json claims_json(const std::vector<Claim>& claims);

//! "plots": {"file", "title", "x", "y", "ylabel", "logy"[, "fill", "csv", "kind", "hline"]}.
Json plots_json(const std::vector<PlotSpec>& plots);

//! Monte Carlo "metrics": per name {"min", "median", "max"} over the finite values of its
//! column (null if none), and "nonfinite": their count when there are any.
Json summary_json(const std::vector<std::string>& names,
                  const std::vector<std::vector<double>>& columns);

}  // namespace adcs::sim::cli
