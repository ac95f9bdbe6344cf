#pragma once
// The two loops every step fixture (bench/step_fixtures.hpp) runs in, shared by the per-seed
// translation units bench/steps_*.cpp, which adcs-bench and adcs-stepcount both link:
//   - BM_Step<Fixture> (adcs-bench): Google Benchmark's loop, then individually timed steps;
//   - adcs_counted_steps<Fixture> (adcs-stepcount): the region callgrind counts
//     (tools/callgrind-counts.py, --toggle-collect=*adcs_counted_steps*).
// Each BM_<Name>_Step reports
//   - Time: the mean per step of Google Benchmark's timed loop (no clock call per step);
//   - step_p50_ns / step_p99_ns: percentiles of 20,000 individually timed steps run after that
//     loop (steady_clock around each step, minus the median cost of an empty timed region, so
//     they compare with Time; steps under ~1 µs are timed in batches, step_batch per sample);
//     the distribution a flight timing budget is about;
//   - allocs_per_step: operator new calls per step over both passes (must be 0).
#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstddef>
#include <vector>

#include "new_counter.hpp"  // tests/nomalloc: g_new_calls, counted by counting_new.hpp

namespace adcs::bench {

using Clock = std::chrono::steady_clock;
inline constexpr int kSampledSteps = 20000;

//! Median cost [ns] of an empty timed region (two steady_clock reads), subtracted from samples.
inline double clock_overhead_ns() {
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

template <class Fixture>
__attribute__((noinline)) void adcs_counted_steps(Fixture& f, long steps) {
  for (long k = 0; k < steps; ++k) f();
}

//! Marks the end of a counted region: tools/callgrind-counts.py has callgrind dump its counts
//! when this returns (--dump-after), so one process can count several fixtures (adcs-stepcount
//! --each). Outside adcs_counted_steps collection is off, so it adds nothing to a count.
__attribute__((noinline)) inline void adcs_count_region_end() noexcept { asm volatile(""); }

template <class Fixture>
int run(long steps) {
  Fixture f;
  for (int k = 0; k < 100; ++k) f();  // warm-up: the same branches as in the counted steps
  adcs_counted_steps(f, steps);
  adcs_count_region_end();
  return 0;
}

//! One adcs-stepcount entry: a fixture's name and its counted run.
struct StepEntry {
  const char* name;
  int (*fn)(long);
};

//! A translation unit's fixtures for adcs-stepcount (bench/step_entries.cpp lists them all).
struct StepTable {
  const StepEntry* entries;
  int size;
};
//! A unit's table from its array of entries.
template <int N>
constexpr StepTable step_table(const StepEntry (&entries)[N]) noexcept {
  return {entries, N};
}
StepTable attitude_steps() noexcept;  // bench/steps_attitude.cpp
StepTable seed002_steps() noexcept;   // bench/steps_seed002.cpp
StepTable seed003_steps() noexcept;   // bench/steps_seed003.cpp
StepTable seed004_steps() noexcept;   // bench/steps_seed004.cpp
StepTable component_steps() noexcept;  // bench/steps_components.cpp: the one list of components

}  // namespace adcs::bench

// Both inside namespace adcs::bench (BENCHMARK_TEMPLATE pastes the function's name into a token).
#define ADCS_STEP_BENCHMARK(N) BENCHMARK_TEMPLATE(BM_Step, N##Step)->Name("BM_" #N "_Step")
#define ADCS_STEP_ENTRY(N) StepEntry{#N, &run<N##Step>}
