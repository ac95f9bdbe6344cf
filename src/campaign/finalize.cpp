#include "campaign/finalize.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <regex>
#include <set>

#include "campaign/envelopes_h5.hpp"
#include "campaign/series.hpp"
#include "campaign/statistics.hpp"
#include "cli/atomic_file.hpp"
#include "scenarios/params.hpp"

namespace adcs::sim::campaign {
namespace ADCS_UNITY_ID {

namespace fs = std::filesystem;

constexpr std::size_t kNoLog = static_cast<std::size_t>(-1);

//! One log file, scanned: its header and, for each row in file order, the run and where its
//! line is. The rows themselves are not kept (a row is ~2.5 kB, its place here 24 bytes): the
//! tables are built by reading them again, one at a time, in run order.
struct FoundLog {
  std::string path, series_path, name;
  LogHeader header;
  struct Row {
    std::uint64_t run = 0;
    RowSpan span;
  };
  std::vector<Row> rows;
};

//! Where a metric first appears: (run, position in that run's metrics), the smallest over the
//! rows. Sorting the names by it gives their order of first appearance in the rows sorted by run,
//! without holding the rows.
using FirstSeen = std::map<std::string, std::pair<std::uint64_t, std::size_t>>;

std::string shell_quote(const std::string& s) {
  if (!s.empty() && s.find_first_not_of("ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789_-.,/=:+") ==
                        std::string::npos)
    return s;
  std::string q = "'";
  for (char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

std::string csv_field(const std::string& s) {
  if (s.find_first_of(",\"\n") == std::string::npos) return s;
  std::string q = "\"";
  for (char c : s) q += c == '"' ? std::string("\"\"") : std::string(1, c);
  return q + "\"";
}

//! Every campaign log in `dirs`: NAME-montecarlo.log.jsonl or NAME-montecarlo.shard-I-of-N.log.jsonl;
//! `metrics` receives where each metric first appears.
std::vector<FoundLog> find_logs(const std::vector<fs::path>& dirs, const std::string& name, FirstSeen& metrics) {
  static const std::regex pattern(R"((.+)-montecarlo(\.shard-([0-9]+)-of-([0-9]+))?\.log\.jsonl)");
  std::vector<FoundLog> logs;
  std::set<std::string> seen;
  for (const fs::path& dir : dirs) {
    if (!fs::is_directory(dir)) throw ParamError("merge: " + dir.string() + " is not a directory");
    std::vector<fs::path> files;
    for (const auto& e : fs::directory_iterator(dir)) files.push_back(e.path());
    std::sort(files.begin(), files.end());
    for (const fs::path& f : files) {
      std::smatch m;
      const std::string base = f.filename().string();
      if (!std::regex_match(base, m, pattern)) continue;
      if (!name.empty() && m[1] != name) continue;
      const std::string canonical = fs::weakly_canonical(f).string();
      if (!seen.insert(canonical).second) continue;  // the same directory given twice
      FoundLog l;
      l.path = f.string();
      l.name = m[1];
      l.series_path = (f.parent_path() / (l.name + "-montecarlo" + std::string(m[2]) + ".series.bin")).string();
      try {
        l.header = scan_log(l.path, [&](RunRow&& r, const RowSpan& span) {
                     l.rows.push_back({r.run, span});
                     for (std::size_t i = 0; i < r.metrics.size(); ++i) {
                       const auto [it, fresh] = metrics.emplace(r.metrics[i].first, std::make_pair(r.run, i));
                       if (!fresh) it->second = std::min(it->second, std::make_pair(r.run, i));
                     }
                   }).header;
      } catch (const std::runtime_error& e) {
        throw ParamError(e.what());
      }
      logs.push_back(std::move(l));
    }
  }
  return logs;
}

//! A statistic in the campaign JSON: null when undefined (no finite value), as a run's JSON
//! writes a non-finite metric (the count of non-finite values says why).
Json stat(double x) { return std::isfinite(x) ? Json(x) : Json(nullptr); }

Json summary_json(const Summary& s) {
  Json j;
  j["count"] = s.count;
  j["nonfinite"] = s.nonfinite;
  j["min"] = stat(s.min);
  j["p1"] = stat(s.p1);
  j["p5"] = stat(s.p5);
  j["median"] = stat(s.median);
  j["p95"] = stat(s.p95);
  j["p99"] = stat(s.p99);
  j["max"] = stat(s.max);
  j["mean"] = stat(s.mean);
  j["std"] = stat(s.std);
  return j;
}

}  // namespace
using namespace ADCS_UNITY_ID;  // as an anonymous namespace would (CMakeLists.txt, adcs_unity)

std::string rerun_command(const Json& identity, const RunRow& row) {
  std::string cmd = "adcs-sim run " + shell_quote(identity.at("run_target").get<std::string>()) + " --seed " +
                    std::to_string(row.seed);
  for (const auto& s : identity.at("sets")) cmd += " --set " + shell_quote(s.get<std::string>());
  for (const auto& s : row.drawn_sets) cmd += " --set " + shell_quote(s);
  return cmd;
}

FinalizeResult finalize_from_dirs(const std::vector<fs::path>& dirs, const fs::path& out_dir, const std::string& name) {
  FirstSeen first_seen;
  std::vector<FoundLog> logs = find_logs(dirs, name, first_seen);
  if (logs.empty()) throw ParamError("merge: no campaign log (NAME-montecarlo*.log.jsonl) in the given directories");
  // One campaign, every shard once.
  const LogHeader& h0 = logs.front().header;
  for (const FoundLog& l : logs) {
    const LogHeader& h = l.header;
    if (h.campaign_id != h0.campaign_id)
      throw ParamError("merge: shards of different campaigns: " + logs.front().path + " (campaign " + h0.campaign_id +
                       ") and " + l.path + " (campaign " + h.campaign_id + ")");
    if (h.shard_count != h0.shard_count)
      throw ParamError("merge: " + l.path + " is shard " + std::to_string(h.shard_index) + " of " +
                       std::to_string(h.shard_count) + ", " + logs.front().path + " of " + std::to_string(h0.shard_count));
  }
  const std::uint64_t n_shards = h0.shard_count;
  std::map<std::uint64_t, std::string> shard_file;
  for (const FoundLog& l : logs) {
    const auto [it, fresh] = shard_file.emplace(l.header.shard_index, l.path);
    if (!fresh) throw ParamError("merge: shard " + std::to_string(l.header.shard_index) + " given twice: " + it->second + " and " + l.path);
  }
  for (std::uint64_t i = 0; i < n_shards; ++i)
    if (!shard_file.count(i)) throw ParamError("merge: shard " + std::to_string(i) + " of " + std::to_string(n_shards) + " is missing");
  const Json& id = h0.identity;
  const std::uint64_t runs = id.at("runs").get<std::uint64_t>();
  const std::string cname = id.at("scenario").get<std::string>();

  // Rows, each run exactly once and in its own shard: where each run's line is, by run index.
  struct RowAt {
    std::size_t log = kNoLog;
    RowSpan span;
  };
  std::vector<RowAt> row_at(static_cast<std::size_t>(runs));
  std::uint64_t n_rows = 0;
  for (std::size_t li = 0; li < logs.size(); ++li) {
    FoundLog& l = logs[li];
    for (const FoundLog::Row& r : l.rows) {
      if (r.run >= runs || r.run % n_shards != l.header.shard_index)
        throw ParamError("merge: " + l.path + " holds run " + std::to_string(r.run) + ", which is not shard " +
                         std::to_string(l.header.shard_index) + "'s");
      RowAt& at = row_at[static_cast<std::size_t>(r.run)];
      if (at.log != kNoLog)
        throw ParamError("merge: run " + std::to_string(r.run) + " is recorded twice (" + logs[at.log].path + ", " + l.path + ")");
      at = {li, r.span};
      ++n_rows;
    }
    std::vector<FoundLog::Row>().swap(l.rows);
  }
  if (n_rows != runs) {
    std::string missing;
    int shown = 0;
    for (std::uint64_t k = 0; k < runs && shown < 5; ++k)
      if (row_at[static_cast<std::size_t>(k)].log == kNoLog) missing += (shown++ ? ", " : "") + std::to_string(k);
    throw ParamError("merge: " + std::to_string(runs - n_rows) + " of " + std::to_string(runs) +
                     " runs are missing (e.g. run " + missing + "): finish the shards with --resume");
  }

  // Columns: drawn values (the same for every run: run 0's), then the metrics in order of first
  // appearance in the rows sorted by run.
  std::vector<std::pair<std::pair<std::uint64_t, std::size_t>, std::string>> by_first;
  for (const auto& [m, first] : first_seen) by_first.emplace_back(first, m);
  std::sort(by_first.begin(), by_first.end());
  std::vector<std::string> metric_names;
  for (auto& f : by_first) metric_names.push_back(std::move(f.second));
  std::string rank = id.at("rank_metric").get<std::string>();
  if (rank.empty() && !metric_names.empty()) rank = metric_names.front();

  // The rows are read again one at a time, in run order, and go straight into the CSV, which is
  // written to its temporary as it is made; what the JSON needs is gathered on the way: each ok
  // run's metric values (8 bytes a value, for the percentiles) and a bounded few rows' rerun
  // commands. Nothing else of a row is kept, so memory grows by bytes, not kilobytes, per run.
  // The output directory and temporaries undo themselves if anything below throws (all or
  // nothing, as before: every refusal is above).
  const std::string stem = cname + "-montecarlo";
  cli::OutputDir dir(out_dir);
  cli::TempFile csv_file(dir.path(), stem + ".csv"), json_file(dir.path(), stem + ".json");
  std::ofstream csv(csv_file.temp_path(), std::ios::binary | std::ios::trunc);
  if (!csv) throw cli::IoError("cannot open '" + csv_file.temp_path() + "' for writing");
  std::vector<std::string> drawn_names;
  std::map<std::string, std::vector<double>> by_metric;
  std::uint64_t n_ok = 0, n_invalid = 0, n_failed = 0;
  std::vector<char> run_ok(static_cast<std::size_t>(runs), 0);
  // Claims: pass counts over the runs that judged them; up to 3 failing runs each.
  struct ClaimTally {
    std::string kind, claim;
    std::uint64_t held = 0, failed = 0, informative = 0;
    Json failing = Json::array();
  };
  std::vector<ClaimTally> tallies;
  // The worst runs by the rank metric (largest first; equal values in run order, as a stable
  // sort of all of them would give): the 5 largest so far, with their rerun commands.
  struct Ranked {
    double value;
    std::uint64_t run, seed;
    std::string command;
  };
  std::vector<Ranked> worst_5;
  constexpr std::size_t kWorst = 5;
  Json failed = Json::array();
  std::string row_text;
  for (std::uint64_t k = 0; k < runs; ++k) {
    const RowAt& at = row_at[static_cast<std::size_t>(k)];
    const RunRow r = read_row_at(logs[at.log].path, at.span);
    if (k == 0) {
      drawn_names = r.drawn_names;
      row_text = "run";
      for (const auto& d : drawn_names) row_text += "," + csv_field(d);
      for (const auto& m : metric_names) row_text += "," + csv_field(m);
      row_text += ",status,seed,error\n";
      csv << row_text;
    }
    row_text = std::to_string(r.run);
    for (std::size_t i = 0; i < drawn_names.size(); ++i)
      row_text += "," + (i < r.drawn_values.size() ? format_number(r.drawn_values[i]) : std::string("nan"));
    std::map<std::string, double> mv(r.metrics.begin(), r.metrics.end());
    for (const auto& m : metric_names) {
      const auto it = mv.find(m);
      row_text += "," + (it == mv.end() ? std::string("") : format_number(it->second));
      if (r.status == RunStatus::ok && it != mv.end()) by_metric[m].push_back(it->second);
    }
    row_text += std::string(",") + to_string(r.status) + "," + std::to_string(r.seed) + "," + csv_field(r.error) + "\n";
    csv << row_text;
    if (r.status == RunStatus::ok) ++n_ok;
    if (r.status == RunStatus::invalid) ++n_invalid;
    if (r.status == RunStatus::failed) ++n_failed;
    run_ok[static_cast<std::size_t>(k)] = r.status == RunStatus::ok;

    for (const ClaimOutcome& c : r.claims) {
      auto it = std::find_if(tallies.begin(), tallies.end(), [&](const ClaimTally& t) { return t.kind == c.kind && t.claim == c.claim; });
      if (it == tallies.end()) {
        tallies.push_back({c.kind, c.claim, 0, 0, 0, Json::array()});
        it = tallies.end() - 1;
      }
      if (!c.holds) ++it->informative;
      else if (*c.holds) ++it->held;
      else {
        ++it->failed;
        if (it->failing.size() < 3) it->failing.push_back({{"run", r.run}, {"command", rerun_command(id, r)}});
      }
    }
    if (r.status == RunStatus::ok)
      for (const auto& m : r.metrics) {
        if (m.first != rank || !std::isfinite(m.second)) continue;
        const auto pos = std::upper_bound(worst_5.begin(), worst_5.end(), m.second,
                                          [](double v, const Ranked& w) { return v > w.value; });
        if (static_cast<std::size_t>(pos - worst_5.begin()) >= kWorst) continue;
        worst_5.insert(pos, {m.second, r.run, r.seed, rerun_command(id, r)});
        if (worst_5.size() > kWorst) worst_5.pop_back();
      }
    if (r.status != RunStatus::ok && failed.size() < 20)
      failed.push_back({{"run", r.run}, {"status", to_string(r.status)}, {"error", r.error}, {"command", rerun_command(id, r)}});
  }
  csv.close();
  if (!csv) throw cli::IoError("cannot write '" + csv_file.temp_path() + "'");

  Json j;
  j["scenario"] = cname;
  j["campaign_id"] = h0.campaign_id;
  j["description"] = id.at("description");
  j["run_target"] = id.at("run_target");
  j["runs"] = runs;
  j["seed0"] = id.at("seed0");
  j["sets"] = id.at("sets");
  j["dispersions"] = id.at("dispersions");
  j["counts"] = {{"ok", n_ok}, {"invalid", n_invalid}, {"failed", n_failed}};
  Json metrics = Json::object();
  for (const auto& m : metric_names) {
    metrics[m] = summary_json(summarize(std::move(by_metric[m])));
    by_metric.erase(m);
  }
  j["metrics"] = metrics;

  Json claims = Json::array();
  for (const ClaimTally& t : tallies) {
    Json c;
    c["kind"] = t.kind;
    c["claim"] = t.claim;
    c["held"] = t.held;
    c["failed"] = t.failed;
    c["informative"] = t.informative;
    const std::uint64_t judged = t.held + t.failed;
    c["summary"] = judged ? "held in " + std::to_string(t.held) + " / " + std::to_string(judged)
                          : "informative in " + std::to_string(t.informative) + " runs";
    c["failing_runs"] = t.failing;
    claims.push_back(c);
  }
  j["claims"] = claims;

  Json worst = Json::array();
  for (const Ranked& w : worst_5)
    worst.push_back({{"run", w.run}, {"seed", w.seed}, {"value", json_number(w.value)}, {"command", w.command}});
  j["worst_runs"] = {{"metric", rank}, {"runs", worst}};
  j["failed_runs"] = failed;
  j["csv"] = stem + ".csv";
  const std::vector<std::string> series = id.at("series").get<std::vector<std::string>>();
  j["series"] = series;
  j["series_file"] = series.empty() ? Json(nullptr) : Json(stem + "-series.h5");
  j["parameters"] = id.at("parameters");

  // Envelopes of the kept series over the ok runs (the last record of a run wins: a run rerun
  // after a kill between its series record and its log line wrote the same record twice).
  std::vector<Envelope> envelopes;
  if (!series.empty()) {
    std::vector<SeriesIndexEntry> by_run(static_cast<std::size_t>(runs));
    for (const FoundLog& l : logs)
      for (SeriesIndexEntry& e : index_series_file(l.series_path))
        if (e.run < runs && run_ok[static_cast<std::size_t>(e.run)]) by_run[static_cast<std::size_t>(e.run)] = std::move(e);
    std::vector<SeriesIndexEntry> entries;
    for (SeriesIndexEntry& e : by_run)
      if (!e.path.empty()) entries.push_back(std::move(e));
    std::vector<SeriesIndexEntry>().swap(by_run);
    envelopes = compute_envelopes(entries, series);
  }

  // All or nothing: the temporaries are renamed into place together.
  std::unique_ptr<cli::TempFile> h5;
  json_file.write(j.dump(2) + "\n");
  if (!series.empty()) {
    h5 = std::make_unique<cli::TempFile>(dir.path(), stem + "-series.h5");
    write_envelopes_h5(h5->temp_path(), envelopes);
  }
  csv_file.commit();
  json_file.commit();
  if (h5) h5->commit();
  dir.keep();

  FinalizeResult out;
  out.name = cname;
  out.csv_path = csv_file.final_path();
  out.json_path = json_file.final_path();
  if (h5) out.series_path = h5->final_path();
  Json line;
  line["scenario"] = cname;
  line["runs"] = runs;
  line["seed0"] = id.at("seed0");
  line["counts"] = j["counts"];
  Json ms = Json::object();
  for (const auto& m : metric_names) {
    const Json& s = metrics[m];
    ms[m] = {{"min", s["min"]}, {"median", s["median"]}, {"max", s["max"]}};
    if (s["nonfinite"].get<std::uint64_t>() > 0) ms[m]["nonfinite"] = s["nonfinite"];
  }
  line["metrics"] = ms;
  out.summary_line = line;
  return out;
}

}  // namespace adcs::sim::campaign
