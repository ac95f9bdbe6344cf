#pragma once
// What the two rigid-body + reaction-wheel scenarios share: the spacecraft parameters (declared
// once, with units and sources), the initial state (optionally drawn from --seed), the
// integrator choice, and the CSV columns users compare with other tools.
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "adcs/actuator/limits.hpp"
#include "adcs/core/signals.hpp"
#include "adcs/plant/rigid_body_rw.hpp"
#include "scenarios/scenario.hpp"
#include "sim/closed_loop.hpp"
#include "sim/recorder.hpp"

namespace adcs::sim {

inline constexpr int kRigidRwWheels = 4;
using RigidRwPlant = adcs::RigidBodyRw<kRigidRwWheels>;

//! Defaults that differ between the scenarios.
struct RigidRwDefaults {
  std::vector<std::vector<double>> J_kgm2;
  std::vector<double> wheel_Js_kgm2;
  std::vector<double> sigma0_BN, omega0_BN_B, Omega0_rad_s;
  double duration_s = 0.0, control_period_s = 0.0;
  std::string source;  //!< why these defaults
  //! One row per wheel spin axis; empty: 3 orthogonal + 1 skewed (the foundation issue's set).
  std::vector<std::vector<double>> wheel_axes_B = {};
  std::string wheel_axes_source = {};
};

//! The 12U cubesat manoeuvre of issue 15, flown by cubesat-mrp-pd and cubesat-ppc-10hz: J
//! diag(0.20, 0.25, 0.15) kg m², four 3 mN m wheels in a 30° pyramid, at rest, a 30° rest-to-rest
//! slew about (1, 2, 3)/√14 and a 300 s hold, at 10 Hz.
struct CubesatManoeuvre {
  RigidRwDefaults defaults;      //!< vehicle, initial state, duration, 10 Hz
  std::vector<double> sigma_RN;  //!< [-] the inertial target, tan(30°/4) (1, 2, 3)/√14
  double torque_limit_Nm = 0.0;  //!< per wheel
  const char* source = "";       //!< the issue's words for all of the above
};
CubesatManoeuvre cubesat_12u_manoeuvre();

//! Declares duration_s, control_period_s, J_kgm2, wheel_axes_B, wheel_Js_kgm2, sigma0_BN,
//! omega0_BN_B, Omega0_rad_s, omega0_dispersion_rad_s, integrator, rtol, atol, rk4_step_s,
//! record_every.
void declare_rigid_rw(ParamSet& p, const RigidRwDefaults& d);

//! Declares the wheel limits of a controlled scenario: torque_limit_Nm (per wheel motor) and
//! wheel_speed_limit_rad_s (per wheel; the same for every wheel).
void declare_wheel_limits(ParamSet& p, double torque_limit_Nm, const std::string& torque_source);

//! The declared wheel limits (actuator/limits.hpp); throws ParamError unless both are > 0.
ActuatorLimits<0, kRigidRwWheels> wheel_limits(const ParamSet& p);

//! The plant's wheel input from the allocated torques: each wheel's speed limit applied
//! (actuator/limits.hpp; the torque limit is the allocator's), u's wheel part set, its external
//! torque part left to the caller; wheels held at their speed limit are added to `speed_held`.
void set_wheel_input(const ActuatorLimits<0, kRigidRwWheels>& limits, const RigidRwPlant::State& x,
                     const WheelTorques<kRigidRwWheels>& w, RigidRwPlant::Input& u, long& speed_held);

//! Plant parameters from the ParamSet; throws ParamError when they are not physical.
RigidRwPlant::Params rigid_rw_plant_params(const ParamSet& p);

//! Initial state. seed == 0: the declared sigma0/omega0/Omega0. seed > 0: sigma0_BN uniform over
//! SO(3) (short MRP set) and omega0_BN_B uniform in +-omega0_dispersion_rad_s per axis, drawn
//! with our portable generator, so the same seed gives the same run on every machine.
//! When `used` is given and seed > 0, the drawn sigma0_BN and omega0_BN_B are appended to it
//! (RunResult::used), so the run's JSON records the initial state actually simulated.
RigidRwPlant::State rigid_rw_initial_state(const ParamSet& p, std::uint64_t seed,
                                           std::vector<UsedValue>* used = nullptr);

//! The CSV columns t, sigma_BN_1..3, omega_BN_B_1..3, Omega_1..4, then `extra`.
std::vector<Column> rigid_rw_columns(const std::vector<Column>& extra = {});

//! Appends t and the plant state to `row` (in rigid_rw_columns() order).
void rigid_rw_row(double t, const RigidRwPlant::State& x, std::vector<double>& row);

//! The integrator the parameters select ("integrator" adams / bdf / rk4, "rtol", "atol",
//! "rk4_step_s", declared by declare_rigid_rw_plant): the one choice of sim/closed_loop.hpp.
IntegratorChoice integrator_choice(const ParamSet& p);

}  // namespace adcs::sim
