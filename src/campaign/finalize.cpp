#include "campaign/finalize.hpp"

#include <algorithm>
#include <cmath>
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

struct FoundLog {
  std::string path, series_path, name;
  LogContents contents;
};

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

//! Every campaign log in `dirs`: NAME-montecarlo.log.jsonl or NAME-montecarlo.shard-I-of-N.log.jsonl.
std::vector<FoundLog> find_logs(const std::vector<fs::path>& dirs, const std::string& name) {
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
        l.contents = read_log(l.path);
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
  std::vector<FoundLog> logs = find_logs(dirs, name);
  if (logs.empty()) throw ParamError("merge: no campaign log (NAME-montecarlo*.log.jsonl) in the given directories");
  // One campaign, every shard once.
  const LogHeader& h0 = logs.front().contents.header;
  for (const FoundLog& l : logs) {
    const LogHeader& h = l.contents.header;
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
    const auto [it, fresh] = shard_file.emplace(l.contents.header.shard_index, l.path);
    if (!fresh) throw ParamError("merge: shard " + std::to_string(l.contents.header.shard_index) + " given twice: " + it->second + " and " + l.path);
  }
  for (std::uint64_t i = 0; i < n_shards; ++i)
    if (!shard_file.count(i)) throw ParamError("merge: shard " + std::to_string(i) + " of " + std::to_string(n_shards) + " is missing");
  const Json& id = h0.identity;
  const std::uint64_t runs = id.at("runs").get<std::uint64_t>();
  const std::string cname = id.at("scenario").get<std::string>();

  // Rows, each run exactly once and in its own shard.
  std::vector<RunRow> rows;
  std::map<std::uint64_t, std::string> row_file;
  for (FoundLog& l : logs) {
    for (RunRow& r : l.contents.rows) {
      if (r.run >= runs || r.run % n_shards != l.contents.header.shard_index)
        throw ParamError("merge: " + l.path + " holds run " + std::to_string(r.run) + ", which is not shard " +
                         std::to_string(l.contents.header.shard_index) + "'s");
      const auto [it, fresh] = row_file.emplace(r.run, l.path);
      if (!fresh) throw ParamError("merge: run " + std::to_string(r.run) + " is recorded twice (" + it->second + ", " + l.path + ")");
      rows.push_back(std::move(r));
    }
  }
  if (rows.size() != runs) {
    std::string missing;
    int shown = 0;
    for (std::uint64_t k = 0; k < runs && shown < 5; ++k)
      if (!row_file.count(k)) missing += (shown++ ? ", " : "") + std::to_string(k);
    throw ParamError("merge: " + std::to_string(runs - rows.size()) + " of " + std::to_string(runs) +
                     " runs are missing (e.g. run " + missing + "): finish the shards with --resume");
  }
  std::sort(rows.begin(), rows.end(), [](const RunRow& a, const RunRow& b) { return a.run < b.run; });

  // Columns: drawn values (the same for every run), then the metrics in order of first appearance.
  std::vector<std::string> drawn_names = rows.front().drawn_names;
  std::vector<std::string> metric_names;
  std::set<std::string> metric_seen;
  for (const RunRow& r : rows)
    for (const auto& m : r.metrics)
      if (metric_seen.insert(m.first).second) metric_names.push_back(m.first);

  std::string csv = "run";
  for (const auto& d : drawn_names) csv += "," + csv_field(d);
  for (const auto& m : metric_names) csv += "," + csv_field(m);
  csv += ",status,seed,error\n";
  std::map<std::string, std::vector<double>> by_metric;
  std::uint64_t n_ok = 0, n_invalid = 0, n_failed = 0;
  for (const RunRow& r : rows) {
    csv += std::to_string(r.run);
    for (std::size_t i = 0; i < drawn_names.size(); ++i)
      csv += "," + (i < r.drawn_values.size() ? format_number(r.drawn_values[i]) : std::string("nan"));
    std::map<std::string, double> mv(r.metrics.begin(), r.metrics.end());
    for (const auto& m : metric_names) {
      const auto it = mv.find(m);
      csv += "," + (it == mv.end() ? std::string("") : format_number(it->second));
      if (r.status == RunStatus::ok && it != mv.end()) by_metric[m].push_back(it->second);
    }
    csv += std::string(",") + to_string(r.status) + "," + std::to_string(r.seed) + "," + csv_field(r.error) + "\n";
    if (r.status == RunStatus::ok) ++n_ok;
    if (r.status == RunStatus::invalid) ++n_invalid;
    if (r.status == RunStatus::failed) ++n_failed;
  }

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
  for (const auto& m : metric_names) metrics[m] = summary_json(summarize(by_metric[m]));
  j["metrics"] = metrics;

  // Claims: pass counts over the runs that judged them; up to 3 failing runs each.
  struct ClaimTally {
    std::string kind, claim;
    std::uint64_t held = 0, failed = 0, informative = 0;
    std::vector<const RunRow*> failing;
  };
  std::vector<ClaimTally> tallies;
  for (const RunRow& r : rows)
    for (const ClaimOutcome& c : r.claims) {
      auto it = std::find_if(tallies.begin(), tallies.end(), [&](const ClaimTally& t) { return t.kind == c.kind && t.claim == c.claim; });
      if (it == tallies.end()) {
        tallies.push_back({c.kind, c.claim, 0, 0, 0, {}});
        it = tallies.end() - 1;
      }
      if (!c.holds) ++it->informative;
      else if (*c.holds) ++it->held;
      else {
        ++it->failed;
        if (it->failing.size() < 3) it->failing.push_back(&r);
      }
    }
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
    Json f = Json::array();
    for (const RunRow* r : t.failing) f.push_back({{"run", r->run}, {"command", rerun_command(id, *r)}});
    c["failing_runs"] = f;
    claims.push_back(c);
  }
  j["claims"] = claims;

  // The worst runs by the rank metric (largest first), each with the command that reruns it.
  std::string rank = id.at("rank_metric").get<std::string>();
  if (rank.empty() && !metric_names.empty()) rank = metric_names.front();
  std::vector<std::pair<double, const RunRow*>> ranked;
  for (const RunRow& r : rows)
    if (r.status == RunStatus::ok)
      for (const auto& m : r.metrics)
        if (m.first == rank && std::isfinite(m.second)) ranked.emplace_back(m.second, &r);
  std::stable_sort(ranked.begin(), ranked.end(), [](const auto& a, const auto& b) { return a.first > b.first; });
  Json worst = Json::array();
  for (std::size_t i = 0; i < ranked.size() && i < 5; ++i)
    worst.push_back({{"run", ranked[i].second->run}, {"seed", ranked[i].second->seed}, {"value", json_number(ranked[i].first)},
                     {"command", rerun_command(id, *ranked[i].second)}});
  j["worst_runs"] = {{"metric", rank}, {"runs", worst}};
  Json failed = Json::array();
  for (const RunRow& r : rows)
    if (r.status != RunStatus::ok && failed.size() < 20)
      failed.push_back({{"run", r.run}, {"status", to_string(r.status)}, {"error", r.error}, {"command", rerun_command(id, r)}});
  j["failed_runs"] = failed;
  const std::string stem = cname + "-montecarlo";
  j["csv"] = stem + ".csv";
  const std::vector<std::string> series = id.at("series").get<std::vector<std::string>>();
  j["series"] = series;
  j["series_file"] = series.empty() ? Json(nullptr) : Json(stem + "-series.h5");
  j["parameters"] = id.at("parameters");

  // Envelopes of the kept series over the ok runs (the last record of a run wins: a run rerun
  // after a kill between its series record and its log line wrote the same record twice).
  std::vector<Envelope> envelopes;
  if (!series.empty()) {
    std::map<std::uint64_t, SeriesIndexEntry> by_run;
    std::set<std::uint64_t> ok_runs;
    for (const RunRow& r : rows)
      if (r.status == RunStatus::ok) ok_runs.insert(r.run);
    for (const FoundLog& l : logs)
      for (const SeriesIndexEntry& e : index_series_file(l.series_path))
        if (ok_runs.count(e.run)) by_run[e.run] = e;
    std::vector<SeriesIndexEntry> entries;
    for (const auto& kv : by_run) entries.push_back(kv.second);
    envelopes = compute_envelopes(entries, series);
  }

  // All or nothing: the temporaries are renamed into place together.
  cli::OutputDir dir(out_dir);
  cli::TempFile csv_file(dir.path(), stem + ".csv"), json_file(dir.path(), stem + ".json");
  std::unique_ptr<cli::TempFile> h5;
  csv_file.write(csv);
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
