#include "cli/run_json.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <set>

namespace adcs::sim::cli {
namespace ADCS_UNITY_ID {

Json param_value(ParamKind kind, const ParamValue& v) {
  switch (kind) {
    case ParamKind::number: return v.number;
    case ParamKind::vector: return v.vector;
    case ParamKind::matrix: return v.matrix;
    case ParamKind::name: return v.name;
  }
  return nullptr;
}

const UsedValue* find_used(const std::vector<UsedValue>& used, const std::string& key) {
  for (const UsedValue& u : used)
    if (u.key == key) return &u;
  return nullptr;
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

}  // namespace
using namespace ADCS_UNITY_ID;  // as an anonymous namespace would (CMakeLists.txt, adcs_unity)

Json parameters_json(const ParamSet& ps, const std::vector<UsedValue>& used) {
  Json params = Json::object();
  for (const Param& p : ps) {
    const std::string declared_source = p.overridden ? "command line (--set)" : p.source;
    Json entry = Json::object();
    if (const UsedValue* u = find_used(used, p.key)) {
      entry["value"] = param_value(u->kind, u->value);
      entry["unit"] = u->unit.empty() ? p.unit : u->unit;
      entry["source"] = u->source;
      entry["declared"] = param_value(p.kind, p.value);
      entry["declared_source"] = declared_source;
    } else {
      entry["value"] = param_value(p.kind, p.value);
      entry["unit"] = p.unit;
      entry["source"] = declared_source;
    }
    if (p.overridden) {
      entry["default"] = param_value(p.kind, p.default_value);
      entry["default_source"] = p.source;
    }
    params[p.key] = std::move(entry);
  }
  std::set<std::string> written;
  for (const UsedValue& u : used) {
    if (ps.has(u.key) || !written.insert(u.key).second) continue;
    params[u.key] = Json{{"value", param_value(u.kind, u.value)},
                         {"unit", u.unit},
                         {"source", u.source}};
  }
  return params;
}

Json metrics_json(const std::vector<std::pair<std::string, double>>& metrics) {
  Json m = Json::object();
  for (const auto& [name, value] : metrics) m[name] = value;
  return m;
}

Json claims_json(const std::vector<Claim>& claims) {
  Json list = Json::array();
  for (const Claim& c : claims) {
    Json claim = Json::object();
    claim["kind"] = c.kind;
    claim["claim"] = c.claim;
    claim["paper_value"] = c.paper_value;
    claim["ours"] = c.ours;
    claim["paper_verdict"] = c.paper_verdict ? Json(to_string(*c.paper_verdict)) : Json(nullptr);
    claim["criterion"] = c.criterion;
    const Json holds = c.holds ? Json(*c.holds) : Json(nullptr);
    claim["criterion_holds"] = holds;
    claim["holds"] = holds;  // = criterion_holds (kept for readers of older outputs)
    if (!c.note.empty()) claim["note"] = c.note;
    list.push_back(std::move(claim));
  }
  return list;
}

Json plots_json(const std::vector<PlotSpec>& plots) {
  Json list = Json::array();
  for (const PlotSpec& p : plots) {
    Json plot = Json::object();
    plot["file"] = p.file;
    plot["title"] = p.title;
    plot["x"] = p.x;
    plot["y"] = p.y;
    plot["ylabel"] = p.ylabel;
    plot["logy"] = p.logy;
    if (!p.fill.empty()) {
      Json& fill = plot["fill"] = Json::array();
      for (const auto& [lo, hi] : p.fill) fill.push_back(Json::array({lo, hi}));
    }
    if (!p.csv.empty()) plot["csv"] = p.csv;
    if (!p.kind.empty()) plot["kind"] = p.kind;
    if (!p.hline.empty()) {
      Json& hline = plot["hline"] = Json::array();
      for (const auto& [v, label] : p.hline) hline.push_back(Json::array({v, label}));
    }
    list.push_back(std::move(plot));
  }
  return list;
}

Json summary_json(const std::vector<std::string>& names,
                  const std::vector<std::vector<double>>& columns) {
  Json metrics = Json::object();
  for (std::size_t m = 0; m < names.size(); ++m) {
    const Summary s = summarize(columns[m]);
    Json& entry = metrics[names[m]] = Json{{"min", s.min}, {"median", s.median}, {"max", s.max}};
    if (s.nonfinite) entry["nonfinite"] = s.nonfinite;
  }
  return metrics;
}

}  // namespace adcs::sim::cli
