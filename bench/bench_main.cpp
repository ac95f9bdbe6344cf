// adcs-bench. Run e.g.
//   build/bench/adcs-bench --benchmark_repetitions=10 --benchmark_report_aggregates_only=true
// and read the *_median rows. Inputs vary between iterations so nothing is constant-folded.
#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdlib>

#include "adcs/adcs.hpp"
#ifdef ADCS_BENCH_HAVE_SIM
#include "scenarios/registry.hpp"
#endif

namespace {

adcs::Mat<3, 4> four_wheel_axes() {
  adcs::Mat<3, 4> G;
  const double s = 1.0 / std::sqrt(3.0);
  G << 1, 0, 0, s, 0, 1, 0, s, 0, 0, 1, s;
  return G;
}

// One MrpPd::step() (the controller of rigid-rw-mrp-pd).
void BM_MrpPd_Step(benchmark::State& state) {
  adcs::MrpPdParams<4> p;
  p.K = 1.44;
  p.P = adcs::Vec3(36, 32, 28).asDiagonal();
  p.J_rw_B = adcs::Vec3(900, 800, 600).asDiagonal();
  p.G_s_B = four_wheel_axes();
  p.J_s.setConstant(0.05);
  adcs::MrpPd<4> ctrl(p);
  adcs::MrpPd<4>::Measurement m;
  m.sigma_BN << 0.1, -0.2, 0.3;
  m.omega_BN_B << 0.01, 0.002, -0.003;
  m.Omega << 10, 20, 30, 40;
  adcs::AttitudeReference r;
  r.sigma_RN << 0.1, 0.2, -0.3;
  adcs::MrpPdCommand out;
  double k = 0.0;
  for (auto _ : state) {
    m.sigma_BN(0) = 0.1 + 1e-9 * k;
    k += 1.0;
    benchmark::DoNotOptimize(ctrl.step(m, r, out));
    benchmark::DoNotOptimize(out.L_r_B.data());
  }
}
BENCHMARK(BM_MrpPd_Step);

// One RwTorqueAllocator::allocate() (precomputed pseudo-inverse + scaling).
void BM_RwAllocation_Step(benchmark::State& state) {
  adcs::RwAllocationParams<4> p;
  p.G_s_B = four_wheel_axes();
  const adcs::RwTorqueAllocator<4> alloc(p);
  adcs::Vec3 L(0.05, -0.3, 0.1);
  adcs::Vec<4> us;
  for (auto _ : state) {
    L(0) += 1e-12;
    benchmark::DoNotOptimize(alloc.allocate(L, us));
    benchmark::DoNotOptimize(us.data());
  }
}
BENCHMARK(BM_RwAllocation_Step);

// One HybridAdaptive::step() (seed 001, M = 4 CMGs, N = 3 wheels): regressors, steering via
// LDLT of X X^T, adaptation with projection. Inputs move each iteration.
void hybrid_adaptive_step(benchmark::State& state, adcs::AdaptationStep adaptation) {
  adcs::HybridAdaptive<4, 3>::Params p;
  p.nominal = adcs::pyramid_4cmg_3rw_nominal();
  p.adaptation_step = adaptation;
  adcs::HybridAdaptive<4, 3> ctrl(p);
  adcs::HybridAdaptive<4, 3>::Measurement m;
  m.sigma_BN << 0.3, -0.2, 0.1;
  m.omega_BN_B << 0.01, -0.02, 0.015;
  m.gamma << 0.1, -0.2, 0.15, 0.05;
  const adcs::SinusoidalRateReference ref;
  adcs::MrpReferenceSample r = ref.sample(123.0, adcs::Vec3(0.29, -0.21, 0.1));
  adcs::HybridAdaptive<4, 3>::Command out;
  double k = 0.0;
  for (auto _ : state) {
    m.gamma(0) = 0.1 + 1e-9 * k;
    k += 1.0;
    benchmark::DoNotOptimize(ctrl.step(m, r, out));
    benchmark::DoNotOptimize(out.u.data());
    if (static_cast<long>(k) % 4096 == 0) ctrl.reset();  // keep the estimates near nominal
  }
}
void BM_HybridAdaptive_Step(benchmark::State& state) {
  hybrid_adaptive_step(state, adcs::AdaptationStep::explicit_euler);  // the paper's update
}
BENCHMARK(BM_HybridAdaptive_Step);
void BM_HybridAdaptiveNormalized_Step(benchmark::State& state) {
  hybrid_adaptive_step(state, adcs::AdaptationStep::normalized);  // ours, for 5-20 Hz
}
BENCHMARK(BM_HybridAdaptiveNormalized_Step);

// One step of a seed 002 Euler-angle law (PPATC or ATC) on the scenario's initial state, time
// and angles moving each iteration: kinematics, (funnel transform,) RBF layer, adaptation.
template <class Law>
void euler_tracking_step(benchmark::State& state, Law& law) {
  const adcs::SinusoidalEulerReference ref;
  typename Law::Measurement m;
  m.angles = adcs::Vec3(0.25, 0.15, -0.20) * (3.14159265358979 / 180.0);
  m.omega_BN_B = adcs::Vec3(2e-4, 1e-4, -3e-4);
  typename Law::Command out;
  double k = 0.0;
  for (auto _ : state) {
    m.t = 1e-9 * k;
    m.angles(0) += 1e-15;
    k += 1.0;
    benchmark::DoNotOptimize(law.step(m, ref.sample(m.t), out));
    benchmark::DoNotOptimize(out.torque_B.data());
    if (static_cast<long>(k) % 4096 == 0) law.reset();
  }
}
void BM_FlexiblePPC_Step(benchmark::State& state) {
  adcs::PpcNeural law({adcs::seed002_tracking_gains(), adcs::seed002_performance()});
  euler_tracking_step(state, law);
}
BENCHMARK(BM_FlexiblePPC_Step);
void BM_AdaptiveTracking_Step(benchmark::State& state) {
  adcs::AdaptiveTracking law({adcs::seed002_tracking_gains()});
  euler_tracking_step(state, law);
}
BENCHMARK(BM_AdaptiveTracking_Step);

// Seed 004, one 0.1 s sample. The filters are built from the drag-free model once.
struct DragFreeBench {
  adcs::DragFreeParams p;
  adcs::DragFreeDiscrete d;
  adcs::DragFreeEskf::Params e1;
  adcs::SaturatedEsfParams e2[3];
  DragFreeBench() {
    if (adcs::drag_free_discretize(p, d) != adcs::Status::ok) std::abort();
    const adcs::DragFreeNoise n = adcs::drag_free_noise(p);
    e1.A_d = d.A_d;
    e1.B_d = d.B_d;
    e1.B_e = d.B_e;
    e1.C_d = d.C_d;
    e1.q.head<6>().setConstant(8.538e-13);
    e1.S = (n.sigma_F_sc * n.sigma_F_sc) * adcs::Mat<9, 9>::Identity();
    e1.R = (n.sigma_pos * n.sigma_pos) * adcs::Mat<9, 9>::Identity();
    for (int j = 0; j < 3; ++j) {
      adcs::DragFreeAxisModel m;
      if (adcs::drag_free_axis_model(p, j, m) != adcs::Status::ok) std::abort();
      e2[j].A_d = m.A_d;
      e2[j].B_d = m.B_d;
      e2[j].C = m.C;
      e2[j].D = m.D;
      e2[j].q = 8.538e-13;
      e2[j].S = n.sigma_F_sc * n.sigma_F_sc;
      e2[j].R_a = n.sigma_acc * n.sigma_acc;
      e2[j].y_min = p.accel_min;
      e2[j].y_max = p.accel_max;
    }
  }
};

void BM_DragFreeEskf_Step(benchmark::State& state) {
  const DragFreeBench b;
  adcs::DragFreeEskf f(b.e1);
  adcs::Vec<9> Y = adcs::Vec<9>::Constant(1e-8), u = adcs::Vec<9>::Zero();
  for (auto _ : state) {
    Y(0) += 1e-12;
    benchmark::DoNotOptimize(f.predict(u));
    benchmark::DoNotOptimize(f.update(Y));
  }
}
BENCHMARK(BM_DragFreeEskf_Step);

void BM_SaturatedEsf_Step(benchmark::State& state) {  // alternating in-range and saturated samples
  const DragFreeBench b;
  adcs::SaturatedEsf f(b.e2[0]);
  long k = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(f.predict(0.0));
    benchmark::DoNotOptimize(f.update((++k & 1) ? 1e-7 : 6e-6, 0.0));
  }
}
BENCHMARK(BM_SaturatedEsf_Step);

