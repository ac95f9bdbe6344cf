#pragma once
// The scenario interface (ground code). A scenario declares every parameter it reads (with
// default, unit and source), runs, and returns metrics, claim rows for out/REPORT.md and plot
// specifications for tools/plot.py. Scenarios are listed in src/scenarios/registry.cpp.
//
// Rules a scenario follows (adcs-sim relies on them):
//  - declare() declares at least `duration_s` and `control_period_s` (numbers, seconds).
//  - run() reads parameters only through the ParamSet, uses ctx.seed for all randomness,
//    writes its time series to ctx.csv_path (a temporary file adcs-sim renames into place)
//    unless ctx.csv_path is empty, and prints nothing to stdout when ctx.quiet.
//  - run() throws ParamError for an invalid parameter value (adcs-sim exits 2) and any other
//    exception for a simulation failure (adcs-sim exits 1). Either way no output is kept.
//  - Every value run() uses that is not the declared one (a --seed draw, a derived value)
//    goes into RunResult::used, so the run's JSON holds every value actually used.
#include <cstdint>
#include <functional>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <Eigen/Core>

#include "scenarios/params.hpp"

namespace adcs::sim {

//! How a run compares with a paper's own number or statement (issue 16): judged against the
//! paper's words, never against a criterion of ours.
enum class PaperVerdict { reproduced, partly, not_reproduced };

inline const char* to_string(PaperVerdict v) noexcept {
  switch (v) {
    case PaperVerdict::reproduced: return "reproduced";
    case PaperVerdict::partly: return "partly";
    case PaperVerdict::not_reproduced: return "not reproduced";
  }
  return "?";
}

//! One row of the claims table: a paper claim ("paper") or a check of ours ("check").
//! Two verdicts, never blurred (issue 16):
//!  - `paper_verdict` (paper rows): the run against `paper_value`, the paper's own number or
//!    statement, quoted;
//!  - `holds` (JSON "criterion_holds"): the run against our documented `criterion` (with its
//!    source: spec, prototype, physics); for checks `paper_value` is the requirement itself.
//! Either is empty when the row is informative only. `note` says what a reader must know to
//! weigh the row, e.g. that a baseline meets the criterion too ("not discriminating").
struct Claim {
  std::string kind;  // "paper" or "check"
  std::string claim, paper_value, ours;
  std::optional<bool> holds;
  std::optional<PaperVerdict> paper_verdict = std::nullopt;
  std::string criterion = {};
  std::string note = {};
};

//! One figure tools/plot.py draws from the run's CSV: columns `y` against column `x`.
struct PlotSpec {
  std::string file, title, x = "t";
  std::vector<std::string> y;
  std::string ylabel;
  bool logy = false;
  //! Shaded bands between two columns (lo, hi), e.g. prescribed-performance funnels.
  std::vector<std::pair<std::string, std::string>> fill = {};
  //! Read the columns from this extra table (RunResult::tables) instead of the time series.
  std::string csv = {};
  //! "psd": log-log axes for spectra; "points": markers only (sparse event columns); empty: lines.
  std::string kind = {};
  //! Horizontal reference lines (value, label), e.g. a requirement.
  std::vector<std::pair<double, std::string>> hline = {};
};

//! A small extra table a run writes next to its time series (e.g. a spectrum), DIR/file.
struct Table {
  std::string file;                          //!< e.g. "dragfree-adrc-asd.csv"
  std::vector<std::string> names, units;     //!< one per column
  std::vector<std::vector<double>> columns;  //!< equal lengths
};

struct RunContext {
  //! Where the scenario writes its time series (a temporary path); empty => don't write one.
  std::string csv_path;
  std::uint64_t seed = 0;
  //! Monte Carlo runs: no chatter on stdout.
  bool quiet = false;
  //! Progress sink (adcs-sim --progress): (t0, t, t_end) [s] of the simulation loop. adcs-sim
  //! installs it around run() as the hook of the shared sampled-data loop (ProgressScope in
  //! sim/sampled_data.hpp), so scenarios need not call it; one with its own loop may.
  std::function<void(double t0_s, double t_s, double t_end_s)> progress;
};

//! A value a run actually used in place of, or in addition to, the declared parameters: e.g.
//! the initial attitude drawn from --seed. adcs-sim writes it into the JSON "parameters" (over
//! the declared value of the same key, which is kept as "declared").
struct UsedValue {
  std::string key;
  ParamKind kind = ParamKind::number;
  ParamValue value;    //!< only the member of `kind` is meaningful
  std::string unit;
  std::string source;  //!< how it was obtained, e.g. "drawn from --seed 3: ..."

  static UsedValue number(std::string key, double x, std::string unit, std::string source) {
    UsedValue u{std::move(key), ParamKind::number, {}, std::move(unit), std::move(source)};
    u.value.number = x;
    return u;
  }
  static UsedValue vector(std::string key, std::vector<double> v, std::string unit,
                          std::string source) {
    UsedValue u{std::move(key), ParamKind::vector, {}, std::move(unit), std::move(source)};
    u.value.vector = std::move(v);
    return u;
  }
  //! Rows of an Eigen matrix (any fixed size).
  template <class Derived>
  static UsedValue matrix(std::string key, const Eigen::MatrixBase<Derived>& m, std::string unit,
                          std::string source) {
    UsedValue u{std::move(key), ParamKind::matrix, {}, std::move(unit), std::move(source)};
    for (Eigen::Index i = 0; i < m.rows(); ++i) {
      std::vector<double> row;
      for (Eigen::Index j = 0; j < m.cols(); ++j) row.push_back(m(i, j));
      u.value.matrix.push_back(std::move(row));
    }
    return u;
  }
  static UsedValue name(std::string key, std::string value, std::string source) {
    UsedValue u{std::move(key), ParamKind::name, {}, "", std::move(source)};
    u.value.name = std::move(value);
    return u;
  }
};

struct RunResult {
  std::vector<std::pair<std::string, double>> metrics;  // ordered; non-finite => JSON null
  std::vector<Claim> claims;
  std::vector<PlotSpec> plots;
  std::vector<Table> tables;  //!< extra CSV files (written atomically with the run's outputs)
  //! Values used other than the declared ones (--seed draws, derived values); see UsedValue.
  //! Empty when the run used exactly the declared parameters (e.g. seed 0).
  std::vector<UsedValue> used;

  //! The metric's value; NaN when there is no metric of that name (see has_metric).
  double metric(const std::string& name) const {
    for (const auto& [k, v] : metrics)
      if (k == name) return v;
    return std::numeric_limits<double>::quiet_NaN();
  }
  bool has_metric(const std::string& name) const {
    for (const auto& kv : metrics)
      if (kv.first == name) return true;
    return false;
  }
};

class Scenario {
 public:
  virtual ~Scenario() = default;
  //! Lower-case letters, digits and '-' (used in file names).
  virtual std::string name() const = 0;
  virtual std::string description() const = 0;
  //! Every parameter, with default, unit and source.
  virtual void declare(ParamSet& params) const = 0;
  //! May throw (see the rules above).
  virtual RunResult run(const ParamSet& params, const RunContext& ctx) const = 0;
};

}  // namespace adcs::sim
