#include "cli/commands.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <exception>
#include <iostream>
#include <limits>
#include <map>
#include <memory>
#include <ostream>
#include <set>

#include <unistd.h>

#include "cli/atomic_file.hpp"
#include "cli/json.hpp"
#include "cli/progress.hpp"
#include "sim/sampled_data.hpp"
#include "sim/recorder.hpp"
#include "scenarios/registry.hpp"

namespace adcs::sim::cli {
namespace {

constexpr const char* kProg = "adcs-sim";
constexpr std::uint64_t kMaxRuns = 1000000;

//! A failure of the scenario's run() or of its result (exit 1).
struct RunFailure : std::runtime_error {
  using runtime_error::runtime_error;
};

// ---- parameters -----------------------------------------------------------------------------

ParamSet declared_params(const Scenario& s,
                         const std::vector<std::pair<std::string, std::string>>& sets) {
  ParamSet ps;
  s.declare(ps);
  for (const auto& [key, text] : sets) {
    try {
      ps.set(key, text);
    } catch (const ParamError& e) {
      throw ParamError(std::string(e.what()) + " (see '" + kProg + " describe " + s.name() +
                       "')");
    }
  }
  check_run_parameters(ps);
  return ps;
}

bool has_number(const ParamSet& ps, const char* key) {
  return ps.has(key) && ps.at(key).kind == ParamKind::number;
}

//! Refuses duration_s / step_key above kMaxSteps (or not finite).
void check_steps(const ParamSet& ps, const char* step_key, const char* what) {
  if (!has_number(ps, "duration_s") || !has_number(ps, step_key)) return;
  const double n = ps.get_number("duration_s") / ps.get_number(step_key);
  if (!(n <= kMaxSteps))
    throw ParamError(std::string("duration_s / ") + step_key + " = " +
                     format_value(ps.at("duration_s")) + " / " + format_value(ps.at(step_key)) +
                     " = " + format_number(n) + " " + what + ", more than the maximum " +
                     format_number(kMaxSteps) + " (lower duration_s or raise " + step_key + ")");
}

[[noreturn]] void refuse(const ParamSet& ps, const char* key, const std::string& rule) {
  throw ParamError(std::string("parameter '") + key + "' must be " + rule + ", got " +
                   format_value(ps.at(key)));
}

void write_param_value(JsonWriter& w, ParamKind kind, const ParamValue& v) {
  switch (kind) {
    case ParamKind::number: w.value(v.number); break;
    case ParamKind::vector: w.value(v.vector); break;
    case ParamKind::matrix: w.value(v.matrix); break;
    case ParamKind::name: w.value(v.name); break;
  }
}

const UsedValue* find_used(const std::vector<UsedValue>& used, const std::string& key) {
  for (const UsedValue& u : used)
    if (u.key == key) return &u;
  return nullptr;
}

//! The declared parameters; a value the run reports in `used` replaces the declared "value"
//! (its "source" says how it was obtained; the declared value moves to "declared" /
//! "declared_source"); used values of undeclared keys follow the declared ones.
void write_parameters(JsonWriter& w, const ParamSet& ps, const std::vector<UsedValue>& used = {}) {
  w.key("parameters").begin_object();
  for (const Param& p : ps) {
    const std::string declared_source = p.overridden ? "command line (--set)" : p.source;
    w.key(p.key).begin_object();
    w.key("value");
    if (const UsedValue* u = find_used(used, p.key)) {
      write_param_value(w, u->kind, u->value);
      w.key("unit").value(u->unit.empty() ? p.unit : u->unit);
      w.key("source").value(u->source);
      w.key("declared");
      write_param_value(w, p.kind, p.value);
      w.key("declared_source").value(declared_source);
    } else {
      write_param_value(w, p.kind, p.value);
      w.key("unit").value(p.unit);
      w.key("source").value(declared_source);
    }
    if (p.overridden) {
      w.key("default");
      write_param_value(w, p.kind, p.default_value);
      w.key("default_source").value(p.source);
    }
    w.end_object();
  }
  std::set<std::string> written;
  for (const UsedValue& u : used) {
    if (ps.has(u.key) || !written.insert(u.key).second) continue;
    w.key(u.key).begin_object();
    w.key("value");
    write_param_value(w, u.kind, u.value);
    w.key("unit").value(u.unit);
    w.key("source").value(u.source);
    w.end_object();
  }
  w.end_object();
}

// ---- running --------------------------------------------------------------------------------

void check_metrics(const Scenario& s, const RunResult& r) {
  std::set<std::string> seen;
  for (const auto& [name, value] : r.metrics) {
    (void)value;
    const bool bad = name.empty() || std::any_of(name.begin(), name.end(), [](char c) {
                       return c == ',' || c == '"' || static_cast<unsigned char>(c) < 0x20;
                     });
    if (bad)
      throw RunFailure("scenario '" + s.name() + "' returned an invalid metric name '" + name +
                       "'");
    if (!seen.insert(name).second)
      throw RunFailure("scenario '" + s.name() + "' returned metric '" + name + "' twice");
  }
}

RunResult run_scenario(const Scenario& s, const ParamSet& ps, const RunContext& ctx) {
  RunResult r;
  try {
    const ProgressScope progress(ctx.progress);
    r = s.run(ps, ctx);
  } catch (const ParamError&) {
    throw;  // an invalid value the scenario detected: exit 2
  } catch (const std::exception& e) {
    throw RunFailure("scenario '" + s.name() + "' failed (seed " + std::to_string(ctx.seed) +
                     "): " + e.what());
  } catch (...) {
    throw RunFailure("scenario '" + s.name() + "' failed (seed " + std::to_string(ctx.seed) +
                     "): unknown exception");
  }
  check_metrics(s, r);
  return r;
}

void write_metrics(JsonWriter& w, const RunResult& r) {
  w.key("metrics").begin_object();
  for (const auto& [name, value] : r.metrics) w.key(name).value(value);
  w.end_object();
}

const Scenario& lookup(const Catalog& catalog, const std::string& name) {
  const Scenario* s = catalog.find(name);
  if (!s) throw UsageError("unknown scenario '" + name + "' (see '" + kProg + " list')");
  return *s;
}

std::string csv_number(double x) {
  if (std::isnan(x)) return "nan";
  if (std::isinf(x)) return x > 0 ? "inf" : "-inf";
  return json_number(x);
}

// ---- commands -------------------------------------------------------------------------------

//! Renames the CSV and the JSON into place together: if the JSON cannot be committed, the CSV
//! is taken back, so a run leaves both files or neither.
void commit_outputs(TempFile& csv, TempFile& json, OutputDir& dir,
                    const std::vector<std::unique_ptr<TempFile>>& extra = {}) {
  csv.commit();
  std::size_t done = 0;
  try {
    for (; done < extra.size(); ++done) extra[done]->commit();
    json.commit();
  } catch (...) {
    for (std::size_t i = 0; i < done; ++i) extra[i]->uncommit();
    csv.uncommit();
    throw;
  }
  dir.keep();
}

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

int cmd_list(const Options&, const Catalog& catalog, std::ostream& out) {
  for (const Scenario* s : catalog.scenarios) out << s->name() << '\n';
  out.flush();
  return kExitOk;
}

int cmd_describe(const Options& o, const Catalog& catalog, std::ostream& out) {
  const Scenario& s = lookup(catalog, o.scenario);
  ParamSet ps;
  s.declare(ps);
  out << s.name() << ": " << s.description() << "\n\n";
  out << "parameters (override with: " << kProg << " run " << s.name() << " --set KEY=VALUE):\n";
  std::size_t wk = 0;
  for (const Param& p : ps) wk = std::max(wk, p.key.size());
  for (const Param& p : ps) {
    out << "  " << p.key << std::string(wk - p.key.size(), ' ') << " = " << format_value(p);
    if (!p.unit.empty()) out << " [" << p.unit << "]";
    out << "  (" << describe_kind(p) << ")\n";
    out << "  " << std::string(wk, ' ') << "   source: " << p.source << '\n';
  }
  out.flush();
  return kExitOk;
}

int cmd_run(const Options& o, const Catalog& catalog, std::ostream& out, std::ostream& err,
            bool err_is_terminal) {
  const Scenario& s = lookup(catalog, o.scenario);
  const ParamSet ps = declared_params(s, o.sets);
  const std::uint64_t seed = o.seed.value_or(0);

  OutputDir dir(o.out_dir.value_or("out"));
  TempFile csv(dir.path(), s.name() + ".csv");
  TempFile json(dir.path(), s.name() + ".json");

  ProgressReporter progress(err, s.name(), o.progress, err_is_terminal);
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

  JsonWriter w(2);
  w.begin_object();
  w.key("scenario").value(s.name());
  w.key("seed").value(seed);
  w.key("description").value(s.description());
  write_parameters(w, ps, r.used);
  write_metrics(w, r);
  w.key("claims").begin_array();
  for (const Claim& c : r.claims) {
    w.begin_object();
    w.key("kind").value(c.kind);
    w.key("claim").value(c.claim);
    w.key("paper_value").value(c.paper_value);
    w.key("ours").value(c.ours);
    w.key("paper_verdict");
    if (c.paper_verdict) w.value(to_string(*c.paper_verdict)); else w.null();
    w.key("criterion").value(c.criterion);
    w.key("criterion_holds").value(c.holds);
    w.key("holds").value(c.holds);  // = criterion_holds (kept for readers of older outputs)
    if (!c.note.empty()) w.key("note").value(c.note);
    w.end_object();
  }
  w.end_array();
  w.key("plots").begin_array();
  for (const PlotSpec& p : r.plots) {
    w.begin_object();
    w.key("file").value(p.file);
    w.key("title").value(p.title);
    w.key("x").value(p.x);
    w.key("y").value(p.y);
    w.key("ylabel").value(p.ylabel);
    w.key("logy").value(p.logy);
    if (!p.fill.empty()) {
      w.key("fill").begin_array();
      for (const auto& [lo, hi] : p.fill) w.value(std::vector<std::string>{lo, hi});
      w.end_array();
    }
    if (!p.csv.empty()) w.key("csv").value(p.csv);
    if (!p.kind.empty()) w.key("kind").value(p.kind);
    if (!p.hline.empty()) {
      w.key("hline").begin_array();
      for (const auto& [v, label] : p.hline) {
        w.begin_array();
        w.value(v);
        w.value(label);
        w.end_array();
      }
      w.end_array();
    }
    w.end_object();
  }
  w.end_array();
  w.key("csv").value(s.name() + ".csv");
  w.end_object();
  json.write(w.str() + "\n");

  const std::vector<std::unique_ptr<TempFile>> tables = write_tables(r, dir);
  commit_outputs(csv, json, dir, tables);

  JsonWriter line;
  line.begin_object();
  line.key("scenario").value(s.name());
  line.key("seed").value(seed);
  write_metrics(line, r);
  line.end_object();
  out << "wrote " << csv.final_path() << " and " << json.final_path() << '\n';
  out << line.str() << std::endl;
  return kExitOk;
}

struct Summary {
  double min = std::numeric_limits<double>::quiet_NaN();
  double median = std::numeric_limits<double>::quiet_NaN();
  double max = std::numeric_limits<double>::quiet_NaN();
  std::size_t nonfinite = 0;
};

Summary summarize(std::vector<double> v) {
  Summary s;
  const auto end = std::remove_if(v.begin(), v.end(), [](double x) { return !std::isfinite(x); });
  s.nonfinite = static_cast<std::size_t>(v.end() - end);
  v.erase(end, v.end());
  if (v.empty()) return s;
  std::sort(v.begin(), v.end());
  s.min = v.front();
  s.max = v.back();
  const std::size_t n = v.size();
  s.median = (n % 2) ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
  return s;
}

void write_summary(JsonWriter& w, const std::vector<std::string>& names,
                   const std::vector<std::vector<double>>& columns) {
  w.key("metrics").begin_object();
  for (std::size_t m = 0; m < names.size(); ++m) {
    const Summary s = summarize(columns[m]);
    w.key(names[m]).begin_object();
    w.key("min").value(s.min);
    w.key("median").value(s.median);
    w.key("max").value(s.max);
    if (s.nonfinite) w.key("nonfinite").value(static_cast<unsigned long long>(s.nonfinite));
    w.end_object();
  }
  w.end_object();
}

int cmd_montecarlo(const Options& o, const Catalog& catalog, std::ostream& out,
                   std::ostream& err, bool err_is_terminal) {
  const Scenario& s = lookup(catalog, o.scenario);
  const ParamSet ps = declared_params(s, o.sets);
  const std::uint64_t runs = *o.runs;
  const std::uint64_t seed0 = o.seed0.value_or(1);

  OutputDir dir(o.out_dir.value_or("out"));
  const std::string stem = s.name() + "-montecarlo";
  TempFile csv(dir.path(), stem + ".csv");
  TempFile json(dir.path(), stem + ".json");

  std::vector<std::string> names;
  std::vector<std::vector<double>> columns;  // per metric, per run
  for (std::uint64_t k = 0; k < runs; ++k) {
    RunContext ctx;
    ctx.seed = seed0 + k;
    ctx.quiet = true;
    ProgressReporter progress(err,
                              s.name() + " [" + std::to_string(k + 1) + "/" +
                                  std::to_string(runs) + "] seed=" + std::to_string(ctx.seed),
                              o.progress, err_is_terminal);
    if (progress.enabled())
      ctx.progress = [&progress](double t0, double t, double t_end) {
        progress.update(t0, t, t_end);
      };
    const auto t0 = std::chrono::steady_clock::now();
    const RunResult r = run_scenario(s, ps, ctx);
    progress.finish();
    const double dt = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    if (k == 0) {
      for (const auto& m : r.metrics) names.push_back(m.first);
      columns.resize(names.size());
    }
    std::map<std::string, double> by_name(r.metrics.begin(), r.metrics.end());
    if (by_name.size() != names.size())
      throw RunFailure("scenario '" + s.name() + "' returned a different set of metrics for seed " +
                       std::to_string(ctx.seed));
    for (std::size_t m = 0; m < names.size(); ++m) {
      const auto it = by_name.find(names[m]);
      if (it == by_name.end())
        throw RunFailure("scenario '" + s.name() + "' did not return metric '" + names[m] +
                         "' for seed " + std::to_string(ctx.seed));
      columns[m].push_back(it->second);
    }
    char buf[64];
    std::snprintf(buf, sizeof buf, " (%.2f s)", dt);
    err << '[' << (k + 1) << '/' << runs << "] seed=" << ctx.seed << buf << '\n';
    err.flush();
  }

  std::string table = "seed";
  for (const auto& n : names) table += "," + n;
  table += '\n';
  for (std::uint64_t k = 0; k < runs; ++k) {
    table += std::to_string(seed0 + k);
    for (const auto& col : columns) table += "," + csv_number(col[k]);
    table += '\n';
  }
  csv.write(table);

  JsonWriter w(2);
  w.begin_object();
  w.key("scenario").value(s.name());
  w.key("runs").value(runs);
  w.key("seed0").value(seed0);
  w.key("description").value(s.description());
  write_parameters(w, ps);
  write_summary(w, names, columns);
  w.key("csv").value(stem + ".csv");
  w.end_object();
  json.write(w.str() + "\n");

  commit_outputs(csv, json, dir);

  JsonWriter line;
  line.begin_object();
  line.key("scenario").value(s.name());
  line.key("runs").value(runs);
  line.key("seed0").value(seed0);
  write_summary(line, names, columns);
  line.end_object();
  out << "wrote " << csv.final_path() << " and " << json.final_path() << '\n';
  out << line.str() << std::endl;
  return kExitOk;
}

}  // namespace

// ---- public ---------------------------------------------------------------------------------

void check_run_parameters(const ParamSet& ps) {
  // duration_s and control_period_s are declared as numbers by every scenario (contract).
  for (const char* key : {"duration_s", "control_period_s"})
    if (has_number(ps, key) && !(ps.get_number(key) > 0.0)) refuse(ps, key, "> 0");
  check_steps(ps, "control_period_s", "control steps");
  // CVODE tolerances (SUNDIALS accepts reltol >= 0 and abstol >= 0, but rtol = 0 asks for
  // exact arithmetic, rtol >= 1 for no accuracy, and atol = 0 makes the error weight of a zero
  // state component infinite, so CVODE fails on the first step).
  if (has_number(ps, "rtol")) {
    const double rtol = ps.get_number("rtol");
    if (!(rtol > 0.0 && rtol < 1.0)) refuse(ps, "rtol", "> 0 and < 1");
  }
  if (has_number(ps, "atol") && !(ps.get_number("atol") > 0.0)) refuse(ps, "atol", "> 0");
  if (has_number(ps, "rk4_step_s")) {
    if (!(ps.get_number("rk4_step_s") > 0.0)) refuse(ps, "rk4_step_s", "> 0");
    if (ps.has("integrator") && ps.at("integrator").kind == ParamKind::name &&
        ps.get_name("integrator") == "rk4")
      check_steps(ps, "rk4_step_s", "RK4 steps");
  }
}

const Scenario* Catalog::find(const std::string& name) const {
  for (const Scenario* s : scenarios)
    if (s->name() == name) return s;
  return nullptr;
}

Catalog Catalog::registered() {
  Catalog c;
  for (const auto& s : all_scenarios()) c.scenarios.push_back(s.get());
  return c;
}

std::string one_line(const std::string& msg) {
  std::string s = msg;
  for (char& c : s)
    if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) c = ' ';
  return s;
}