void BM_DragFreeAdrc_Step(benchmark::State& state) {  // Algorithms 1-3 + ADRC for one sample
  const DragFreeBench b;
  adcs::DragFreeEskf a1(b.e1);
  adcs::SaturatedEsf a2[3] = {adcs::SaturatedEsf(b.e2[0]), adcs::SaturatedEsf(b.e2[1]), adcs::SaturatedEsf(b.e2[2])};
  adcs::DragFreeAdrc ctrl(adcs::DragFreeAdrcParams{});
  adcs::Vec<9> Y = adcs::Vec<9>::Constant(1e-8), u = adcs::Vec<9>::Zero();
  for (auto _ : state) {
    Y(0) += 1e-12;
    benchmark::DoNotOptimize(a1.predict(u));
    for (auto& f : a2) benchmark::DoNotOptimize(f.predict(u(4)));
    benchmark::DoNotOptimize(a1.update(Y));
    const adcs::Vec3 F(a2[0].state()(2), a2[1].state()(2), a2[2].state()(2));
    benchmark::DoNotOptimize(ctrl.step(a1.state(), F, adcs::Vec3::Zero(), u));
    for (int j = 0; j < 3; ++j) {
      benchmark::DoNotOptimize(a2[j].update(1e-7, u(3 + j)));
      benchmark::DoNotOptimize(adcs::fuse_axis(a1, a2[j], j));
    }
  }
}
BENCHMARK(BM_DragFreeAdrc_Step);

