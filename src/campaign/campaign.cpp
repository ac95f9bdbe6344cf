#include "campaign/campaign.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <condition_variable>
#include <cstdio>
#include <memory>
#include <mutex>
#include <ostream>
#include <set>
#include <thread>

#include "campaign/finalize.hpp"
#include "campaign/seeding.hpp"
#include "sim/recorder.hpp"

namespace adcs::sim::campaign {
namespace ADCS_UNITY_ID {

namespace fs = std::filesystem;

std::string one_line(std::string s) {
  for (char& c : s)
    if (c == '\n' || c == '\r' || c == '\t') c = ' ';
  return s;
}

//! Progress on stderr: runs done / total, failures, ETA; at most once a second (a terminal line
//! is rewritten in place), and a last line at the end.
class Progress {
 public:
  Progress(std::ostream* out, bool terminal, std::uint64_t total, std::uint64_t already)
      : out_(out), terminal_(terminal), total_(total), done_(already), base_(already),
        start_(std::chrono::steady_clock::now()), last_(start_) {}
  void add(const RunRow& r, bool final = false) {
    if (r.status == RunStatus::invalid) ++invalid_;
    if (r.status == RunStatus::failed) ++failed_;
    ++done_;
    report(final);
  }
  void report(bool final) {
    if (!out_) return;
    const auto now = std::chrono::steady_clock::now();
    if (!final && now - last_ < std::chrono::seconds(1) && done_ < total_) return;
    last_ = now;
    const double elapsed = std::chrono::duration<double>(now - start_).count();
    const std::uint64_t fresh = done_ - base_;
    const double eta = fresh > 0 ? elapsed / static_cast<double>(fresh) * static_cast<double>(total_ - done_) : NAN;
    char buf[200];
    std::snprintf(buf, sizeof buf, "[%llu/%llu runs] %llu invalid, %llu failed, %.0f s elapsed, ETA %s",
                  static_cast<unsigned long long>(done_), static_cast<unsigned long long>(total_),
                  static_cast<unsigned long long>(invalid_), static_cast<unsigned long long>(failed_), elapsed,
                  std::isfinite(eta) ? (std::to_string(static_cast<long long>(std::lround(eta))) + " s").c_str() : "-");
    if (terminal_) *out_ << '\r' << buf << "\x1b[K" << (done_ == total_ ? "\n" : "");
    else *out_ << buf << '\n';
    out_->flush();
  }

