// Host program run at build time: closes each paper loop around the replay System itself (its
// core, replay_<name>.cpp, the same object code the host replay runs) and writes the System's
// input of every step as a C++ header of hex-float literals (exact): replay_inputs_<name>.hpp in
// the build tree. Usage: record_inputs <hybrid|ppc|se3|dragfree> <out.hpp> <steps>
// Rows are packed in the layout each System documents at its kInputWidth (replay_<name>.hpp).
// (the float Systems and attitude too: record_inputs <hybrid_f|ppc_f|atc_f|eso_adrc_f|se3_f|
// se3_ftsmc_f|dragfree_f|attitude|attitude_f> <out.hpp> <steps>.)
//
// The loops follow src/scenarios/ with their default parameters and the RK4 / exact-ZOH truth the
// scenarios offer; the plant wrappers are the scenarios' own (src/scenarios/truth_plants.hpp),
// the drag-free truth is restated (drag_free.cpp keeps it with its noise streams):
//   hybrid, hybrid_f  A-REF: TP-FULL + D1 deviations + σ_d, one RK4 step per 1 ms period
//            (integrator=rk4); each System closes its own loop (hybrid_f: the float law)
//   ppc, ppc_f, atc_f, eso_adrc_f  flexible spacecraft (2 panels x 4 modes) + disturbance, RK4
//            at min(T, 1e-3 s); each System closes its own loop at its period (the float laws:
//            PPATC, the ATC baseline, the ESO-based ADRC at 0.05 s)
//   se3, se3_f, se3_ftsmc_f  chaser + target on SE(3), state 1, disturbance, RK4 at h/10
//            (integrator=rk4); the float Systems' rows carry the desired state (computed here)
//   dragfree, dragfree_f  the 27-state exact ZOH truth with seeded noise (run seed 0 -> streams
//            of seed 1); each System closes its own loop (dragfree_f: the float flight code)
//   attitude, attitude_f  the cubesat of examples/cubesat_mrp_pd.cpp (RigidBodyRw<4>), 10 RK4
//            steps per 0.1 s period, through its 30 deg slew; each System closes its own loop
//            (the float law's commands differ from the double one's)
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <string>
#include <vector>

#include "adcs/math/quaternion.hpp"
#include "adcs/plant/drag_free.hpp"
#include "adcs/plant/flexible_configurations.hpp"
#include "adcs/plant/flexible_spacecraft.hpp"
#include "adcs/plant/rigid_body_rw.hpp"
#include "adcs/plant/se3_spacecraft.hpp"
#include "adcs/plant/vscmg_configurations.hpp"
#include "adcs/reference/sinusoidal_euler.hpp"
#include "adcs/reference/sinusoidal_rate.hpp"
#include "replay_runtime.hpp"
#include "scenarios/truth_plants.hpp"
#include "sim/random.hpp"
#include "sim/rk4_integrator.hpp"
#include "sim/sampled_data.hpp"
#include "scenarios/seed003_data.hpp"  // seed 003's scenario data (paper data, not flight code)