std::uint64_t parse_uint(const std::string& what, const std::string& text) {
  if (text.empty()) throw UsageError(what + " needs a value");
  std::uint64_t v = 0;
  for (char c : text) {
    if (c < '0' || c > '9')
      throw UsageError(what + " must be a non-negative integer, got '" + text + "'");
    const auto d = static_cast<std::uint64_t>(c - '0');
    if (v > (std::numeric_limits<std::uint64_t>::max() - d) / 10)
      throw UsageError(what + " is too large: '" + text + "'");
    v = v * 10 + d;
  }
  return v;
}

Options parse_options(const std::string& command, const std::vector<std::string>& args) {
  const bool is_run = command == "run", is_mc = command == "montecarlo";
  const bool takes_name = is_run || is_mc || command == "describe";
  Options o;
  bool have_name = false;
  std::set<std::string> set_keys;
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string& a = args[i];
    if (a == "--help" || a == "-h") {
      o.help = true;
      continue;
    }
    if (a.size() > 1 && a[0] == '-') {
      std::string opt = a, val;
      bool inline_val = false;
      if (const auto eq = a.find('='); a.rfind("--", 0) == 0 && eq != std::string::npos) {
        opt = a.substr(0, eq);
        val = a.substr(eq + 1);
        inline_val = true;
      }
      if ((is_run || is_mc) && opt == "--progress") {
        if (inline_val) throw UsageError("--progress takes no value");
        if (o.progress) throw UsageError("--progress given twice");
        o.progress = true;
        continue;
      }
      const bool known = ((is_run || is_mc) && (opt == "--set" || opt == "--out")) ||
                         (is_run && opt == "--seed") ||
                         (is_mc && (opt == "--runs" || opt == "--seed0"));
      if (!known) {
        if (!is_mc && (opt == "--runs" || opt == "--seed0"))
          throw UsageError("option " + opt + " belongs to 'montecarlo', not '" + command + "'");
        if (is_mc && opt == "--seed")
          throw UsageError("montecarlo takes --seed0 S (seeds S..S+R-1), not --seed");
        throw UsageError("unknown option '" + opt + "' for '" + command + "' (see '" + kProg +
                         " help')");
      }
      if (!inline_val) {
        if (i + 1 >= args.size()) throw UsageError("option " + opt + " needs a value");
        val = args[++i];
      }
      if (opt == "--set") {
        const auto eq = val.find('=');
        if (eq == std::string::npos)
          throw UsageError("--set expects KEY=VALUE, got '" + val + "'");
        std::string key = val.substr(0, eq);
        if (key.empty())
          throw UsageError("--set expects KEY=VALUE, got an empty key in '" + val + "'");
        if (!set_keys.insert(key).second)
          throw UsageError("parameter '" + key + "' is set twice");
        o.sets.emplace_back(std::move(key), val.substr(eq + 1));
      } else if (opt == "--seed") {
        if (o.seed) throw UsageError("--seed given twice");
        o.seed = parse_uint("--seed", val);
      } else if (opt == "--seed0") {
        if (o.seed0) throw UsageError("--seed0 given twice");
        o.seed0 = parse_uint("--seed0", val);
      } else if (opt == "--runs") {
        if (o.runs) throw UsageError("--runs given twice");
        o.runs = parse_uint("--runs", val);
        if (*o.runs < 1 || *o.runs > kMaxRuns)
          throw UsageError("--runs must be between 1 and " + std::to_string(kMaxRuns) +
                           ", got " + val);
      } else if (opt == "--out") {
        if (o.out_dir) throw UsageError("--out given twice");
        if (val.empty()) throw UsageError("--out needs a directory");
        o.out_dir = val;
      }
      continue;
    }
    if (!takes_name) throw UsageError("'" + command + "' takes no argument, got '" + a + "'");
    if (have_name) throw UsageError("unexpected argument '" + a + "' (one scenario at a time)");
    o.scenario = a;
    have_name = true;
  }
  if (o.help) return o;
  if (takes_name && !have_name) throw UsageError("'" + command + "' needs a scenario NAME");
  if (is_mc) {
    if (!o.runs) throw UsageError("montecarlo needs --runs R");
    const std::uint64_t s0 = o.seed0.value_or(1);
    if (s0 > std::numeric_limits<std::uint64_t>::max() - (*o.runs - 1))
      throw UsageError("--seed0 + --runs overflows the seed range");
  }
  return o;
}

