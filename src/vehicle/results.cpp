#include "vehicle/results.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "sim/metrics.hpp"
#include "sim/sim_error.hpp"
#include "sim/format.hpp"

namespace adcs::sim::vehicle {
namespace ADCS_UNITY_ID {

constexpr double kRad2Deg = 180.0 / kPiRad;

}  // namespace
using namespace ADCS_UNITY_ID;  // as an anonymous namespace would (CMakeLists.txt, adcs_unity)

std::vector<Column> common_columns() {
  std::vector<Column> c{{"t", "s"}, {"att_err_deg", "deg"}};
  for (int i = 1; i <= 3; ++i) c.push_back({"sigma_BN_" + std::to_string(i), "-"});
  for (int i = 1; i <= 3; ++i) c.push_back({"omega_BN_B_" + std::to_string(i), "rad/s"});
  for (int i = 1; i <= 3; ++i) c.push_back({"torque_B_" + std::to_string(i), "N m"});
  for (int i = 1; i <= 3; ++i) c.push_back({"L_r_B_" + std::to_string(i), "N m"});
  for (int i = 1; i <= 3; ++i) c.push_back({"L_dist_B_" + std::to_string(i), "N m"});
  c.push_back({"att_knowledge_err_deg", "deg"});
  c.push_back({"star_tracker_valid", "-"});
  return c;
}

RunTrace::RunTrace(const VehicleConfig& c) : c_(c) {}

void RunTrace::observe(double t_s, const Vec3& sigma_BN, const Vec3& omega_BN_B, double err_rad,
                       double knowledge_err_rad, const Vec3& torque_B_Nm, const Vec3& request_B_Nm,
                       const Vec3& disturbance_B_Nm, bool star_tracker_valid, std::vector<double>* row) {
  t_.push_back(t_s);
  err_.push_back(err_rad);
  if (t_s >= c_.run.steady_t0_s && t_s <= c_.run.steady_t1_s) {
    err_ss_max_ = std::max(err_ss_max_, err_rad);
    ++steady_samples_;
  }
  torque_max_ = std::max(torque_max_, torque_B_Nm.cwiseAbs().maxCoeff());
  knowledge_err_max_ = std::max(knowledge_err_max_, knowledge_err_rad);
  if (!row) return;
  row->clear();
  row->push_back(t_s);
  row->push_back(kRad2Deg * err_rad);
  for (const Vec3* v : {&sigma_BN, &omega_BN_B, &torque_B_Nm, &request_B_Nm, &disturbance_B_Nm})
    for (int i = 0; i < 3; ++i) row->push_back((*v)(i));
  row->push_back(kRad2Deg * knowledge_err_rad);
  row->push_back(star_tracker_valid ? 1.0 : 0.0);
}

void RunTrace::control_step(Status law, Status actuation, bool limited) noexcept {
  ++steps_;
  if (limited) ++limited_;
  if (!usable(law) || !written(actuation)) ++rejected_;
}

RunResult RunTrace::finish(const std::vector<std::pair<std::string, double>>& extra, long star_tracker_samples,
                           long star_tracker_dropouts) const {
  const double err_final = err_.empty() ? NAN : err_.back();
  const double err_max = err_.empty() ? NAN : *std::max_element(err_.begin(), err_.end());
  // Settling from the last change of target: over the samples from that time on.
  const double t_change = c_.reference.last_change_s(c_.run.duration_s);
  double settle = NAN;
  if (c_.pointing_deg) {
    const auto first = std::lower_bound(t_.begin(), t_.end(), t_change);
    const std::size_t k = static_cast<std::size_t>(first - t_.begin());
    const std::vector<double> t(t_.begin() + static_cast<std::ptrdiff_t>(k), t_.end());
    const std::vector<double> e(err_.begin() + static_cast<std::ptrdiff_t>(k), err_.end());
    settle = metrics::settling_time(t, e, c_.pointing_deg->value / kRad2Deg);
  }
  // No sample in the steady window (t0 = t1 between two samples): no steady error, not 0.
  const double err_ss = steady_samples_ > 0 ? kRad2Deg * err_ss_max_ : NAN;
  RunResult r;
  r.metrics = {{"att_err_ss_max_deg", err_ss},
               {"att_err_final_deg", kRad2Deg * err_final},
               {"att_err_max_deg", kRad2Deg * err_max},
               {"settle_s", settle},
               {"torque_max_Nm", torque_max_},
               {"saturated_fraction", steps_ ? double(limited_) / double(steps_) : 0.0},
               {"rejected_steps", double(rejected_)},
               {"star_tracker_samples", double(star_tracker_samples)},
               {"star_tracker_dropouts", double(star_tracker_dropouts)},
               {"att_knowledge_err_max_deg", kRad2Deg * knowledge_err_max_}};
  r.metrics.insert(r.metrics.end(), extra.begin(), extra.end());

  // The file's requirements, as checks a campaign counts ("held in 997 / 1000").
  const std::string window = fmt("[%g, ", c_.run.steady_t0_s) + fmt("%g] s", c_.run.steady_t1_s);
  if (c_.pointing_deg) {
    const double req = c_.pointing_deg->value, ours = err_ss;
    r.claims.push_back({"check", "pointing: max principal attitude error over the steady window " + window,
                        "<= " + fmt("%g deg", req), std::isnan(ours) ? "no sample in the window" : fmt("%.4g deg", ours),
                        ours <= req,
                        std::nullopt, "requirements.pointing_deg (" + c_.pointing_deg->where + ")"});
  }
  if (c_.settle_s) {
    const double req = c_.settle_s->value;
    const std::string ours = std::isnan(settle) ? "never settles" : fmt("%.4g s", settle);
    r.claims.push_back({"check",
                        "settling: within pointing_deg from " + fmt("%g s", t_change) + " (last reference change) on",
                        "<= " + fmt("%g s", req), ours, !std::isnan(settle) && settle <= req, std::nullopt,
                        "requirements.settle_s (" + c_.settle_s->where + ")"});
  }
  const std::string n = c_.name;
  PlotSpec err{n + "-error.png", "Principal attitude error vs the reference", "t", {"att_err_deg", "att_knowledge_err_deg"},
               "error [deg]", true};
  if (c_.pointing_deg) err.hline = {{c_.pointing_deg->value, "requirements.pointing_deg"}};
  r.plots.push_back(err);
  r.plots.push_back({n + "-torque.png", "Actuator torque on the body", "t", {"torque_B_1", "torque_B_2", "torque_B_3"},
                     "torque [N m]", false});
  r.plots.push_back({n + "-omega.png", "Body rate omega_BN_B", "t", {"omega_BN_B_1", "omega_BN_B_2", "omega_BN_B_3"},
                     "omega_BN_B [rad/s]", false});
  return r;
}

void check_finite_state(double t_s, bool finite) {
  if (!finite) throw SimError("vehicle run: the state is not finite at t = " + format_double(t_s) + " s");
}

}  // namespace adcs::sim::vehicle
