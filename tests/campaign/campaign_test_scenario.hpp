#pragma once
// A fast, deterministic scenario for the campaign tests: a first-order "attitude error" decaying
// from a seed-drawn start at a rate set by `gain`, with a `bias` vector, a claim that holds when
// the final error is small, and failures on demand (gain < 0: ParamError; gain > 100: a
// simulation error), so the campaign's bookkeeping is tested without a real plant.
#include <atomic>
#include <chrono>
#include <cmath>
#include <string>
#include <thread>

#include "scenarios/scenario.hpp"
#include "sim/random.hpp"
#include "sim/recorder.hpp"
#include "sim/sim_error.hpp"

namespace adcs::sim::campaign::test {

class DecayScenario final : public Scenario {
 public:
  mutable std::atomic<int> runs{0};
  //! Runs in progress now, and the most seen at once (how many runs overlap under --jobs).
  mutable std::atomic<int> in_flight{0}, max_in_flight{0};
  int sleep_ms = 0;            //!< each run takes at least this long (to see runs overlap)
  bool extra_metrics = false;  //!< "fast" (2nd) when gain > 1.5, "slow" (last) when gain < 0.5
  std::string name() const override { return "decay"; }
  std::string description() const override { return "test: exponential decay"; }
  void declare(ParamSet& p) const override {
    p.number("duration_s", 5.0, "s", "test");
    p.number("control_period_s", 0.5, "s", "test");
    p.number("gain", 1.0, "1/s", "test");
    p.vector("bias", {0.0, 0.0, 0.0}, "-", "test");
    p.matrix("spacecraft.J_kgm2", {{0.20, 0.0, 0.0}, {0.0, 0.25, 0.0}, {0.0, 0.0, 0.15}}, "kg m^2", "test");
  }
  RunResult run(const ParamSet& p, const RunContext& ctx) const override {
    ++runs;
    struct InFlight {
      const DecayScenario& s;
      explicit InFlight(const DecayScenario& sc) : s(sc) {
        const int now = ++s.in_flight;
        for (int m = s.max_in_flight.load(); now > m && !s.max_in_flight.compare_exchange_weak(m, now);) {
        }
      }
      ~InFlight() { --s.in_flight; }
    } in_flight_scope(*this);
    if (sleep_ms > 0) std::this_thread::sleep_for(std::chrono::milliseconds(sleep_ms));
    const double gain = p.get_number("gain");
    if (gain < 0.0) throw ParamError("gain must be >= 0");
    if (gain > 100.0) throw SimError("closed loop diverged (test)");
    Rng rng(ctx.seed);
    const double e0 = 1.0 + rng.uniform(0.0, 1.0);
    const double b = p.get_vec<3>("bias").sum();
    const double J = p.get_mat<3, 3>("spacecraft.J_kgm2").trace();
    std::unique_ptr<CsvRecorder> csv;
    if (!ctx.csv_path.empty()) csv = std::make_unique<CsvRecorder>(ctx.csv_path, std::vector<Column>{{"t", "s"}, {"err", "rad"}});
    double e = 0.0;
    for (int k = 0; k <= 10; ++k) {
      const double t = 0.5 * k;
      e = e0 * std::exp(-gain * t) + std::abs(b);
      if (csv) csv->record_row({t, e}, k == 10);
    }
    RunResult r;
    r.metrics = {{"err_final", e}, {"J_trace", J}, {"e0", e0}};
    if (extra_metrics && gain > 1.5) r.metrics.insert(r.metrics.begin() + 1, {"fast", gain});
    if (extra_metrics && gain < 0.5) r.metrics.emplace_back("slow", gain);
    r.claims.push_back({"check", "error below 0.05 at the end", "< 0.05", std::to_string(e), e < 0.05});
    r.claims.push_back({"check", "informative row", "-", "-", std::nullopt});
    return r;
  }
};

}  // namespace adcs::sim::campaign::test
