// rigid-rw-torquefree: a tumbling rigid spacecraft with 4 spinning reaction wheels and no torque
// at all (motor or external). Inertial angular momentum H_N and kinetic energy must stay
// constant: the harness check users compare with other tools (CSV columns t, sigma_BN_1..3,
// omega_BN_B_1..3, Omega_1..4).
#include <algorithm>
#include <cmath>
#include <memory>
#include <utility>

#include "scenarios/rigid_rw_common.hpp"
#include "sim/sampled_data.hpp"

namespace adcs::sim {
namespace ADCS_UNITY_ID {

constexpr const char* kSource = "assumed: harness check, not from a paper";

class RigidRwTorqueFree final : public Scenario {
 public:
  std::string name() const override { return "rigid-rw-torquefree"; }
  std::string description() const override {
    return "Torque-free rigid body + 4 reaction wheels: inertial momentum and kinetic energy "
           "conservation (harness check)";
  }

  void declare(ParamSet& p) const override {
    RigidRwDefaults d;
    // Asymmetric, with products of inertia, so every coupling term of the model is exercised.
    d.J_kgm2 = {{100.0, 2.0, -1.5}, {2.0, 80.0, 3.0}, {-1.5, 3.0, 60.0}};
    d.wheel_Js_kgm2 = {0.05, 0.05, 0.05, 0.05};
    d.sigma0_BN = {0.1, 0.2, -0.3};
    d.omega0_BN_B = {0.05, -0.03, 0.02};
    d.Omega0_rad_s = {100.0, -50.0, 75.0, 20.0};
    d.duration_s = 1000.0;
    // Nothing is commanded: the "control period" is the sampling/recording interval.
    d.control_period_s = 1.0;
    d.source = kSource;
    declare_rigid_rw(p, d);
  }

  RunResult run(const ParamSet& p, const RunContext& ctx) const override {
    const RigidRwPlant plant(rigid_rw_plant_params(p));
    std::vector<UsedValue> used;
    RigidRwPlant::State x = rigid_rw_initial_state(p, ctx.seed, &used);
    const Vec3 H0 = plant.momentum_N(x);
    const double T0 = plant.kinetic_energy(x);

    std::unique_ptr<CsvRecorder> csv;
    if (!ctx.csv_path.empty())
      csv = std::make_unique<CsvRecorder>(ctx.csv_path, rigid_rw_columns(),
                                          static_cast<int>(p.get_number("record_every")));
    double dH_max = 0.0, dT_max = 0.0;
    std::vector<double> row;
    SampledDataOptions opt;
    opt.t_end = p.get_number("duration_s");
    opt.sample_period = p.get_number("control_period_s");
    const double t_end = opt.t_end;
    with_integrator(plant, integrator_choice(p), [&](auto& integrator) {  // open loop: no controller
      run_sampled_data(
          plant, integrator, x, opt,
          [](double, const RigidRwPlant::State&, RigidRwPlant::Input& u) { u.setZero(); },
          [&](double t, const RigidRwPlant::State& xs, const RigidRwPlant::Input&) {
            dH_max = std::max(dH_max, (plant.momentum_N(xs) - H0).norm());
            dT_max = std::max(dT_max, std::abs(plant.kinetic_energy(xs) - T0));
            if (csv) {
              rigid_rw_row(t, xs, row);
              csv->record_row(row, t == t_end);
            }
          });
    });
    if (csv) csv->close();

    RunResult r;
    r.used = std::move(used);
    const double momentum_drift_rel = dH_max / H0.norm();
    const double energy_drift_rel = dT_max / T0;
    r.metrics = {{"momentum_drift_rel", momentum_drift_rel}, {"energy_drift_rel", energy_drift_rel}};
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.3g", momentum_drift_rel);
    r.claims.push_back({"check", "torque-free: inertial momentum |H_N(t)-H_N(0)|/|H_N(0)|",
                        "<= 1e-9 (harness requirement)", buf, momentum_drift_rel <= 1e-9});
    std::snprintf(buf, sizeof buf, "%.3g", energy_drift_rel);
    r.claims.push_back({"check", "torque-free: kinetic energy |T(t)-T(0)|/T(0)",
                        "<= 1e-9 (harness requirement)", buf, energy_drift_rel <= 1e-9});
    r.plots = {
        {name() + "-sigma.png", "Attitude sigma_BN (torque-free tumble)", "t",
         {"sigma_BN_1", "sigma_BN_2", "sigma_BN_3"}, "sigma_BN [-]", false},
        {name() + "-omega.png", "Body rate omega_BN_B", "t",
         {"omega_BN_B_1", "omega_BN_B_2", "omega_BN_B_3"}, "omega_BN_B [rad/s]", false},
        {name() + "-wheels.png", "Wheel speeds relative to the body", "t",
         {"Omega_1", "Omega_2", "Omega_3", "Omega_4"}, "Omega [rad/s]", false},
    };
    return r;
  }
};

}  // namespace
using namespace ADCS_UNITY_ID;  // as an anonymous namespace would (CMakeLists.txt, adcs_unity)

std::unique_ptr<Scenario> make_rigid_rw_torquefree() { return std::make_unique<RigidRwTorqueFree>(); }

}  // namespace adcs::sim
