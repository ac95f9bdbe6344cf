#pragma once
// The wheels-only loop of a vehicle file (actuation.type = rw_allocation), a sim/closed_loop.hpp
// composition at control_period_s with a zero-order hold:
//   sensors (vehicle/sensors.hpp) → the law (MrpPd<N> or PPC, vehicle/law.hpp) → RwTorqueAllocator<N>
//   (believed axes; min-norm, scaled into the smallest wheel's torque limit) → each wheel's torque and
//   speed limit (actuator/limits.hpp) → RigidBodyRw<N> (truth) + friction + external torques
//   (vehicle/plants.hpp), CVODE or RK4.
// Included only by the rw_loop_N.cpp instantiation files.
#include <algorithm>
#include <memory>
#include <string>
#include <vector>

#include "adcs/actuator/limits.hpp"
#include "adcs/actuator/rw_allocation.hpp"
#include "adcs/math/mrp.hpp"
#include "adcs/plant/rigid_body_rw.hpp"
#include "sim/closed_loop.hpp"
#include "sim/recorder.hpp"
#include "vehicle/disturbances.hpp"
#include "vehicle/law.hpp"
#include "vehicle/loops.hpp"
#include "vehicle/plants.hpp"
#include "vehicle/results.hpp"
#include "vehicle/sensors.hpp"