std::string usage() {
  return R"(usage: adcs-sim COMMAND [ARGS]

commands:
  list                      scenario names, one a line
  describe NAME             NAME's description and parameters (default, unit, source)
  run NAME [--set KEY=VALUE]... [--seed N] [--out DIR] [--progress]
                            run once; writes DIR/NAME.csv (time series) and DIR/NAME.json
                            (every value used incl. --seed draws, metrics, claims, plots)
  montecarlo NAME --runs R [--seed0 S] [--out DIR] [--set KEY=VALUE]... [--progress]
                            R runs with seeds S..S+R-1; writes per-run metrics to
                            DIR/NAME-montecarlo.csv and min/median/max to NAME-montecarlo.json
  help                      this text

options:
  --set KEY=VALUE  override a parameter (repeatable, each KEY once). VALUE is a number
                   (1e-3, -2, 0.5), a vector [a,b,c], a matrix [[a,b],[c,d]] (row-major)
                   or a name (adams). Every scenario has duration_s and control_period_s.
  --seed N         random seed of run (default 0)
  --runs R         number of Monte Carlo runs (required)
  --seed0 S        first Monte Carlo seed (default 1)
  --out DIR        output directory (default out; created if missing)
  --progress       progress on stderr (simulated time, wall time, ETA) at most once a second,
                   and a final line; shown anyway, in place, when stderr is a terminal and the
                   run lasts over 3 s. stdout is the same either way.
  Options also accept the form --opt=VALUE.

Refused before running (exit 2): duration_s or control_period_s <= 0; more than 1e8 steps
(duration_s / control_period_s, or duration_s / rk4_step_s with integrator=rk4); where
declared, rtol outside (0, 1), atol <= 0, rk4_step_s <= 0.

The last line on stdout is one JSON object: {"scenario": ..., "seed": N, "metrics": {...}}
for run, {"scenario": ..., "runs": R, "seed0": S, "metrics": {m: {"min", "median", "max"}}}
for montecarlo. Errors are one line on stderr; exit status 2 for a bad command line (unknown
scenario, option, parameter or value), 1 if the simulation or writing fails. Either way no
output file is left behind.
)";
}

