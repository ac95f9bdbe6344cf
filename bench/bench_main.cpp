// adcs-bench: per-step latency of every controller and estimator (BM_<Name>_Step) and the math
// kernels, registered in bench/step_entries.cpp (shared with adcs-stepcount), plus one whole
// closed-loop CVODE run here. Run e.g.
//   taskset -c 1 build/bench/adcs-bench --benchmark_repetitions=10 --benchmark_report_aggregates_only=true
// and read the *_median rows, or let tools/check-budgets.py compare them with bench/budgets.json.
#include <benchmark/benchmark.h>

#ifdef ADCS_BENCH_HAVE_SIM
#include <memory>

#include "scenarios/scenario.hpp"

namespace adcs::sim {
// src/scenarios/rigid_rw_mrp_pd.cpp (library adcs_scenarios_rigid_rw), as registry.cpp declares it:
// the bench links that scenario alone, not the registry of every paper's closed loop.
std::unique_ptr<Scenario> make_rigid_rw_mrp_pd();
}  // namespace adcs::sim

namespace {
// One 300 s closed-loop run of rigid-rw-mrp-pd (CVODE Adams, 10 Hz ZOH, no file output).
void BM_RigidRw_300s(benchmark::State& state) {
  const std::unique_ptr<adcs::sim::Scenario> s = adcs::sim::make_rigid_rw_mrp_pd();
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
}  // namespace
#endif

BENCHMARK_MAIN();
