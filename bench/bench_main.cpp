// adcs-bench: per-step latency of every controller and estimator (BM_<Name>_Step), plus math
// kernels and one whole closed-loop CVODE run. Run e.g.
//   taskset -c 1 build/bench/adcs-bench --benchmark_repetitions=10 --benchmark_report_aggregates_only=true
// and read the *_median rows, or let tools/check-budgets.sh compare them with bench/budgets.json.
//
// Each BM_<Name>_Step reports
//   - Time: the mean per step of Google Benchmark's timed loop (no clock call per step);
//   - step_p50_ns / step_p99_ns: percentiles of 20,000 individually timed steps run after that
//     loop (steady_clock around each step, minus the median cost of an empty timed region, so
//     they compare with Time; steps under ~1 µs are timed in batches, step_batch per sample);
//     the distribution a flight timing budget is about;
//   - allocs_per_step: operator new calls per step over both passes (must be 0).
// The step code itself lives in bench/step_fixtures.hpp, shared with adcs-stepcount (callgrind).
#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <vector>

#include "counting_new.hpp"  // tests/nomalloc: counts every operator new (allocs_per_step)
#include "step_fixtures.hpp"
#ifdef ADCS_BENCH_HAVE_SIM
#include "scenarios/registry.hpp"
#endif

namespace {

using Clock = std::chrono::steady_clock;
constexpr int kSampledSteps = 20000;

//! Median cost [ns] of an empty timed region (two steady_clock reads), subtracted from samples.
double clock_overhead_ns() {
  static const double overhead = [] {
    std::vector<double> d(4001);
    for (double& x : d) {
      const auto t0 = Clock::now();
      const auto t1 = Clock::now();
      x = std::chrono::duration<double, std::nano>(t1 - t0).count();
    }
    std::nth_element(d.begin(), d.begin() + 2000, d.end());
    return d[2000];
  }();
  return overhead;
}

//! Google Benchmark's loop over one step, then the per-step sampling pass (see the header).
//! Steps much shorter than the clock's resolution (~20 ns) are timed in batches of B steps (each
//! batch ≥ ~1 µs, B in step_batch) and each sample is batch time / B.
template <class Fixture>
void BM_Step(benchmark::State& state) {
  Fixture step;
  std::vector<double> ns(kSampledSteps);  // allocated before counting starts
  const double overhead = clock_overhead_ns();
  const long allocs0 = adcs::test::g_new_calls.load();
  for (auto _ : state) step();
  const auto c0 = Clock::now();
  for (int k = 0; k < 2000; ++k) step();
  const double mean_ns = std::chrono::duration<double, std::nano>(Clock::now() - c0).count() / 2000.0;
  const int batch = static_cast<int>(std::clamp(std::ceil(1000.0 / std::max(mean_ns, 1e-3)), 1.0, 1000.0));
  for (double& x : ns) {
    const auto t0 = Clock::now();
    for (int b = 0; b < batch; ++b) step();
    const auto t1 = Clock::now();
    x = std::max(0.0, std::chrono::duration<double, std::nano>(t1 - t0).count() - overhead) / batch;
  }
  const long allocs = adcs::test::g_new_calls.load() - allocs0;
  auto pct = [&](double q) {
    const auto k = static_cast<std::size_t>(q * (ns.size() - 1));
    std::nth_element(ns.begin(), ns.begin() + static_cast<long>(k), ns.end());
    return ns[k];
  };
  state.counters["step_p50_ns"] = pct(0.50);
  state.counters["step_p99_ns"] = pct(0.99);
  state.counters["step_batch"] = batch;
  state.counters["allocs_per_step"] =
      double(allocs) / double(static_cast<long>(state.iterations()) + 2000 + double(kSampledSteps) * batch);
}

namespace fx = adcs::bench;
#define ADCS_STEP_BENCHMARK(N) BENCHMARK_TEMPLATE(BM_Step, fx::N##Step)->Name("BM_" #N "_Step")

ADCS_STEP_BENCHMARK(MrpPd);
ADCS_STEP_BENCHMARK(RwAllocation);
ADCS_STEP_BENCHMARK(HybridAdaptive);            // seed 001, the paper's estimate update
ADCS_STEP_BENCHMARK(HybridAdaptiveNormalized);  // seed 001, ours for 5-20 Hz
ADCS_STEP_BENCHMARK(FlexiblePPC);               // seed 002 PPATC
ADCS_STEP_BENCHMARK(AdaptiveTracking);          // seed 002 ATC baseline
ADCS_STEP_BENCHMARK(DragFreeEskf);              // seed 004 Algorithm 1
ADCS_STEP_BENCHMARK(SaturatedEsf);              // seed 004 Algorithm 2, one axis
ADCS_STEP_BENCHMARK(Fusion);                    // seed 004 Algorithm 3, one axis
ADCS_STEP_BENCHMARK(Adrc);                      // seed 004 ADRC law alone
ADCS_STEP_BENCHMARK(Pid);                       // seed 004 PID baseline
ADCS_STEP_BENCHMARK(DragFreeAdrc);              // seed 004 whole sample: Algorithms 1-3 + ADRC
ADCS_STEP_BENCHMARK(SE3PrescribedTime);         // seed 003 BsPdTC
ADCS_STEP_BENCHMARK(SE3Ftsmc);                  // seed 003 FTSMC baseline
ADCS_STEP_BENCHMARK(CompositeQuantizer);        // seed 003 sat + quantizer, 6 channels

// Right pseudo-inverse solve of a 3x4 matrix via LDLT of X X^T, with conditioning report.
void BM_Pinv3x4(benchmark::State& state) {
  adcs::Mat<3, 4> X = fx::four_wheel_axes();
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