int run_cli(const std::vector<std::string>& args, const Catalog& catalog, std::ostream& out,
            std::ostream& err, bool err_is_terminal) {
  const auto fail = [&](int status, const std::string& msg) {
    out.flush();
    err << kProg << ": error: " << one_line(msg) << std::endl;
    return status;
  };
  try {
    if (args.empty()) return fail(kExitUsage, std::string("no command (see '") + kProg + " help')");
    const std::string& cmd = args.front();
    if (cmd == "help" || cmd == "--help" || cmd == "-h") {
      out << usage();
      out.flush();
      return kExitOk;
    }
    if (cmd != "list" && cmd != "describe" && cmd != "run" && cmd != "montecarlo")
      return fail(kExitUsage, "unknown command '" + cmd + "' (see '" + kProg + " help')");
    const Options o = parse_options(cmd, std::vector<std::string>(args.begin() + 1, args.end()));
    if (o.help) {
      out << usage();
      out.flush();
      return kExitOk;
    }
    if (cmd == "list") return cmd_list(o, catalog, out);
    if (cmd == "describe") return cmd_describe(o, catalog, out);
    if (cmd == "run") return cmd_run(o, catalog, out, err, err_is_terminal);
    return cmd_montecarlo(o, catalog, out, err, err_is_terminal);
  } catch (const UsageError& e) {
    return fail(kExitUsage, e.what());
  } catch (const ParamError& e) {
    return fail(kExitUsage, e.what());
  } catch (const RunFailure& e) {
    return fail(kExitFailure, e.what());
  } catch (const IoError& e) {
    return fail(kExitFailure, e.what());
  } catch (const std::exception& e) {
    return fail(kExitFailure, std::string("internal error: ") + e.what());
  } catch (...) {
    return fail(kExitFailure, "internal error: unknown exception");
  }
}

int cli_main(int argc, char** argv) {
  install_cleanup_signal_handlers();
  std::vector<std::string> args;
  for (int i = 1; i < argc; ++i) args.emplace_back(argv[i]);
  try {
    return run_cli(args, Catalog::registered(), std::cout, std::cerr, ::isatty(2) == 1);
  } catch (const std::exception& e) {  // e.g. a scenario factory throwing
    std::cerr << kProg << ": error: internal error: " << one_line(e.what()) << std::endl;
    return kExitFailure;
  } catch (...) {
    std::cerr << kProg << ": error: internal error while starting" << std::endl;
    return kExitFailure;
  }
}

}  // namespace adcs::sim::cli
