// rigid-rw-mrp-pd and cubesat-mrp-pd: inertial-pointing slew of a rigid spacecraft with 4 reaction wheels
// (3 orthogonal + 1 skewed) under the MRP PD law (control/mrp_pd.hpp) at 10 Hz, minimum-norm
// pseudo-inverse torque allocation with a per-wheel limit (actuator/rw_allocation.hpp). Our
// baseline against Basilisk's mrpFeedback (K_i = 0) + rwMotorTorque. No external torque, so
// the wheels only exchange momentum with the body: H_N is conserved (checked).
#include <algorithm>
#include <cmath>
#include <memory>
#include <utility>

#include "adcs/actuator/rw_allocation.hpp"
#include "adcs/control/mrp_pd.hpp"
#include "scenarios/rigid_rw_common.hpp"
#include "sim/metrics.hpp"
#include "sim/closed_loop.hpp"

namespace adcs::sim {
namespace ADCS_UNITY_ID {

// rigid-rw-mrp-pd: every parameter below is ours (the foundation issue fixes only J, the 10 Hz
// rate and the 0.2 N m limit): chosen so the saturated slew converges without large overshoot.
constexpr const char* kSource = "assumed: foundation baseline, not from a paper";
constexpr const char* kIssue = "issue 2 (foundation): inertia diag(900,800,600), 10 Hz, 0.2 N m";
// cubesat-mrp-pd: the 12U cubesat of issue 15, gains chosen as a user would (see declare()).
constexpr const char* kCubesatOurs = "ours: chosen for the 12U cubesat (issue 15), see the scenario file";

//! Which vehicle the MRP PD scenario flies.
struct MrpPdVehicle {
  std::string name, description;
  RigidRwDefaults defaults;
  std::vector<double> sigma_RN;
  double K_Nm;
  std::vector<double> P_Nms;
  double torque_limit_Nm, settle_band_rad;
  std::string gain_source, limit_source;
};

MrpPdVehicle foundation_vehicle() {
  MrpPdVehicle v;  // at rest, wheels stopped, at sigma_BN = 0 (the target is sigma_RN)
  v.name = "rigid-rw-mrp-pd";
  v.description = "MRP PD slew to an inertial target, 4 reaction wheels (3 orthogonal + 1 skewed), "
                  "min-norm allocation with 0.2 N m limit, 10 Hz";
  RigidRwDefaults& d = v.defaults;
  d.sigma0_BN = {0.0, 0.0, 0.0};
  d.omega0_BN_B = {0.0, 0.0, 0.0};
  d.Omega0_rad_s = {0.0, 0.0, 0.0, 0.0};
  d.J_kgm2 = {{900.0, 0.0, 0.0}, {0.0, 800.0, 0.0}, {0.0, 0.0, 600.0}};
  d.wheel_Js_kgm2 = {0.05, 0.05, 0.05, 0.05};
  d.duration_s = 1200.0;
  d.control_period_s = 0.1;
  d.source = kSource;
  v.sigma_RN = {0.1, 0.2, -0.3};  // 82.6 deg slew
  // Critically damped linearised axes (sigma ~ phi/4): K = 4 J_i w_n^2, P_i = 2 J_i w_n,
  // w_n = 0.02 rad/s on x; the low K/P ratio keeps the saturated cruise rate small enough to
  // stop within the 0.2 N m budget.
  v.K_Nm = 1.44;
  v.P_Nms = {36.0, 32.0, 28.0};
  v.torque_limit_Nm = 0.2;
  v.settle_band_rad = 1e-3;
  v.gain_source = kSource;
  v.limit_source = kIssue;
  return v;
}

//! The 12U cubesat of issue 15 (cubesat_12u_manoeuvre()) under MRP PD.
MrpPdVehicle cubesat_vehicle() {
  const CubesatManoeuvre c = cubesat_12u_manoeuvre();
  MrpPdVehicle v;
  v.name = "cubesat-mrp-pd";
  v.description = "12U cubesat (issue 15): 30 deg rest-to-rest slew about (1,2,3)/sqrt(14) and a 300 s hold, "
                  "MRP PD at 10 Hz, 4 wheels in a 30 deg pyramid, 3 mN m each";
  v.defaults = c.defaults;
  v.sigma_RN = c.sigma_RN;
  // Gains as a user would choose them: critically damped axes (sigma ~ phi/4, so
  // K = 4 J_i w_n^2, P_i = 2 J_i w_n) with w_n = 0.1 rad/s on the largest inertia; the 30 deg
  // step then asks K sigma ~ 0.7 mN m, within one wheel's 3 mN m, so the slew is unsaturated.
  v.K_Nm = 4.0 * 0.25 * 0.1 * 0.1;
  v.P_Nms = {2.0 * 0.20 * 0.1, 2.0 * 0.25 * 0.1, 2.0 * 0.15 * 0.1};
  v.torque_limit_Nm = c.torque_limit_Nm;
  v.settle_band_rad = 1e-3;
  v.gain_source = kCubesatOurs;
  v.limit_source = c.source;
  return v;
}

class RigidRwMrpPd final : public Scenario {
 public:
  explicit RigidRwMrpPd(MrpPdVehicle v) : v_(std::move(v)) {}
  std::string name() const override { return v_.name; }
  std::string description() const override { return v_.description; }

