#pragma once
// A vehicle file's parameters as the run uses them: typed, in SI units, and checked for meaning
// (unit axes, positive inertias and limits, a star-tracker rate that divides the control rate,
// ...). read_config() reads the ParamSet after any --set, so a value from the command line is
// checked the same way as one from the file; errors are ParamError "FILE:LINE: KEY: why" (or
// "KEY (--set): why").
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "adcs/actuator/vscmg_steering.hpp"
#include "adcs/adapt/ppc.hpp"
#include "adcs/core/failure_policy.hpp"
#include "adcs/core/types.hpp"
#include "scenarios/params.hpp"
#include "sim/closed_loop.hpp"
#include "vehicle/vehicle_file.hpp"

namespace adcs::sim::vehicle {

struct RunSettings {
  double duration_s = 0.0, control_period_s = 0.0;
  IntegratorChoice integrator;
  int record_every = 1;
  double steady_t0_s = 0.0, steady_t1_s = 0.0;  //!< [s] the steady window
};

//! N reaction wheels (N = 0: none). Axes are unit columns (B components).
struct WheelConfig {
  int count = 0;
  Eigen::MatrixXd axes_B;  //!< 3 x N
  Eigen::VectorXd J_s_kgm2, torque_max_Nm, speed_max_rad_s, friction_Nm_s, Omega0_rad_s;
};

//! M single-gimbal CMGs (M = 0: none). Spin axes at γ = 0, perpendicular to the gimbal axes.
struct CmgConfig {
  int count = 0;
  Eigen::MatrixXd gimbal_axes_B, spin_axes_B;  //!< 3 x M
  Eigen::VectorXd h_Nms, gimbal_rate_max_rad_s, gamma0_rad;
  SteeringLaw steering = SteeringLaw::escape;
};

struct GyroConfig {
  double arw_rad_sqrt_s = 0.0;    //!< white rate noise of spectral density arw² [rad²/s]
  double rrw_rad_s_sqrt_s = 0.0;  //!< bias random walk [rad/s/√s]
  Vec3 bias_rad_s = Vec3::Zero();  //!< initial bias
};

struct StarTrackerConfig {
  double noise_rad = 0.0;            //!< 1σ per axis
  double rate_hz = 0.0;
  double dropout_probability = 0.0;  //!< per star-tracker sample
  int every_samples = 1;             //!< one star-tracker sample every this many control samples
};

struct DisturbanceConfig {
  Vec3 constant_B_Nm = Vec3::Zero();
  bool harmonic = false;
  Vec3 amplitude_B_Nm = Vec3::Zero(), phase_rad = Vec3::Zero();
  double frequency_rad_s = 0.0;
  bool gravity_gradient = false;
  double altitude_m = 0.0;
};

struct ControllerConfig {
  bool ppc = false;  //!< false: MRP PD
  FailurePolicy on_failure = FailurePolicy::safe_command;
  double K_Nm = 0.0;  //!< MRP PD
  Vec3 P_Nms = Vec3::Zero();
  PpcParams<3> funnel{};  //!< PPC: ρ0, ρ∞ [rad], k, δ, recovery
  Vec3 lambda = Vec3::Zero(), K = Vec3::Zero(), tau_w = Vec3::Zero();
  double tau_mu = 0.0, beta = 0.0, gamma = 0.0, sigma = 0.0;
};

struct Slew {
  double t_s = 0.0;
  Vec3 sigma_RN = Vec3::Zero();
};

//! Inertial hold targets: sigma_RN from t = 0, then each slew's target from its t_s.
struct ReferenceConfig {
  Vec3 sigma_RN = Vec3::Zero();
  std::vector<Slew> slews;  //!< increasing t_s
  //! The target in force at t [s].
  Vec3 target(double t_s) const;
  //! The time of the last change of target at or before t_end [s] (0 without slews).
  double last_change_s(double t_end_s) const;
};

//! What the controller and the actuation stage believe (defaults: the nominal truth).
struct KnowledgeConfig {
  Mat3 J_kgm2 = Mat3::Zero();
  Eigen::MatrixXd wheel_axes_B, cmg_gimbal_axes_B, cmg_spin_axes_B;  //!< 3 x N, 3 x M, unit columns
  Eigen::VectorXd wheel_J_s_kgm2, cmg_h_Nms;
};

struct Requirement {
  double value = 0.0;
  std::string where;  //!< "FILE:LINE" (or "--set")
};

struct VehicleConfig {
  std::string name;
  RunSettings run;
  Mat3 J_kgm2 = Mat3::Zero();  //!< truth, total inertia incl. wheels
  Vec3 sigma0_BN = Vec3::Zero(), omega0_BN_B = Vec3::Zero();
  WheelConfig wheels;
  CmgConfig cmgs;
  std::optional<GyroConfig> gyro;
  std::optional<StarTrackerConfig> star_tracker;
  DisturbanceConfig disturbances;
  ControllerConfig controller;
  bool steering = false;  //!< actuation: vscmg_steering (true) or rw_allocation
  ReferenceConfig reference;
  KnowledgeConfig knowledge;
  std::optional<Requirement> pointing_deg, settle_s;
};

//! The run's configuration from the declared (and possibly --set) parameters; throws ParamError.
VehicleConfig read_config(const VehicleFile& file, const ParamSet& ps);

}  // namespace adcs::sim::vehicle