namespace {

using namespace adcs;
using Rows = std::vector<std::vector<double>>;
using sim::FlexibleSimPlant;
using sim::HybridSimPlant;
using sim::Se3PairPlant;
using Row = std::vector<double>;

[[noreturn]] void fail(const std::string& what) {
  std::fprintf(stderr, "record_inputs: %s\n", what.c_str());
  std::exit(1);
}

void append(Row& row, const Eigen::Ref<const Eigen::VectorXd>& v) {
  for (Eigen::Index i = 0; i < v.size(); ++i) row.push_back(v(i));
}

//! The loop must stay in the usable statuses (ok or degraded-but-valid) for its inputs to be a
//! meaningful sequence: every status column ("st..." names) of the last sample is checked.
void check_statuses(const replay::Api& sys) {
  std::vector<double> v(static_cast<std::size_t>(sys.num_columns));
  sys.outputs(v.data());
  for (int c = 0; c < sys.num_columns; ++c)
    if (std::strncmp(sys.columns[c].name, "st", 2) == 0 && !usable(static_cast<Status>(static_cast<int>(v[c]))))
      fail(std::string(sys.name) + ": " + sys.columns[c].name + " = " +
           to_string(static_cast<Status>(static_cast<int>(v[c]))) + " while recording");
}

//! One sample through the System's parts, as the replay's step() runs it.
void step(const replay::Api& sys, const Row& row) {
  if (static_cast<int>(row.size()) != sys.input_width) fail(std::string(sys.name) + ": row layout mismatch");
  for (int part = 0; part < sys.parts; ++part) sys.step_part(part, row.data());
  check_statuses(sys);
}

// ------------------------------------------------------------------------------ seed 001

Rows record_hybrid(const replay::Api& sys, int steps) {
  using FullPlant = HybridSimPlant::FullPlant;
  const FullPlant plant(vscmg_params_A_REF());  // truth = nominal + D1 (spec A.5)
  if (plant.status() != Status::ok) fail("hybrid plant rejected");
  if (sys.init_status() != Status::ok) fail("hybrid controller rejected");
  const double T = sys.period_s;
  HybridSimPlant sim{&plant, SinusoidalRateReference{}};
  HybridSimPlant::State x;  // σ = σ_d = 0, ω = 0, γ = 0, Ω_w = 0 (spec §A.4 #24)
  x << plant.initial_state(Vec3::Zero(), Vec3::Zero(), Vec<4>::Zero(), Vec3::Zero()), Vec3::Zero();
  Rows rows;
  auto control = [&](double t, const HybridSimPlant::State& xs, HybridSimPlant::Input& u) {
    const FullPlant::State xp = xs.head<FullPlant::kStateSize>();
    const MrpReferenceSample r = sim.ref.sample(t, xs.tail<3>());
    Row row;  // σ_BN, ω_BN_B (with the γ̇ held over the last period), γ, Ω_w, σ_d, σ̇_d, σ̈_d
    append(row, FullPlant::sigma_BN(xp));
    append(row, plant.omega_BN_B(xp, u));
    append(row, FullPlant::gamma(xp));
    append(row, FullPlant::Omega_w(xp));
    append(row, r.sigma);
    append(row, r.sigma_dot);
    append(row, r.sigma_ddot);
    step(sys, row);
    sys.command(u.data());
    rows.push_back(row);
  };
  sim::SampledDataOptions opt;
  opt.t_end = steps * T;
  opt.sample_period = T;
  sim::Rk4Integrator<HybridSimPlant> integ(sim, T);
  sim::run_sampled_data(sim, integ, x, opt, control, [](double, const auto&, const auto&) {});
  return rows;
}

// ------------------------------------------------------------------------------ seed 002

Rows record_ppc(const replay::Api& sys, int steps) {
  using Plant = FlexibleSimPlant::Plant;
  constexpr double d2r = 3.14159265358979323846 / 180.0;
  const Plant plant(flexible_params_seed002());
  if (plant.status() != Status::ok) fail("flexible plant rejected");
  const FlexibleSimPlant sim{&plant, 0.0045, 0.0011};  // seed 002 §4: a = 0.0045 N m, n0 = 0.0011 rad/s
  const SinusoidalEulerReference ref;                   // seed 002 §4 defaults
  if (sys.init_status() != Status::ok) fail(std::string(sys.name) + " rejected");
  const double T = sys.period_s;
  Plant::State x = Plant::initial_state(Vec3(0.25, 0.15, -0.20) * d2r, Vec3(0.02, 0.01, -0.02) * d2r);
  Rows rows;
  auto control = [&](double t, const Plant::State& xs, Vec3& u) {
    const EulerReferenceSample r = ref.sample(t);
    Row row{t};  // t, ϑ, ω, ϑ_d, ϑ̇_d, ϑ̈_d (perfect measurements, Assumption 1)
    append(row, Plant::angles(xs));
    append(row, Plant::omega_BN_B(xs));
    append(row, r.angles);
    append(row, r.angles_dot);
    append(row, r.angles_ddot);
    step(sys, row);
    sys.command(u.data());
    rows.push_back(row);
  };
  sim::SampledDataOptions opt;
  opt.t_end = steps * T;
  opt.sample_period = T;
  sim::Rk4Integrator<FlexibleSimPlant> integ(sim, std::min(T, 1e-3));
  sim::run_sampled_data(sim, integ, x, opt, control, [](double, const auto&, const auto&) {});
  return rows;
}

// ------------------------------------------------------------------------------ seed 003

//! The se3-ptc loop's plant at state 1 with the spec A.8 defaults (the Systems' own), for a System
//! of period `period_s`.
struct Se3Loop {
  Se3ScenarioParams sp;
  Se3Spacecraft chaser, target;
  Se3PairPlant plant;
  Se3PairPlant::State x;
  static Se3ScenarioParams params(double period_s) {
    Se3ScenarioParams sp;
    sp.control_period = period_s;
    return sp;
  }
  static Se3SpacecraftParams truth(const Se3ScenarioParams& sp) {
    Se3SpacecraftParams truth_p;
    if (se3_chaser_truth_params(sp, truth_p) != Status::ok) fail("se3 truth parameters");
    return truth_p;
  }
  explicit Se3Loop(double period_s)
      : sp(params(period_s)), chaser(truth(sp)), target(se3_target_params(sp)), plant{&chaser, &target, &sp} {
    Se3SpacecraftState o0;
    if (se3_target_initial_state(sp, o0) != Status::ok) fail("se3 target initial state");
    const Se3SpacecraftState c0 = se3_chaser_initial_state(o0, kSe3InitialPoses[0]);  // state 1
    Se3PairPlant::put(x, 0, c0);
    Se3PairPlant::put(x, Se3PairPlant::kBody, o0);
  }
  Se3Loop(const Se3Loop&) = delete;  // plant points into this object
  //! Closes the loop for `steps` ticks at the period, RK4 at h/10 (spec C.1).
  template <class Control>
  void run(int steps, Control&& control) {
    sim::SampledDataOptions opt;
    opt.t_end = steps * sp.control_period;
    opt.sample_period = sp.control_period;
    sim::Rk4Integrator<Se3PairPlant> integ(plant, sp.control_period / 10.0);
    sim::run_sampled_data(plant, integ, x, opt, control, [](double, const auto&, const auto&) {});
  }
};

Rows record_se3(int steps) {
  const replay::Api& sys = replay::kSe3;
  if (sys.init_status() != Status::ok) fail("se3 controller rejected");
  Se3Loop loop(sys.period_s);
  Rows rows;
  auto control = [&](double, const Se3PairPlant::State& xs, Vec6& u) {
    Row row;  // chaser then target: C_NB (column-major), R_N, ω, v_B
    for (int off : {0, Se3PairPlant::kBody}) {
      const Se3SpacecraftState b = Se3PairPlant::body(xs, off);
      append(row, b.C_NB.reshaped());
      append(row, b.R_N);
      append(row, b.omega_BN_B);
      append(row, b.v_B);
    }
    step(sys, row);
    sys.command(u.data());
    rows.push_back(row);
  };
  loop.run(steps, control);
  return rows;
}

//! se3_f: the float law's own loop (state 1, RK4 at h/10). The row carries the desired state,
//! computed here in double from the target's model as the float scenario's ground code does, and
//! the law's raw command goes through sat -> Q here (the actuator, double), as in se3-ptc.
Rows record_se3_f(const replay::Api& sys, int steps) {
  if (sys.init_status() != Status::ok) fail(std::string(sys.name) + " controller rejected");
  Se3Loop loop(sys.period_s);
  CompositeQuantizer<6> quantizer(seed003_quantizer_params());
  const Vec6 limit = se3_actuator_limits(loop.sp);
  if (quantizer.status() != Status::ok) fail("se3 quantizer");
  Rows rows;
  auto control = [&](double, const Se3PairPlant::State& xs, Vec6& u) {
    const Se3SpacecraftState c = Se3PairPlant::body(xs, 0), o = Se3PairPlant::body(xs, Se3PairPlant::kBody);
    Se3DesiredState d;
    if (se3_desired_state(loop.target, o, loop.sp, d) != Status::ok) fail("se3_f desired state");
    Row row;  // chaser C_NB (column-major), R_N, ω, v_B; desired C_ND, R_N, ω_d, v_d, ω̇_d, v̇_d
    append(row, c.C_NB.reshaped());
    append(row, c.R_N);
    append(row, c.omega_BN_B);
    append(row, c.v_B);
    append(row, d.C_ND.reshaped());
    append(row, d.R_N);
    append(row, d.omega_DN_D);
    append(row, d.v_D);
    append(row, d.omega_dot_D);
    append(row, d.v_dot_D);
    step(sys, row);
    Vec6 u_law;
    sys.command(u_law.data());
    Vec6 u_c;
    const Status sq = saturate_then_quantize<6>(u_law, limit, quantizer, u_c);
    if (sq != Status::ok && sq != Status::saturated) fail("se3_f sat/Q");
    u = u_c;
    rows.push_back(row);
  };
  loop.run(steps, control);
  return rows;
}

// ------------------------------------------------------------------------------ seed 004
Rows record_dragfree(const replay::Api& sys, int steps) {
  if (sys.init_status() != Status::ok || sys.parts != 2) fail("drag-free filters/controller rejected");
  DragFreeParams d;  // Table 2 defaults, as the System's
  d.period_s = sys.period_s;
  DragFreeDiscrete model;
  if (drag_free_discretize(d, model) != Status::ok) fail("drag-free discretisation");
  const DragFreeNoise noise = drag_free_noise(d);
  // Noise streams as NoiseStreams(seed + 1) of src/scenarios/drag_free.cpp, run seed 0.
  const std::uint64_t seed = 1;
  std::vector<sim::Rng> rw, rd, ra;
  for (int i = 0; i < 9; ++i) rw.emplace_back(seed * 1000003u + 11u + i);
  for (int i = 0; i < 9; ++i) rd.emplace_back(seed * 1000003u + 101u + i);
  for (int i = 0; i < 3; ++i) ra.emplace_back(seed * 1000003u + 211u + i);
  constexpr double kPi = 3.14159265358979323846;
  // f(t) as DragFreeConfig::f/set_disturbance: T_Dsc = F_Dsc = bias + amp sin(ω_d t + 2πi/3)
  // (Table 2: -12.8 mN, 7.7 mN, 1.2e-3 rad/s), T_Dtm = 0.
  auto put_f = [](Vec<27>& X, double t) {
    for (int i = 0; i < 3; ++i) {
      const double s = -12.8e-3 + 7.7e-3 * std::sin(1.2e-3 * t + 2.0 * kPi * i / 3.0);
      X(DragFreeIndex::T_Dsc + i) = s;
      X(DragFreeIndex::F_Dsc + i) = s;
      X(DragFreeIndex::T_Dtm + i) = 0.0;
    }
  };
  Vec<27> X = Vec<27>::Zero();
  put_f(X, 0.0);
  Rows rows;
  for (int k = 0; k < steps; ++k) {
    const double t = k * d.period_s;
    Row row(static_cast<std::size_t>(sys.input_width), 0.0);  // Y, y_c, φ_cmd = 0 (before t_on = 1e4 s)
    const Vec<9> Y = model.C_d * X;
    for (int i = 0; i < 9; ++i) row[i] = Y(i) + noise.sigma_pos * rd[i].normal();
    sys.step_part(0, row.data());  // predictions, Algorithm 1 update, ADRC
    Vec<9> u;
    sys.command(u.data());
    Vec<9> w;
    for (int i = 0; i < 3; ++i) w(i) = noise.sigma_T_sc * rw[i].normal();
    for (int i = 3; i < 6; ++i) w(i) = noise.sigma_F_sc * rw[i].normal();
    for (int i = 6; i < 9; ++i) w(i) = noise.sigma_T_tm * rw[i].normal();
    for (int j = 0; j < 3; ++j) {
      const Vec3 F_applied = u.segment<3>(3) + w.segment<3>(3);
      const double y = drag_free_accelerometer(d, X, F_applied, j) + noise.sigma_acc * ra[j].normal();
      row[9 + j] = saturate_accelerometer(d, y);
    }
    sys.step_part(1, row.data());  // Algorithm 2 updates with y_c, fusion
    check_statuses(sys);
    X = (model.A_d * X + model.B_d * (u + w)).eval();
    put_f(X, t + d.period_s);
    if (!all_finite(X)) fail("drag-free truth diverged");
    rows.push_back(row);
  }
  return rows;
}

// ------------------------------------------------------------------------------ issue 19

Rows record_attitude(const replay::Api& sys, int steps) {
  using Plant = RigidBodyRw<4>;
  constexpr double kDeg = kPiRad / 180.0;
  if (sys.init_status() != Status::ok) fail("attitude law or allocation rejected");
  Plant::Params vehicle;
  vehicle.J_B = Vec3(0.20, 0.25, 0.15).asDiagonal();
  if (wheel_pyramid_axes<4>(30.0 * kDeg, vehicle.G_s_B) != Status::ok) fail("wheel pyramid");
  vehicle.J_s = Vec<4>::Constant(2e-5);
  const Plant plant(vehicle);
  if (plant.status() != Status::ok) fail("cubesat plant rejected");
  const Vec3 sigma_RN = std::tan(30.0 * kDeg / 4.0) * Vec3(1.0, 2.0, 3.0).normalized();
  const double T = sys.period_s;
  sim::Rk4Integrator<Plant> integ(plant, T / 10.0);
  Plant::State x = Plant::State::Zero();
  Plant::Input u = Plant::Input::Zero();  // [wheel motor torques; external torque = 0]
  Rows rows;
  for (int k = 0; k < steps; ++k) {
    Row row;
    append(row, Plant::sigma_BN(x));
    append(row, Plant::omega_BN_B(x));
    append(row, Plant::Omega(x));
    append(row, sigma_RN);
    step(sys, row);
    sys.command(u.data());
    rows.push_back(row);
    // Ten classical RK4 substeps of T/10 with the wheel torques held. The plant is time-invariant,
    // so each period restarts at t = 0 (h = T/10 exactly); the MRP switch (|σ| > 1, never reached
    // by this 30° slew) is checked once per period.
    integ.reset(0.0, x);
    integ.advance(T, u, x);
    (void)plant.normalize(x);
  }
  return rows;
}

void write_header(const char* path, const char* name, const char* what, const Rows& rows) {
  std::FILE* f = std::fopen(path, "w");
  if (!f) fail(std::string("cannot write ") + path);
  std::fprintf(f,
               "// Generated by record_inputs (tests/target/record_inputs.cpp) at build time; do not edit.\n"
               "// %s: %s, %zu steps of the System's input rows, hex floats (exact).\n"
               "#pragma once\nnamespace replay_data {\n"
               "inline constexpr int kSteps = %zu;\ninline constexpr int kWidth = %zu;\n"
               "alignas(8) static const double kRows[%zu][%zu] = {\n",
               name, what, rows.size(), rows.size(), rows.front().size(), rows.size(), rows.front().size());
  char buf[40];
  for (const std::vector<double>& r : rows) {
    std::fputs("    {", f);
    for (std::size_t i = 0; i < r.size(); ++i) {
      if (!std::isfinite(r[i])) fail("non-finite input recorded");
      *replay::put_hexfloat(buf, r[i]) = '\0';
      std::fprintf(f, "%s%s", i ? ", " : "", buf);
    }
    std::fputs("},\n", f);
  }
  std::fputs("};\n}  // namespace replay_data\n", f);
  if (std::fclose(f) != 0) fail(std::string("cannot write ") + path);
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 4) fail("usage: record_inputs <hybrid|hybrid_f|ppc|ppc_f|atc_f|eso_adrc_f|se3|se3_f|se3_ftsmc_f|dragfree|dragfree_f|attitude|attitude_f> <out.hpp> <steps>");
  const std::string name = argv[1];
  const int steps = std::atoi(argv[3]);
  if (steps < 1) fail("steps must be >= 1");
  Rows rows;
  const char* what = "";
  try {
    if (name == "hybrid") {
      rows = record_hybrid(replay::kHybrid, steps);
      what = "seed 001 A-REF closed loop, T_c = 1 ms";
    } else if (name == "hybrid_f") {
      rows = record_hybrid(replay::kHybridF, steps);
      what = "seed 001 A-REF closed loop (float law), T_c = 1 ms";
    } else if (name == "ppc") {
      rows = record_ppc(replay::kPpc, steps);
      what = "seed 002 flexible-ppc closed loop, T = 1e-4 s";
    } else if (name == "ppc_f") {
      rows = record_ppc(replay::kPpcF, steps);
      what = "seed 002 flexible-ppc closed loop (float law), T = 1e-4 s";
    } else if (name == "se3") {
      rows = record_se3(steps);
      what = "seed 003 se3-ptc closed loop (state 1), 8 Hz";
    } else if (name == "se3_f") {
      rows = record_se3_f(replay::kSe3F, steps);
      what = "seed 003 se3-ptc closed loop (state 1, float law), 8 Hz";
    } else if (name == "se3_ftsmc_f") {
      rows = record_se3_f(replay::kSe3FtsmcF, steps);
      what = "seed 003 se3-ftsmc closed loop (state 1, float FTSMC), 8 Hz";
    } else if (name == "atc_f") {
      rows = record_ppc(replay::kAtcF, steps);
      what = "seed 002 flexible-atc closed loop (float ATC), T = 1e-4 s";
    } else if (name == "eso_adrc_f") {
      rows = record_ppc(replay::kEsoAdrcF, steps);
      what = "seed 002's vehicle under the ESO-based ADRC (float), h = 0.05 s";
    } else if (name == "dragfree") {
      rows = record_dragfree(replay::kDragFree, steps);
      what = "seed 004 dragfree-adrc closed loop, h = 0.1 s";
    } else if (name == "dragfree_f") {
      rows = record_dragfree(replay::kDragFreeF, steps);
      what = "seed 004 dragfree-adrc closed loop (float flight code), h = 0.1 s";
    } else if (name == "attitude") {
      rows = record_attitude(replay::kAttitude, steps);
      what = "cubesat MRP PD + wheel allocation closed loop (double), 10 Hz";
    } else if (name == "attitude_f") {
      rows = record_attitude(replay::kAttitudeF, steps);
      what = "cubesat MRP PD + wheel allocation closed loop (float law), 10 Hz";
    } else {
      fail("unknown system " + name);
    }
  } catch (const std::exception& e) {
    fail(e.what());
  }
  if (static_cast<int>(rows.size()) != steps) fail("recorded " + std::to_string(rows.size()) + " steps");
  write_header(argv[2], name.c_str(), what, rows);
  return 0;
}
