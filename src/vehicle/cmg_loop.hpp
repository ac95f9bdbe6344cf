#pragma once
// The CMG loop of a vehicle file (actuation.type = vscmg_steering), a sim/closed_loop.hpp
// composition at control_period_s with a zero-order hold:
//   sensors (vehicle/sensors.hpp; the body rate of the momentum-form plant with the gimbal rates held
//   over the last period) → the law (MrpPd<N> with the wheels, or PPC; vehicle/law.hpp) → + ω × A_cs(γ) h
//   (the CMG rotors' believed momentum, which neither law's model has; as cross_vscmg.cpp's
//   vscmg-mrp-pd) → VscmgSteering<M, N> (believed geometry) → each gimbal's rate limit and each
//   wheel's torque and speed limit (actuator/limits.hpp) → VscmgFullPlant<M, N> (truth) + external
//   torques (vehicle/plants.hpp), CVODE or RK4.
// The torque on the body is τ = −Q_act(γ) u with the TRUE geometry (seed 001 eq. (11)).
// A pure CMG cluster is N = 0 throughout (plant, law, steering, limits): the flight code forms no
// product with the empty 3x0 wheel matrices (VscmgGeometry::internal_momentum, MrpPd::step).
// Included only by the cmg_loop_*.cpp instantiation files.
#include <algorithm>
#include <memory>
#include <string>
#include <vector>

#include "adcs/actuator/limits.hpp"
#include "adcs/actuator/vscmg_steering.hpp"
#include "adcs/math/mrp.hpp"
#include "adcs/plant/vscmg_cluster.hpp"
#include "sim/closed_loop.hpp"
#include "sim/recorder.hpp"
#include "vehicle/disturbances.hpp"
#include "vehicle/law.hpp"
#include "vehicle/loops.hpp"
#include "vehicle/plants.hpp"
#include "vehicle/results.hpp"
#include "vehicle/sensors.hpp"

