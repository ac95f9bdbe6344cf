#include "vehicle/schema.hpp"

namespace adcs::sim::vehicle {
namespace ADCS_UNITY_ID {

KeySpec required(std::string_view table, std::string_view key, Shape shape, std::string_view unit,
                 std::string_view only_for = {}) {
  return KeySpec{table, key, shape, unit, Presence::required, 0.0, {}, {}, {}, only_for, {}};
}

//! A number, or a vector / matrix filled with `value`.
KeySpec with_default(std::string_view table, std::string_view key, Shape shape, std::string_view unit,
                     double value, std::string_view doc) {
  return KeySpec{table, key, shape, unit, Presence::defaulted, value, {}, {}, {}, {}, doc};
}

KeySpec name_key(std::string_view table, std::string_view key, std::vector<std::string_view> allowed,
                 std::string_view default_name, std::string_view doc, std::string_view only_for = {}) {
  const Presence p = default_name.empty() ? Presence::required : Presence::defaulted;
  return KeySpec{table, key, Shape::name, "", p, 0.0, default_name, {}, std::move(allowed), only_for, doc};
}

KeySpec copy_of(std::string_view table, std::string_view key, Shape shape, std::string_view unit,
                std::string_view from) {
  return KeySpec{table, key, shape, unit, Presence::defaulted, 0.0, {}, from, {}, {}, "the nominal truth value"};
}

KeySpec optional(std::string_view table, std::string_view key, std::string_view unit) {
  return KeySpec{table, key, Shape::number, unit, Presence::optional, 0.0, {}, {}, {}, {}, {}};
}

std::vector<KeySpec> build_keys() {
  const std::string_view kPd = "mrp_pd", kPpc = "ppc";
  std::vector<KeySpec> k;
  k.push_back(required("", "name", Shape::text, ""));
  k.push_back(required("", "description", Shape::text, ""));
  // [run]
  k.push_back(required("run", "duration_s", Shape::number, "s"));
  k.push_back(required("run", "control_period_s", Shape::number, "s"));
  k.push_back(name_key("run", "integrator", {"adams", "bdf", "rk4"}, "adams",
                       "CVODE Adams + fixed point (sim/closed_loop.hpp IntegratorChoice)"));
  k.push_back(with_default("run", "rtol", Shape::number, "-", 1e-10, "CVODE rtol of sim/closed_loop.hpp IntegratorChoice"));
  k.push_back(with_default("run", "atol", Shape::number, "state units", 1e-12,
                           "CVODE atol of sim/closed_loop.hpp IntegratorChoice"));
  k.push_back(with_default("run", "rk4_step_s", Shape::number, "s", 0.01, "RK4 sub-step of sim/closed_loop.hpp"));
  k.push_back(with_default("run", "record_every", Shape::number, "samples", 1.0, "every control sample in the CSV"));
  k.push_back(required("run", "steady_window_s", Shape::vec2, "s"));
  // [spacecraft]: the truth
  k.push_back(required("spacecraft", "J_kgm2", Shape::mat33, "kg m^2"));
  k.push_back(with_default("spacecraft", "sigma0_BN", Shape::vec3, "-", 0.0, "B aligned with N"));
  k.push_back(with_default("spacecraft", "omega0_BN_B", Shape::vec3, "rad/s", 0.0, "at rest"));
  // [wheels]
  k.push_back(required("wheels", "axes_B", Shape::mat_wheels, "-"));
  k.push_back(required("wheels", "J_s_kgm2", Shape::vec_wheels, "kg m^2"));
  k.push_back(required("wheels", "torque_max_Nm", Shape::vec_wheels, "N m"));
  k.push_back(required("wheels", "speed_max_rad_s", Shape::vec_wheels, "rad/s"));
  k.push_back(with_default("wheels", "friction_Nm_s", Shape::vec_wheels, "N m s", 0.0,
                           "no friction (the ideal wheel of the registered scenarios)"));
  k.push_back(with_default("wheels", "Omega0_rad_s", Shape::vec_wheels, "rad/s", 0.0, "wheels at rest"));
  // [cmgs]
  k.push_back(required("cmgs", "gimbal_axes_B", Shape::mat_cmgs, "-"));
  k.push_back(required("cmgs", "spin_axes_B", Shape::mat_cmgs, "-"));
  k.push_back(required("cmgs", "h_Nms", Shape::vec_cmgs, "N m s"));
  k.push_back(required("cmgs", "gimbal_rate_max_rad_s", Shape::vec_cmgs, "rad/s"));
  k.push_back(with_default("cmgs", "gamma0_rad", Shape::vec_cmgs, "rad", 0.0, "gimbals at 0 (spin axes as given)"));
  k.push_back(name_key("cmgs", "steering", {"escape", "robust"}, "escape",
                       "Wie 2005's escape law with its published constants (actuator/steering.hpp)"));
  // [sensors.*]: absent = perfect
  k.push_back(required("sensors.gyro", "arw_rad_sqrt_s", Shape::number, "rad/sqrt(s)"));
  k.push_back(required("sensors.gyro", "rrw_rad_s_sqrt_s", Shape::number, "rad/s/sqrt(s)"));
  k.push_back(required("sensors.gyro", "bias_rad_s", Shape::vec3, "rad/s"));
  k.push_back(required("sensors.star_tracker", "noise_rad", Shape::number, "rad"));
  k.push_back(required("sensors.star_tracker", "rate_hz", Shape::number, "Hz"));
  k.push_back(with_default("sensors.star_tracker", "dropout_probability", Shape::number, "-", 0.0,
                           "every sample valid"));
  // [disturbances]
  k.push_back(with_default("disturbances", "constant_torque_B_Nm", Shape::vec3, "N m", 0.0, "none"));
  k.push_back(required("disturbances.harmonic", "amplitude_B_Nm", Shape::vec3, "N m"));
  k.push_back(required("disturbances.harmonic", "frequency_rad_s", Shape::number, "rad/s"));
  k.push_back(with_default("disturbances.harmonic", "phase_rad", Shape::vec3, "rad", 0.0, "sine from t = 0"));
  k.push_back(name_key("disturbances.gravity_gradient", "enabled", {"true", "false"}, "true",
                       "on when the table is present"));
  k.back().shape = Shape::flag;
  k.push_back(required("disturbances.gravity_gradient", "altitude_m", Shape::number, "m"));
  // [controller]
  k.push_back(name_key("controller", "type", {kPd, kPpc}, "", ""));
  k.push_back(name_key("controller", "on_failure", {"safe_command", "hold_last"}, "safe_command",
                       "zero torque after a failed step (docs/FAILURE-POLICY.md)"));
  k.push_back(required("controller", "K_Nm", Shape::number, "N m", kPd));
  k.push_back(required("controller", "P_Nms", Shape::vec3, "N m s", kPd));
  for (const char* v : {"rho0_deg", "rho_inf_deg"}) k.push_back(required("controller", v, Shape::vec3, "deg", kPpc));
  k.push_back(required("controller", "k_rho", Shape::vec3, "1/s", kPpc));
  k.push_back(required("controller", "delta", Shape::vec3, "-", kPpc));
  k.push_back(required("controller", "lambda", Shape::vec3, "1/s", kPpc));
  k.push_back(required("controller", "K", Shape::vec3, "rad/s", kPpc));
  k.push_back(required("controller", "tau_w", Shape::vec3, "-", kPpc));
  for (const char* v : {"tau_mu", "beta", "gamma", "sigma"}) k.push_back(required("controller", v, Shape::number, "-", kPpc));
  k.push_back(name_key("controller", "funnel_recovery", {"reopen", "none"}, "reopen",
                       "re-open a violated funnel from the current error (issue 15)", kPpc));
  // [actuation]
  k.push_back(name_key("actuation", "type", {"rw_allocation", "vscmg_steering"}, "", ""));
  // [reference], [[reference.slews]]
  k.push_back(required("reference", "sigma_RN", Shape::vec3, "-"));
  k.push_back(required("reference.slews", "t_s", Shape::number, "s"));
  k.push_back(required("reference.slews", "sigma_RN", Shape::vec3, "-"));
  // [knowledge]: what the controller believes; defaults to the nominal truth
  k.push_back(copy_of("knowledge", "J_kgm2", Shape::mat33, "kg m^2", "spacecraft.J_kgm2"));
  k.push_back(copy_of("knowledge", "wheel_axes_B", Shape::mat_wheels, "-", "wheels.axes_B"));
  k.push_back(copy_of("knowledge", "wheel_J_s_kgm2", Shape::vec_wheels, "kg m^2", "wheels.J_s_kgm2"));
  k.push_back(copy_of("knowledge", "cmg_gimbal_axes_B", Shape::mat_cmgs, "-", "cmgs.gimbal_axes_B"));
  k.push_back(copy_of("knowledge", "cmg_spin_axes_B", Shape::mat_cmgs, "-", "cmgs.spin_axes_B"));
  k.push_back(copy_of("knowledge", "cmg_h_Nms", Shape::vec_cmgs, "N m s", "cmgs.h_Nms"));
  // [requirements]: each becomes a claim when present
  k.push_back(optional("requirements", "pointing_deg", "deg"));
  k.push_back(optional("requirements", "settle_s", "s"));
  return k;
}

std::vector<TableSpec> build_tables() {
  return {{"", true, false},
          {"run", true, false},
          {"spacecraft", true, false},
          {"wheels", false, false},
          {"cmgs", false, false},
          {"sensors", false, false},
          {"sensors.gyro", false, false},
          {"sensors.star_tracker", false, false},
          {"disturbances", false, false},
          {"disturbances.harmonic", false, false},
          {"disturbances.gravity_gradient", false, false},
          {"controller", true, false},
          {"actuation", true, false},
          {"reference", true, false},
          {"reference.slews", false, true},
          {"knowledge", false, false},
          {"requirements", false, false}};
}

}  // namespace
using namespace ADCS_UNITY_ID;  // as an anonymous namespace would (CMakeLists.txt, adcs_unity)

const std::vector<KeySpec>& key_specs() {
  static const std::vector<KeySpec> keys = build_keys();
  return keys;
}

const std::vector<TableSpec>& table_specs() {
  static const std::vector<TableSpec> tables = build_tables();
  return tables;
}

const KeySpec* find_key(std::string_view table, std::string_view key) {
  for (const KeySpec& k : key_specs())
    if (k.table == table && k.key == key) return &k;
  return nullptr;
}

const TableSpec* find_table(std::string_view path) {
  for (const TableSpec& t : table_specs())
    if (t.path == path) return &t;
  return nullptr;
}

std::string param_name(std::string_view table, std::string_view key) {
  if (table.empty() || table == "run") return std::string(key);
  return std::string(table) + "." + std::string(key);
}

std::string param_name(const KeySpec& k) { return param_name(k.table, k.key); }

}  // namespace adcs::sim::vehicle