// Seed 003, one 8 Hz command from the chaser and target states (tracking error, G, G⁻¹, Ġξ_e, F0,
// the law; the target's feed-forward ξ̇_o included), state 1 of the paper.
struct Se3Bench {
  adcs::Se3ScenarioParams sp;
  adcs::Se3Spacecraft target_model{adcs::se3_target_params(sp)};
  adcs::Se3SpacecraftState target, chaser;
  Se3Bench() {
    if (adcs::se3_target_initial_state(sp, target) != adcs::Status::ok) std::abort();
    chaser = adcs::se3_chaser_initial_state(target, adcs::kSe3InitialPoses[0]);
  }
};

template <class Law>
void se3_step(benchmark::State& state, Law& law) {
  Se3Bench b;
  adcs::Vec6 u;
  for (auto _ : state) {
    b.chaser.R_N(0) += 1e-9;
    adcs::Se3DesiredState d;
    benchmark::DoNotOptimize(adcs::se3_desired_state(b.target_model, b.target, b.sp, d));
    benchmark::DoNotOptimize(law.step(b.chaser, d, u));
    benchmark::DoNotOptimize(u.data());
  }
}
void BM_SE3PrescribedTime_Step(benchmark::State& state) {
  const adcs::Se3ScenarioParams sp;
  adcs::PrescribedTimeSe3 law(adcs::PrescribedTimeSe3Params{}, adcs::se3_chaser_nominal_params(sp));
  se3_step(state, law);
}
BENCHMARK(BM_SE3PrescribedTime_Step);
void BM_SE3Ftsmc_Step(benchmark::State& state) {
  const adcs::Se3ScenarioParams sp;
  adcs::FtsmcSe3 law(adcs::FtsmcSe3Params{}, adcs::se3_chaser_nominal_params(sp));
  se3_step(state, law);
}
BENCHMARK(BM_SE3Ftsmc_Step);

// Right pseudo-inverse solve of a 3x4 matrix via LDLT of X X^T, with conditioning report.
void BM_Pinv3x4(benchmark::State& state) {
  adcs::Mat<3, 4> X = four_wheel_axes();
  const adcs::Vec3 v(0.1, 0.2, 0.3);
  adcs::Vec<4> u;
  adcs::PinvInfo info;
  for (auto _ : state) {
    X(0, 3) += 1e-12;
    benchmark::DoNotOptimize(adcs::right_pinv_solve<3, 4>(X, v, u, &info));
    benchmark::DoNotOptimize(u.data());
  }
}
BENCHMARK(BM_Pinv3x4);

// Continuous Lyapunov solve for seed 001's 6x6 A_1 (done once at construction in flight code).
void BM_Lyapunov6(benchmark::State& state) {
  adcs::Mat<3, 6> K;
  const double r2 = std::sqrt(2.0);
  const adcs::AxisPoles<3> poles{{{{{-0.2, 0.2}, {-0.2, -0.2}}},
                                  {{{-0.3, 0.3}, {-0.3, -0.3}}},
                                  {{{-0.2 * r2, 0}, {-0.3 * r2, 0}}}}};
  if (adcs::place_double_integrator<3>(poles, K) != adcs::Status::ok) state.SkipWithError("place");
  adcs::Mat6 A1 = adcs::double_integrator_closed_loop<3>(K);
  adcs::Mat6 P;
  for (auto _ : state) {
    A1(3, 0) -= 1e-15;
    benchmark::DoNotOptimize(adcs::solve_continuous_lyapunov<6>(A1, adcs::Mat6::Identity(), P));
    benchmark::DoNotOptimize(P.data());
  }
}
BENCHMARK(BM_Lyapunov6);

#ifdef ADCS_BENCH_HAVE_SIM
// One 300 s closed-loop run of rigid-rw-mrp-pd (CVODE Adams, 10 Hz ZOH, no file output).
void BM_RigidRw_300s(benchmark::State& state) {
  const adcs::sim::Scenario* s = adcs::sim::find_scenario("rigid-rw-mrp-pd");
  if (!s) {
    state.SkipWithError("rigid-rw-mrp-pd not registered");
    return;
  }
  adcs::sim::ParamSet params;
  s->declare(params);
  params.set("duration_s", "300");
  adcs::sim::RunContext ctx;
  ctx.quiet = true;
  for (auto _ : state) {
    adcs::sim::RunResult r = s->run(params, ctx);
    benchmark::DoNotOptimize(r.metrics.data());
  }
}
BENCHMARK(BM_RigidRw_300s)->Unit(benchmark::kMillisecond);
#endif

}  // namespace

BENCHMARK_MAIN();
