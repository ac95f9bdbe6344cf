#include "scenarios/registry.hpp"

#include <algorithm>
#include <exception>
#include <set>

namespace adcs::sim {

// Factories, one per scenario file in src/scenarios/.
std::unique_ptr<Scenario> make_rigid_rw_torquefree();
std::unique_ptr<Scenario> make_rigid_rw_mrp_pd();
std::unique_ptr<Scenario> make_hybrid_adaptive();
std::unique_ptr<Scenario> make_hybrid_nonadaptive();
std::unique_ptr<Scenario> make_hybrid_adaptive_bias();
std::unique_ptr<Scenario> make_hybrid_nonadaptive_bias();
std::unique_ptr<Scenario> make_hybrid_adaptive_10hz();
std::unique_ptr<Scenario> make_hybrid_adaptive_projection();
std::unique_ptr<Scenario> make_hybrid_adaptive_calibrated();
std::unique_ptr<Scenario> make_hybrid_nonadaptive_calibrated();
std::unique_ptr<Scenario> make_hybrid_fault_stuck_gimbal();
std::unique_ptr<Scenario> make_hybrid_fault_wheel();
std::unique_ptr<Scenario> make_flexible_ppc();
std::unique_ptr<Scenario> make_flexible_atc();
std::unique_ptr<Scenario> make_flexible_ppc_halfgain();
std::unique_ptr<Scenario> make_flexible_atc_halfgain();
std::unique_ptr<Scenario> make_flexible_fault_sensor_dropout();
std::unique_ptr<Scenario> make_dragfree_estimators();
std::unique_ptr<Scenario> make_dragfree_adrc();
std::unique_ptr<Scenario> make_dragfree_pid();
std::unique_ptr<Scenario> make_dragfree_adrc_tuned();
std::unique_ptr<Scenario> make_se3_ptc();
std::unique_ptr<Scenario> make_se3_ftsmc();
std::unique_ptr<Scenario> make_se3_campaign();
std::unique_ptr<Scenario> make_cmg_singularity_escape();
std::unique_ptr<Scenario> make_cubesat_mrp_pd();
std::unique_ptr<Scenario> make_cubesat_ppc_10hz();
std::unique_ptr<Scenario> make_hybrid_ppc();
std::unique_ptr<Scenario> make_vscmg_mrp_pd();
std::unique_ptr<Scenario> make_flexible_eso_adrc();
std::unique_ptr<Scenario> make_rigid_rw_prescribed_time();

namespace ADCS_UNITY_ID {

std::vector<std::unique_ptr<Scenario>> build_registry() {
  std::vector<std::unique_ptr<Scenario>> v;
  v.push_back(make_rigid_rw_torquefree());
  v.push_back(make_rigid_rw_mrp_pd());
  v.push_back(make_hybrid_adaptive());
  v.push_back(make_hybrid_nonadaptive());
  v.push_back(make_hybrid_adaptive_bias());
  v.push_back(make_hybrid_nonadaptive_bias());
  v.push_back(make_hybrid_adaptive_10hz());
  v.push_back(make_hybrid_adaptive_projection());
  v.push_back(make_hybrid_adaptive_calibrated());
  v.push_back(make_hybrid_nonadaptive_calibrated());
  v.push_back(make_hybrid_fault_stuck_gimbal());
  v.push_back(make_hybrid_fault_wheel());
  v.push_back(make_flexible_ppc());
  v.push_back(make_flexible_atc());
  v.push_back(make_flexible_ppc_halfgain());
  v.push_back(make_flexible_atc_halfgain());
  v.push_back(make_flexible_fault_sensor_dropout());
  v.push_back(make_dragfree_estimators());
  v.push_back(make_dragfree_adrc());
  v.push_back(make_dragfree_pid());
  v.push_back(make_dragfree_adrc_tuned());
  v.push_back(make_se3_ptc());
  v.push_back(make_se3_ftsmc());
  v.push_back(make_se3_campaign());
  v.push_back(make_cmg_singularity_escape());
  v.push_back(make_cubesat_mrp_pd());
  v.push_back(make_cubesat_ppc_10hz());
  v.push_back(make_hybrid_ppc());
  v.push_back(make_vscmg_mrp_pd());
  v.push_back(make_flexible_eso_adrc());
  v.push_back(make_rigid_rw_prescribed_time());
  return v;
}

bool file_safe(const std::string& n) {
  if (n.empty() || n.front() == '-') return false;
  return std::all_of(n.begin(), n.end(), [](char c) {
    return (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '-';
  });
}

}  // namespace

using namespace ADCS_UNITY_ID;  // as an anonymous namespace would (CMakeLists.txt, adcs_unity)

const std::vector<std::unique_ptr<Scenario>>& all_scenarios() {
  static const std::vector<std::unique_ptr<Scenario>> scenarios = build_registry();
  return scenarios;
}

const Scenario* find_scenario(const std::string& name) {
  for (const auto& s : all_scenarios())
    if (s && s->name() == name) return s.get();
  return nullptr;
}

std::vector<std::string> scenario_problems(const Scenario& s) {
  std::vector<std::string> out;
  if (!file_safe(s.name()))
    out.push_back("name '" + s.name() + "' must be lower-case letters, digits and '-'");
  if (s.description().empty()) out.push_back("empty description");
  ParamSet ps;
  try {
    s.declare(ps);
  } catch (const std::exception& e) {
    out.push_back(std::string("declare() throws: ") + e.what());
    return out;
  }
  for (const char* key : {"duration_s", "control_period_s"}) {
    if (!ps.has(key)) {
      out.push_back(std::string("does not declare '") + key + "'");
    } else if (ps.at(key).kind != ParamKind::number) {
      out.push_back(std::string("'") + key + "' must be a number");
    } else if (!(ps.at(key).value.number > 0.0)) {
      out.push_back(std::string("'") + key + "' default must be > 0");
    }
  }
  for (const auto& p : ps)
    if (p.source.empty()) out.push_back("parameter '" + p.key + "' has no source");
  return out;
}

std::vector<std::string> registry_problems() {
  std::vector<std::string> out;
  std::set<std::string> seen;
  const auto& all = all_scenarios();
  if (all.empty()) out.push_back("no scenario registered");
  for (std::size_t i = 0; i < all.size(); ++i) {
    if (!all[i]) {
      out.push_back("registry entry " + std::to_string(i) + " is null");
      continue;
    }
    const std::string n = all[i]->name();
    if (!seen.insert(n).second) out.push_back(n + ": registered twice");
    for (const auto& p : scenario_problems(*all[i])) out.push_back(n + ": " + p);
  }
  return out;
}

}  // namespace adcs::sim
