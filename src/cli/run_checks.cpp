// Values that make no sense for any scenario, refused before running (commands.hpp).
#include "cli/commands.hpp"

namespace adcs::sim::cli {
namespace ADCS_UNITY_ID {

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

}  // namespace
using namespace ADCS_UNITY_ID;  // as an anonymous namespace would (CMakeLists.txt, adcs_unity)

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

}  // namespace adcs::sim::cli