 private:
  std::ostream* out_;
  bool terminal_;
  std::uint64_t total_, done_, base_, invalid_ = 0, failed_ = 0;
  std::chrono::steady_clock::time_point start_, last_;
};

Json parameters_json(const ParamSet& ps) {
  Json j = Json::object();
  for (const Param& p : ps) {
    Json e;
    e["value"] = format_value(p);
    if (!p.unit.empty()) e["unit"] = p.unit;
    e["source"] = p.overridden ? "--set" : p.source;
    j[p.key] = e;
  }
  return j;
}

}  // namespace
using namespace ADCS_UNITY_ID;  // as an anonymous namespace would (CMakeLists.txt, adcs_unity)

Json campaign_identity(const CampaignPlan& plan) {
  Json id;
  id["scenario"] = plan.name;
  id["run_target"] = plan.run_target;
  id["source_id"] = plan.source_id;
  id["description"] = plan.scenario ? plan.scenario->description() : "";
  Json sets = Json::array();
  for (const auto& [k, v] : plan.sets) sets.push_back(k + "=" + v);
  id["sets"] = sets;
  Json disp = Json::array();
  for (const auto& d : plan.dispersions) disp.push_back(d.key + "=" + d.text);
  id["dispersions"] = disp;
  id["seed0"] = plan.seed0;
  id["runs"] = plan.runs;
  id["series"] = plan.series;
  id["series_samples"] = plan.series_samples;
  id["rank_metric"] = plan.rank_metric;
  id["parameters"] = parameters_json(plan.params);
  return id;
}

RunRow execute_run(const CampaignPlan& plan, std::uint64_t run, SeriesRecord* series) {
  RunRow row;
  row.run = run;
  row.seed = run_seed(plan.seed0, run);
  ParamSet ps = plan.params;
  std::string invalid;
  for (const Dispersion& d : plan.dispersions) {
    const DrawnValue v = draw(d, plan.params, plan.seed0, run);
    const std::vector<std::string> names = element_names(v);
    const std::vector<double> values = element_values(v);
    row.drawn_names.insert(row.drawn_names.end(), names.begin(), names.end());
    row.drawn_values.insert(row.drawn_values.end(), values.begin(), values.end());
    if (invalid.empty()) {
      if (const auto problem = physical_problem(d, v, plan.params.at(d.key))) {
        invalid = *problem;
        continue;
      }
      const std::string text = format_value(v.kind, v.value);
      row.drawn_sets.push_back(d.key + "=" + text);
      try {
        ps.set(d.key, text);
      } catch (const ParamError& e) {
        invalid = e.what();
      }
    }
  }
  if (!invalid.empty()) {
    row.status = RunStatus::invalid;
    row.error = one_line(invalid);
    return row;
  }
  RowCapture capture;
  RunContext ctx;
  ctx.seed = row.seed;
  ctx.quiet = true;
  if (series && !plan.series.empty()) {
    // The run's time series goes nowhere; only the chosen columns are kept (RowCapture).
    ctx.csv_path = "/dev/null";
    capture.path = ctx.csv_path;
    capture.columns = {"t"};
    capture.columns.insert(capture.columns.end(), plan.series.begin(), plan.series.end());
  }
  try {
    RowCaptureScope scope(capture);
    const RunResult r = plan.scenario->run(ps, ctx);
    row.metrics = r.metrics;
    for (const Claim& c : r.claims) row.claims.push_back({c.kind, c.claim, c.holds});
    if (series && !plan.series.empty()) {
      if (!capture.opened) throw ParamError("--series: " + plan.name + " writes no time series");
      if (!capture.missing.empty()) {
        std::string avail;
        for (const auto& a : capture.available) avail += (avail.empty() ? "" : ", ") + a;
        throw ParamError("--series: '" + capture.missing.front() + "' is not a column of " + plan.name +
                         "'s time series (" + avail + ")");
      }
      series->run = run;
      series->t = capture.values.front();
      series->y.assign(capture.values.begin() + 1, capture.values.end());
      decimate(*series, plan.series_samples);
    }
  } catch (const ParamError& e) {
    row.status = RunStatus::invalid;
    row.error = one_line(e.what());
  } catch (const std::exception& e) {
    row.status = RunStatus::failed;
    row.error = one_line(e.what());
  }
  return row;
}

void check_plan(const CampaignPlan& plan, const ExecOptions& exec) {
  if (!plan.scenario) throw ParamError("no scenario");
  if (plan.runs == 0) throw ParamError("--runs must be >= 1");
  if (exec.shard_count == 0 || exec.shard_index >= exec.shard_count)
    throw ParamError("--shard " + std::to_string(exec.shard_index) + "/" + std::to_string(exec.shard_count) +
                     ": the index must be in 0.." + (exec.shard_count ? std::to_string(exec.shard_count - 1) : "N-1"));
  if (exec.shard_count > plan.runs)
    throw ParamError("--shard: " + std::to_string(exec.shard_count) + " shards for " + std::to_string(plan.runs) +
                     " runs (each shard needs a run)");
  if (exec.jobs == 0) throw ParamError("--jobs must be >= 1");
  std::set<std::string> keys;
  for (const Dispersion& d : plan.dispersions) {
    check_dispersion(d, plan.params);
    if (!keys.insert(d.key).second) throw ParamError("--disperse " + d.key + " given twice");
  }
}

CampaignCounts run_campaign(const CampaignPlan& plan, const ExecOptions& exec) {
  check_plan(plan, exec);
  LogHeader header;
  header.identity = campaign_identity(plan);
  header.campaign_id = campaign_id_of(header.identity);
  header.shard_index = exec.shard_index;
  header.shard_count = exec.shard_count;
  const fs::path log_path = exec.out_dir / log_file_name(plan.name, exec.shard_index, exec.shard_count);
  const fs::path series_path = exec.out_dir / series_file_name(plan.name, exec.shard_index, exec.shard_count);

  // Which runs are this shard's, and which of them are done already (resume).
  std::set<std::uint64_t> done;
  std::uint64_t valid_bytes = 0;
  const bool exists = fs::exists(log_path);
  if (exists && !exec.resume)
    throw ParamError(log_path.string() + " exists: add --resume to continue that campaign, or choose another --out");
  if (exists) {
    // Only the run indices are kept (not the rows): resuming a large campaign costs no more memory
    // than running it.
    const LogContents old = scan_log(log_path.string(), [&](RunRow&& r, const RowSpan&) { done.insert(r.run); });
    if (old.header.campaign_id != header.campaign_id || old.header.shard_count != exec.shard_count ||
        old.header.shard_index != exec.shard_index)
      throw ParamError("--resume: " + log_path.string() + " belongs to another campaign or shard (campaign " +
                       old.header.campaign_id + ", this one " + header.campaign_id + ")");
    valid_bytes = old.valid_bytes;
  }
  std::vector<std::uint64_t> pending;
  std::uint64_t mine = 0;
  for (std::uint64_t k = exec.shard_index; k < plan.runs; k += exec.shard_count) {
    ++mine;
    if (!done.count(k)) pending.push_back(k);
  }
  CampaignCounts counts;
  counts.resumed = mine - pending.size();

  // The first pending run decides whether the campaign may run at all: a series column or a
  // scenario that cannot run is refused with nothing on disk. It runs in the pool like any other
  // (run alone first, it made --jobs 2 barely faster than --jobs 1 on a campaign of a few long
  // runs): the workers start on the next runs meanwhile, and what finishes before it is decided
  // is held in memory (about kMaxHeld rows at most: a worker then waits) and logged once it passed.
  // The log's line order is completion order anyway; the tables are built sorted by run index.
  std::unique_ptr<LogWriter> log;
  std::unique_ptr<SeriesWriter> series_out;
  std::mutex mu;
  std::condition_variable gate_cv;
  Progress progress(exec.progress, exec.progress_is_terminal, mine, counts.resumed);
  const bool want_series = !plan.series.empty();
  auto record = [&](const RunRow& row, const SeriesRecord* s) {  // with mu held
    if (s && row.status == RunStatus::ok) series_out->append(*s);  // series first: an orphan record is ignored
    log->append(row);
    if (row.status == RunStatus::ok) ++counts.ok;
    if (row.status == RunStatus::invalid) ++counts.invalid;
    if (row.status == RunStatus::failed) ++counts.failed;
    progress.add(row);
  };
  // Why the first run refuses the campaign (a ParamError), or "" when it may run.
  auto refusal = [&](const RunRow& first) -> std::string {
    if (first.status == RunStatus::invalid && first.error.rfind("--series", 0) == 0) return first.error;
    // Without dispersions every run has the nominal parameters: one refused is all refused, and
    // that is a bad command line (as `run` would say), not a campaign of invalid runs.
    if (first.status == RunStatus::invalid && plan.dispersions.empty()) return first.error;
    if (first.status == RunStatus::ok && !plan.rank_metric.empty()) {
      bool found = false;
      for (const auto& m : first.metrics) found = found || m.first == plan.rank_metric;
      if (!found) return "--rank-by: " + plan.name + " has no metric '" + plan.rank_metric + "'";
    }
    return "";
  };
  if (!pending.empty()) {
    constexpr std::size_t kMaxHeld = 64;
    struct Held {
      RunRow row;
      SeriesRecord series;
    };
    std::vector<Held> held;  // finished before the first run was decided
    bool passed = false;     // the first run is decided and the campaign may run (files open)
    std::atomic<std::size_t> next{0};
    std::exception_ptr error;  // a refusal, or an I/O failure of the log: stop the campaign
    auto worker = [&] {
      for (;;) {
        {
          std::unique_lock<std::mutex> lock(mu);
          gate_cv.wait(lock, [&] { return passed || error || held.size() < kMaxHeld; });
          if (error) return;
        }
        const std::size_t i = next.fetch_add(1);  // index 0, the first pending run, is taken first
        if (i >= pending.size()) return;
        SeriesRecord s;
        RunRow row;
        std::exception_ptr run_error;  // execute_run records a run's own failure; anything else stops
        try {
          row = execute_run(plan, pending[i], want_series ? &s : nullptr);
        } catch (...) {
          run_error = std::current_exception();
        }
        std::lock_guard<std::mutex> lock(mu);
        if (error) return;
        try {
          if (run_error) std::rethrow_exception(run_error);
          if (i == 0) {
            if (const std::string why = refusal(row); !why.empty()) throw ParamError(why);
            fs::create_directories(exec.out_dir);
            log = exists ? std::make_unique<LogWriter>(log_path.string(), valid_bytes)
                         : std::make_unique<LogWriter>(log_path.string(), header);
            if (want_series) series_out = std::make_unique<SeriesWriter>(series_path.string(), exists);
            record(row, want_series ? &s : nullptr);
            for (const Held& h : held) record(h.row, want_series ? &h.series : nullptr);
            std::vector<Held>().swap(held);
            passed = true;
            gate_cv.notify_all();
          } else if (passed) {
            record(row, want_series ? &s : nullptr);
          } else {
            held.push_back({std::move(row), std::move(s)});
          }
        } catch (...) {  // what is logged stays
          error = std::current_exception();
          gate_cv.notify_all();
          return;
        }
      }
    };
    const std::size_t n = std::min<std::size_t>(exec.jobs, pending.size());
    std::vector<std::thread> threads;
    for (std::size_t t = 0; t < n; ++t) threads.emplace_back(worker);
    for (auto& t : threads) t.join();
    if (error) std::rethrow_exception(error);
    log.reset();
    series_out.reset();
  }
  if (pending.empty()) progress.report(true);  // nothing ran: say so once
  if (exec.shard_count == 1) counts.tables = finalize_from_dirs({exec.out_dir}, exec.out_dir, plan.name);
  return counts;
}

}  // namespace adcs::sim::campaign