namespace adcs::sim::vehicle {

template <int N>
RunResult run_rw_loop(const VehicleConfig& c, const RunContext& ctx) {
  using Body = RigidBodyRw<N>;
  using State = typename Body::State;
  using Input = typename Body::Input;

  // The truth, and what the controller and the allocator believe (knowledge).
  typename Body::Params truth_params;
  truth_params.J_B = c.J_kgm2;
  truth_params.G_s_B = c.wheels.axes_B;
  truth_params.J_s = c.wheels.J_s_kgm2;
  const Body body(truth_params);
  typename Body::Params believed_params;
  believed_params.J_B = c.knowledge.J_kgm2;
  believed_params.G_s_B = c.knowledge.wheel_axes_B;
  believed_params.J_s = c.knowledge.wheel_J_s_kgm2;
  const Body believed(believed_params);
  if (body.status() != Status::ok || believed.status() != Status::ok)
    throw ParamError(c.name + ": the rigid body + wheel parameters were refused (RigidBodyRw)");
  const DisturbanceModel disturbances(c.disturbances, c.J_kgm2);
  const RwVehiclePlant<N> plant{&body, &disturbances, Vec<N>(c.wheels.friction_Nm_s)};

  VehicleLaw<N> law(make_law_params<N>(c.controller, c.run.control_period_s, believed_params.J_B, believed.J_rw(),
                                       believed_params.G_s_B, believed_params.J_s));
  if (law.status() != Status::ok) throw ParamError(c.name + ": the controller parameters were refused (see [controller])");
  RwAllocationParams<N> ap;
  ap.G_s_B = believed_params.G_s_B;
  // One common scale for the request keeps its direction (rw_allocation.hpp); it fits the
  // weakest wheel, and limit_wheel_torques below holds every wheel to its own limit.
  ap.torque_limit = c.wheels.torque_max_Nm.minCoeff();
  RwTorqueAllocator<N> allocator(ap);
  if (allocator.status() != Status::ok) throw ParamError(c.name + ": the wheel allocation was refused (axes must span R^3)");
  ActuatorLimits<0, N> limits;
  limits.wheel_torque_max_Nm = c.wheels.torque_max_Nm;
  limits.wheel_speed_max_rad_s = c.wheels.speed_max_rad_s;

  State x;
  x.template head<3>() = c.sigma0_BN;
  x.template segment<3>(3) = c.omega0_BN_B;
  x.template tail<N>() = c.wheels.Omega0_rad_s;

  SensorModel sensors(c.gyro, c.star_tracker, c.run.control_period_s, ctx.seed);
  std::unique_ptr<CsvRecorder> csv;
  if (!ctx.csv_path.empty()) {
    std::vector<Column> cols = common_columns();
    for (int j = 1; j <= N; ++j) cols.push_back({"u_s_" + std::to_string(j), "N m"});
    for (int j = 1; j <= N; ++j) cols.push_back({"Omega_" + std::to_string(j), "rad/s"});
    csv = std::make_unique<CsvRecorder>(ctx.csv_path, cols, c.run.record_every);
  }

  RunTrace trace(c);
  std::vector<double> row;
  Vec3 sigma_given = Vec3::Zero();
  bool limited = false;
  long speed_held = 0;
  double wheel_speed_max = 0.0, wheel_torque_max = 0.0;

  auto sense = [&](double t, const State& xs) {
    const AttitudeState m = sensors.measure(AttitudeState{Body::sigma_BN(xs), Body::omega_BN_B(xs)});
    sigma_given = m.sigma_BN;
    typename VehicleLaw<N>::Input in;
    in.t_s = t;
    in.state = m;
    in.Omega_rad_s = Body::Omega(xs);  // wheel tachometers: exact
    in.reference.sigma_RN = c.reference.target(t);
    return in;
  };
  auto to_actuation = [](double, const State&, const BodyTorque& cmd) { return cmd; };
  auto to_plant = [&](double, const State& xs, const WheelTorques<N>& w, Input& u) {
    Vec<N> u_s = w.u_s_Nm;  // zero when the allocator refused (the wheels coast)
    LimitReport lr;
    const Status ls = limit_wheel_torques<N>(limits, Body::Omega(xs), u_s, &lr);
    limited = ls == Status::saturated;
    speed_held += lr.wheel_speed_held;
    u.template head<N>() = u_s;
    u.template tail<3>().setZero();  // external torques act inside the dynamics (RwVehiclePlant)
  };
  auto observe = [&](const auto& s) {
    const State& xs = s.x;
    check_finite_state(s.t_s, all_finite(xs));
    const Vec3 target = c.reference.target(s.t_s);
    const Vec3 sigma = Body::sigma_BN(xs);
    const double err = mrp_principal_angle(mrp_subtract(sigma, target));
    const double given_err = mrp_principal_angle(mrp_subtract(sigma_given, sigma));
    const Vec<N> u_s = s.u.template head<N>();
    const Vec3 torque = -truth_params.G_s_B * (u_s - plant.friction_Nm_s.cwiseProduct(Body::Omega(xs)));
    if (!s.final)
      trace.control_step(s.controller_status, s.actuation_status,
                         s.actuation_status == Status::saturated || limited);
    wheel_speed_max = std::max(wheel_speed_max, Body::Omega(xs).cwiseAbs().maxCoeff());
    wheel_torque_max = std::max(wheel_torque_max, u_s.cwiseAbs().maxCoeff());
    trace.observe(s.t_s, sigma, Body::omega_BN_B(xs), err, given_err, torque, s.command.torque_B_Nm,
                  disturbances.torque_B_Nm(s.t_s, sigma), sensors.star_tracker_valid(), csv ? &row : nullptr);
    if (csv) {
      for (int j = 0; j < N; ++j) row.push_back(u_s(j));
      for (int j = 0; j < N; ++j) row.push_back(Body::Omega(xs)(j));
      csv->record_row(row, s.final);
    }
  };
  SampledDataOptions opt;
  opt.t_end = c.run.duration_s;
  opt.sample_period = c.run.control_period_s;
  const long steps = closed_loop(plant, x, opt, c.run.integrator, sense, law, to_actuation, allocator, to_plant, observe);
  if (csv) csv->close();

  RunResult r = trace.finish({{"wheel_speed_max_rad_s", wheel_speed_max},
                              {"wheel_torque_max_Nm", wheel_torque_max},
                              {"wheel_speed_held", double(speed_held)},
                              {"funnel_recoveries", double(law.funnel_recoveries())},
                              {"integrator_steps", double(steps)}},
                             sensors.star_tracker_samples(), sensors.star_tracker_dropouts());
  std::vector<std::string> speeds, torques;
  for (int j = 1; j <= N; ++j) {
    speeds.push_back("Omega_" + std::to_string(j));
    torques.push_back("u_s_" + std::to_string(j));
  }
  r.plots.push_back({c.name + "-wheels.png", "Wheel speeds", "t", speeds, "Omega [rad/s]", false});
  r.plots.push_back({c.name + "-wheel-torques.png", "Wheel motor torques", "t", torques, "u_s [N m]", false});
  return r;
}

}  // namespace adcs::sim::vehicle