  void declare(ParamSet& p) const override {
    declare_rigid_rw(p, v_.defaults);
    p.vector("sigma_RN", v_.sigma_RN, "-", "inertial target MRP; " + v_.gain_source);
    p.number("K_Nm", v_.K_Nm, "N m", v_.gain_source);
    p.vector("P_Nms", v_.P_Nms, "N m s", "diagonal rate gain; " + v_.gain_source);
    declare_wheel_limits(p, v_.torque_limit_Nm, v_.limit_source);
    p.number("settle_band_rad", v_.settle_band_rad, "rad", "principal-angle band for settle_s; " + v_.gain_source);
    declare_scalar(p);
  }

  RunResult run(const ParamSet& p, const RunContext& ctx) const override {
    return p.get_name("scalar") == "float" ? run_as<float>(p, ctx) : run_as<double>(p, ctx);
  }

 private:
  //! The loop with the law and the allocation in scalar S (the plant stays double under CVODE):
  //! their parameters, inputs and outputs cross the boundary through cast<S>() and back.
  template <class S>
  RunResult run_as(const ParamSet& p, const RunContext& ctx) const {
    const RigidRwPlant::Params pp = rigid_rw_plant_params(p);
    const RigidRwPlant plant(pp);

    MrpPdParams<kRigidRwWheels> cp;
    cp.K = p.get_number("K_Nm");
    cp.P = p.get_vec<3>("P_Nms").asDiagonal();
    cp.J_rw_B = plant.J_rw();
    cp.G_s_B = pp.G_s_B;
    cp.J_s = pp.J_s;
    cp.period_s = p.get_number("control_period_s");
    MrpPd<kRigidRwWheels, S> controller(cp.template cast<S>());
    if (controller.status() != Status::ok)
      throw ParamError("MRP PD parameters rejected (K_Nm > 0, P_Nms > 0, SPD inertia, unit wheel axes)");
    RwAllocationParams<kRigidRwWheels> ap;
    ap.G_s_B = pp.G_s_B;
    ap.torque_limit = p.get_number("torque_limit_Nm");
    RwTorqueAllocator<kRigidRwWheels, S> allocator(ap.template cast<S>());
    if (allocator.status() != Status::ok) throw ParamError("torque_limit_Nm must be > 0");
    const ActuatorLimits<0, kRigidRwWheels> limits = wheel_limits(p);
    AttitudeReference ref;
    ref.sigma_RN = p.get_vec<3>("sigma_RN");

    std::vector<UsedValue> used;
    RigidRwPlant::State x = rigid_rw_initial_state(p, ctx.seed, &used);
    const Vec3 H0 = plant.momentum_N(x);

    std::unique_ptr<CsvRecorder> csv;
    if (!ctx.csv_path.empty()) {
      csv = std::make_unique<CsvRecorder>(
          ctx.csv_path,
          rigid_rw_columns({{"att_err_rad", "rad"},
                            {"L_r_B_1", "N m"}, {"L_r_B_2", "N m"}, {"L_r_B_3", "N m"},
                            {"u_s_1", "N m"}, {"u_s_2", "N m"}, {"u_s_3", "N m"}, {"u_s_4", "N m"}}),
          static_cast<int>(p.get_number("record_every")));
    }

    std::vector<double> t_series, err_series, row;
    double torque_max = 0.0, wheel_max = 0.0, dH_max = 0.0;
    long saturated = 0, rejected = 0, samples = 0, speed_held = 0;
    SampledDataOptions opt;
    opt.t_end = p.get_number("duration_s");
    opt.sample_period = p.get_number("control_period_s");
    const double t_end = opt.t_end;

    // The loop (sim/closed_loop.hpp): perfect sensors (assumed) → MRP PD → min-norm allocation
    // with the torque limit → each wheel's speed limit → the plant's wheel motors.
    auto sensors = [&](double, const RigidRwPlant::State& xs) {
      MrpPdInput<kRigidRwWheels> m;
      m.state = AttitudeState{RigidRwPlant::sigma_BN(xs), RigidRwPlant::omega_BN_B(xs)};
      m.Omega_rad_s = RigidRwPlant::Omega(xs);
      m.reference = ref;
      return m.template cast<S>();  // beyond float range: ±Inf (core/types.hpp narrow_scalar)
    };
    auto to_actuation = [](double, const RigidRwPlant::State&, const BodyTorqueT<S>& cmd) { return cmd; };
    auto to_plant = [&](double, const RigidRwPlant::State& xs, const WheelTorques<kRigidRwWheels, S>& w,
                        RigidRwPlant::Input& u) {
      set_wheel_input(limits, xs, w.template cast<double>(), u, speed_held);
      u.tail<3>().setZero();
    };
    auto observe = [&](const auto& s) {
      const double t = s.t_s;
      const RigidRwPlant::State& xs = s.x;
      const RigidRwPlant::Input& u = s.u;
      if (!s.final) {  // once per control step
        ++samples;
        if (s.controller_status != Status::ok) ++rejected;
        if (s.actuation_status == Status::saturated) ++saturated;
        else if (s.actuation_status != Status::ok) ++rejected;
      }
      const double err = mrp_principal_angle(mrp_subtract(RigidRwPlant::sigma_BN(xs), ref.sigma_RN));
      t_series.push_back(t);
      err_series.push_back(err);
      torque_max = std::max(torque_max, u.head<kRigidRwWheels>().cwiseAbs().maxCoeff());
      wheel_max = std::max(wheel_max, RigidRwPlant::Omega(xs).cwiseAbs().maxCoeff());
      dH_max = std::max(dH_max, (plant.momentum_N(xs) - H0).norm());
      if (csv) {
        rigid_rw_row(t, xs, row);
        row.push_back(err);
        for (int i = 0; i < 3; ++i) row.push_back(static_cast<double>(s.command.torque_B_Nm(i)));
        for (int i = 0; i < kRigidRwWheels; ++i) row.push_back(u(i));
        csv->record_row(row, s.final);
      }
    };
    closed_loop(plant, x, opt, integrator_choice(p), sensors, controller, to_actuation, allocator, to_plant, observe);
    if (csv) csv->close();

    const double att_err_final = err_series.empty() ? NAN : err_series.back();
    const double att_err_max = err_series.empty() ? NAN : *std::max_element(err_series.begin(), err_series.end());
    constexpr double kRad2Deg = 180.0 / kPiRad;
    const double settle = metrics::settling_time(t_series, err_series, p.get_number("settle_band_rad"));
    const double limit = p.get_number("torque_limit_Nm");
    const double H_scale = std::max(H0.norm(), pp.J_B.norm() * 1e-3);  // H0 may be 0 (rest)
    RunResult r;
    r.used = std::move(used);
    r.metrics = {{"att_err_final_rad", att_err_final},
                 {"settle_s", settle},
                 {"torque_max_Nm", torque_max},
                 {"wheel_speed_max_rad_s", wheel_max},
                 {"saturated_fraction", samples ? double(saturated) / double(samples) : 0.0},
                 {"wheel_speed_held", double(speed_held)},
                 {"rejected_steps", double(rejected)},
                 {"momentum_drift_Nms", dH_max},
                 {"momentum_drift_rel", dH_max / H_scale},
                 {"att_err_max_deg", kRad2Deg * att_err_max},
                 {"att_err_final_deg", kRad2Deg * att_err_final}};
    char buf[96];
    std::snprintf(buf, sizeof buf, "%.3g rad after %.0f s", att_err_final, t_end);
    r.claims.push_back({"check", "MRP PD slew converges to the inertial target", "< 1e-3 rad", buf,
                        att_err_final < 1e-3});
    std::snprintf(buf, sizeof buf, "%.4g N m", torque_max);
    r.claims.push_back({"check", "wheel motor torques stay within the limit",
                        "<= " + std::to_string(limit).substr(0, 4) + " N m", buf,
                        torque_max <= limit * (1.0 + 1e-12)});
    std::snprintf(buf, sizeof buf, "%.3g N m s", dH_max);
    r.claims.push_back({"check", "internal wheel torques conserve inertial momentum H_N",
                        "<= 1e-6 N m s", buf, dH_max <= 1e-6});
    r.plots = {
        {name() + "-error.png", "Principal-angle attitude error", "t", {"att_err_rad"},
         "attitude error [rad]", true},
        {name() + "-sigma.png", "Attitude sigma_BN", "t", {"sigma_BN_1", "sigma_BN_2", "sigma_BN_3"},
         "sigma_BN [-]", false},
        {name() + "-omega.png", "Body rate omega_BN_B", "t",
         {"omega_BN_B_1", "omega_BN_B_2", "omega_BN_B_3"}, "omega_BN_B [rad/s]", false},
        {name() + "-torque.png", "Wheel motor torques (limit " + format_number(limit) + " N m)", "t",
         {"u_s_1", "u_s_2", "u_s_3", "u_s_4"}, "u_s [N m]", false},
        {name() + "-wheels.png", "Wheel speeds", "t", {"Omega_1", "Omega_2", "Omega_3", "Omega_4"},
         "Omega [rad/s]", false},
    };
    return r;
  }

  MrpPdVehicle v_;
};

}  // namespace
using namespace ADCS_UNITY_ID;  // as an anonymous namespace would (CMakeLists.txt, adcs_unity)

std::unique_ptr<Scenario> make_rigid_rw_mrp_pd() { return std::make_unique<RigidRwMrpPd>(foundation_vehicle()); }
std::unique_ptr<Scenario> make_cubesat_mrp_pd() { return std::make_unique<RigidRwMrpPd>(cubesat_vehicle()); }

}  // namespace adcs::sim