namespace adcs::sim::vehicle {

//! A cluster geometry from a file's values: gimbal and spin axes (3 x M columns, spin ⟂ gimbal),
//! transverse axes t = g × s, rotor momenta, wheel axes and spin inertias; J_s = J − Σ I_ws s_w s_wᵀ
//! (J total, the gimbal and rotor inertias lumped into it: I_cs = I_ct = I_cg = 0); W wheels.
template <int M, int W>
VscmgGeometry<M, W> cmg_geometry(const Mat3& J_total_kgm2, const Eigen::MatrixXd& gimbal_axes_B,
                                 const Eigen::MatrixXd& spin_axes_B, const Eigen::VectorXd& h_Nms,
                                 const Eigen::MatrixXd& wheel_axes_B, const Eigen::VectorXd& wheel_J_s_kgm2) {
  VscmgGeometry<M, W> g;
  g.A_cg = gimbal_axes_B;
  g.A_cs0 = spin_axes_B;
  for (int i = 0; i < M; ++i) g.A_ct0.col(i) = Vec3(g.A_cg.col(i)).cross(Vec3(g.A_cs0.col(i)));
  g.h_cw = h_Nms;
  g.J_s = J_total_kgm2;
  if constexpr (W > 0) {
    g.A_ws = wheel_axes_B;
    g.I_wws = wheel_J_s_kgm2;
    for (int j = 0; j < W; ++j) g.J_s -= g.I_wws(j) * Vec3(g.A_ws.col(j)) * Vec3(g.A_ws.col(j)).transpose();
  }
  return g;
}

template <int M, int N>
RunResult run_cmg_loop(const VehicleConfig& c, const RunContext& ctx) {
  constexpr int NP = N;  // wheels of the plant and the law
  using Base = VscmgFullPlant<M, NP>;
  using State = typename Base::State;
  using Input = typename Base::Input;
  using Steering = VscmgSteering<M, N>;
  const KnowledgeConfig& k = c.knowledge;

  VscmgParams<M, NP> params;
  params.truth = cmg_geometry<M, NP>(c.J_kgm2, c.cmgs.gimbal_axes_B, c.cmgs.spin_axes_B, c.cmgs.h_Nms, c.wheels.axes_B,
                                     c.wheels.J_s_kgm2);
  params.nominal = cmg_geometry<M, NP>(k.J_kgm2, k.cmg_gimbal_axes_B, k.cmg_spin_axes_B, k.cmg_h_Nms, k.wheel_axes_B,
                                       k.wheel_J_s_kgm2);
  const Base cluster(params);
  if (cluster.status() != Status::ok) throw ParamError(c.name + ": the CMG cluster parameters were refused (VscmgFullPlant)");
  const DisturbanceModel disturbances(c.disturbances, c.J_kgm2);
  const CmgVehiclePlant<M, NP> plant{&cluster, &disturbances};
  const VscmgGeometry<M, NP>& believed = params.nominal;

  // MRP PD sees the wheels (J_rw = J − Σ I_ws s sᵀ = the believed J_s); the PPC law the total J.
  VehicleLaw<NP> law(make_law_params<NP>(c.controller, c.run.control_period_s, k.J_kgm2, believed.J_s, believed.A_ws,
                                         believed.I_wws));
  if (law.status() != Status::ok) throw ParamError(c.name + ": the controller parameters were refused (see [controller])");
  typename Steering::Params sp;  // the law's published constants (actuator/steering.hpp)
  sp.geometry = cmg_geometry<M, N>(k.J_kgm2, k.cmg_gimbal_axes_B, k.cmg_spin_axes_B, k.cmg_h_Nms, k.wheel_axes_B,
                                   k.wheel_J_s_kgm2);
  sp.law = c.cmgs.steering;
  Steering steering(sp);
  if (steering.status() != Status::ok) throw ParamError(c.name + ": the CMG steering geometry was refused");
  ActuatorLimits<M, NP> limits;
  limits.gimbal_rate_max_rad_s = c.cmgs.gimbal_rate_max_rad_s;
  Vec<NP> I_ws = Vec<NP>::Ones();  // the hardware's spin inertias (torque limit → acceleration limit)
  Vec<NP> Omega0 = Vec<NP>::Zero();
  if constexpr (N > 0) {
    limits.wheel_torque_max_Nm = c.wheels.torque_max_Nm;
    limits.wheel_speed_max_rad_s = c.wheels.speed_max_rad_s;
    I_ws = c.wheels.J_s_kgm2;
    Omega0 = c.wheels.Omega0_rad_s;
  }
  State x = cluster.initial_state(c.sigma0_BN, c.omega0_BN_B, Vec<M>(c.cmgs.gamma0_rad), Omega0);
  //! The real wheels' speeds (none for N = 0).
  auto wheel_speeds = [](const State& xs) {
    Vec<N> w;
    if constexpr (N > 0) w = Base::Omega_w(xs);
    return w;
  };

  SensorModel sensors(c.gyro, c.star_tracker, c.run.control_period_s, ctx.seed);
  std::unique_ptr<CsvRecorder> csv;
  if (!ctx.csv_path.empty()) {
    std::vector<Column> cols = common_columns();
    for (int i = 1; i <= M; ++i) cols.push_back({"gamma_dot_" + std::to_string(i), "rad/s"});
    for (int i = 1; i <= M; ++i) cols.push_back({"gamma_" + std::to_string(i), "rad"});
    for (int j = 1; j <= N; ++j) cols.push_back({"Omega_dot_" + std::to_string(j), "rad/s^2"});
    for (int j = 1; j <= N; ++j) cols.push_back({"Omega_" + std::to_string(j), "rad/s"});
    cols.push_back({"steering_torque_error", "-"});
    csv = std::make_unique<CsvRecorder>(ctx.csv_path, cols, c.run.record_every);
  }

  RunTrace trace(c);
  std::vector<double> row;
  Vec3 sigma_given = Vec3::Zero(), omega_given = Vec3::Zero();
  bool limited = false;
  long speed_held = 0, request_not_met = 0;
  double gimbal_rate_peak = 0.0, gimbal_angle_max = 0.0, wheel_speed_max = 0.0;

  auto sense = [&](double t, const State& xs, const Input& u_held) {
    const AttitudeState m = sensors.measure(AttitudeState{Base::sigma_BN(xs), cluster.omega_BN_B(xs, u_held)});
    sigma_given = m.sigma_BN;
    omega_given = m.omega_BN_B;
    typename VehicleLaw<NP>::Input in;
    in.t_s = t;
    in.state = m;
    in.Omega_rad_s = Base::Omega_w(xs);  // wheel tachometers: exact
    in.reference.sigma_RN = c.reference.target(t);
    return in;
  };
  auto to_actuation = [&](double t, const State& xs, const BodyTorque& cmd) {
    const Vec<M> gamma = Base::gamma(xs);  // gimbal encoders: exact
    BodyTorque request = cmd;
    request.torque_B_Nm += omega_given.cross(Vec3(believed.A_cs(gamma) * believed.h_cw));
    return typename Steering::Input{t, request, VscmgState<M, N>{gamma, wheel_speeds(xs)}};
  };
  auto to_plant = [&](double, const State& xs, const VscmgRates<M, N>& a, Input& u) {
    Vec<M + NP> v = Vec<M + NP>::Zero();  // zero rates when the steering wrote nothing
    v.template head<M>() = a.gamma_dot_rad_s;
    if constexpr (N > 0) v.template tail<N>() = a.Omega_dot_rad_s2;
    LimitReport lr;
    const Status ls = limit_vscmg_command<M, NP>(limits, I_ws, Base::Omega_w(xs), v, &lr);
    limited = ls == Status::saturated;
    speed_held += lr.wheel_speed_held;
    u = v;
  };
  auto observe = [&](const auto& s) {
    const State& xs = s.x;
    check_finite_state(s.t_s, all_finite(xs));
    const Vec3 sigma = Base::sigma_BN(xs);
    const double err = mrp_principal_angle(mrp_subtract(sigma, c.reference.target(s.t_s)));
    const double given_err = mrp_principal_angle(mrp_subtract(sigma_given, sigma));
    const Vec<M> gamma = Base::gamma(xs);
    const Vec3 torque = -params.truth.Q_act(gamma) * s.u;
    if (!s.final) {
      trace.control_step(s.controller_status, s.actuation_status, limited);
      if (s.actuation_status == Status::request_not_met) ++request_not_met;
      gimbal_rate_peak = std::max(gimbal_rate_peak, s.u.template head<M>().cwiseAbs().maxCoeff());
    }
    gimbal_angle_max = std::max(gimbal_angle_max, gamma.cwiseAbs().maxCoeff());
    if constexpr (N > 0) wheel_speed_max = std::max(wheel_speed_max, Base::Omega_w(xs).cwiseAbs().maxCoeff());
    trace.observe(s.t_s, sigma, cluster.omega_BN_B(xs, s.u), err, given_err, torque, s.command.torque_B_Nm,
                  disturbances.torque_B_Nm(s.t_s, sigma), sensors.star_tracker_valid(), csv ? &row : nullptr);
    if (csv) {
      for (int i = 0; i < M; ++i) row.push_back(s.u(i));  // gimbal rates
      for (int i = 0; i < M; ++i) row.push_back(gamma(i));
      for (int j = 0; j < N; ++j) row.push_back(s.u(M + j));  // wheel accelerations
      for (int j = 0; j < N; ++j) row.push_back(Base::Omega_w(xs)(j));
      row.push_back(s.actuation_diagnostics.torque_error);
      csv->record_row(row, s.final);
    }
  };
  SampledDataOptions opt;
  opt.t_end = c.run.duration_s;
  opt.sample_period = c.run.control_period_s;
  const long steps = closed_loop(plant, x, opt, c.run.integrator, sense, law, to_actuation, steering, to_plant, observe);
  if (csv) csv->close();

  std::vector<std::pair<std::string, double>> extra{{"gimbal_rate_peak_rad_s", gimbal_rate_peak},
                                                    {"gimbal_angle_max_rad", gimbal_angle_max},
                                                    {"steering_request_not_met", double(request_not_met)}};
  if constexpr (N > 0) {
    extra.push_back({"wheel_speed_max_rad_s", wheel_speed_max});
    extra.push_back({"wheel_speed_held", double(speed_held)});
  }
  extra.push_back({"funnel_recoveries", double(law.funnel_recoveries())});
  extra.push_back({"integrator_steps", double(steps)});
  RunResult r = trace.finish(extra, sensors.star_tracker_samples(), sensors.star_tracker_dropouts());
  std::vector<std::string> angles, rates;
  for (int i = 1; i <= M; ++i) {
    angles.push_back("gamma_" + std::to_string(i));
    rates.push_back("gamma_dot_" + std::to_string(i));
  }
  r.plots.push_back({c.name + "-gimbal-angles.png", "Gimbal angles", "t", angles, "gamma [rad]", false});
  r.plots.push_back({c.name + "-gimbal-rates.png", "Gimbal rates", "t", rates, "gamma_dot [rad/s]", false});
  if constexpr (N > 0) {
    std::vector<std::string> speeds;
    for (int j = 1; j <= N; ++j) speeds.push_back("Omega_" + std::to_string(j));
    r.plots.push_back({c.name + "-wheels.png", "Wheel speeds", "t", speeds, "Omega [rad/s]", false});
  }
  return r;
}

}  // namespace adcs::sim::vehicle
