#pragma once
// What every vehicle-file run measures, whatever its actuators (issue 18): the attitude error
// against the reference in force, the torque on the body, the steps that were limited or
// rejected; turned into the metrics, the requirement claims and the plots of RunResult. The
// loops (vehicle/rw_loop.hpp, vehicle/cmg_loop.hpp) add their actuator metrics and columns.
//
// Metrics (all runs): att_err_ss_max_deg (max principal error over run.steady_window_s),
// att_err_final_deg, att_err_max_deg, settle_s (from the last reference change: the time to enter
// and stay within requirements.pointing_deg; NaN without that requirement or when it never
// settles), torque_max_Nm (max |component| of the actuators' torque on the body),
// saturated_fraction (control steps whose command was scaled or clipped), rejected_steps (law
// step not usable, or the actuation stage wrote nothing), star_tracker_samples,
// star_tracker_dropouts, att_knowledge_err_max_deg (max error of the attitude given to the law).
#include <string>
#include <utility>
#include <vector>

#include "adcs/core/status.hpp"
#include "adcs/core/types.hpp"
#include "scenarios/scenario.hpp"
#include "sim/recorder.hpp"
#include "vehicle/config.hpp"

namespace adcs::sim::vehicle {

//! The CSV columns every run writes first: t, att_err_deg, sigma_BN_1..3, omega_BN_B_1..3,
//! torque_B_1..3 (actuators on the body), L_r_B_1..3 (the law's request), L_dist_B_1..3 (external
//! torque), att_knowledge_err_deg, star_tracker_valid.
std::vector<Column> common_columns();

class RunTrace {
 public:
  explicit RunTrace(const VehicleConfig& c);

  //! One observation (every control sample, then the final one at t_end).
  //! err_rad: true principal error vs the reference in force; knowledge_err_rad: error of the
  //! attitude the law was given; torque_B_Nm: actuators on the body. Appends the common columns
  //! to `row` (cleared first) when recording.
  void observe(double t_s, const Vec3& sigma_BN, const Vec3& omega_BN_B, double err_rad, double knowledge_err_rad,
               const Vec3& torque_B_Nm, const Vec3& request_B_Nm, const Vec3& disturbance_B_Nm,
               bool star_tracker_valid, std::vector<double>* row);
  //! Once per control step: the law's and the actuation stage's statuses, and whether the
  //! command was scaled or clipped anywhere on its way to the actuators.
  void control_step(Status law, Status actuation, bool limited) noexcept;

  //! Metrics (common, then `extra`), the requirement claims, and the common plots.
  RunResult finish(const std::vector<std::pair<std::string, double>>& extra, long star_tracker_samples,
                   long star_tracker_dropouts) const;

 private:
  const VehicleConfig& c_;
  std::vector<double> t_, err_;
  double err_ss_max_ = 0.0, torque_max_ = 0.0, knowledge_err_max_ = 0.0;
  long steps_ = 0, limited_ = 0, rejected_ = 0, steady_samples_ = 0;
};

//! Throws SimError when the state is not finite (the campaign records a failed run).
void check_finite_state(double t_s, bool finite);

}  // namespace adcs::sim::vehicle
