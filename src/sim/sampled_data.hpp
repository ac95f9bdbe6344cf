#pragma once
// The sampled-data (zero-order-hold) loop that joins a discrete controller to a continuous plant.
//
// Samples at t_k = t0 + k*T, k = 0 .. N-1, N = interval_count(t_end - t0, T); the last interval
// ends at t_end and is shorter when t_end - t0 is not a multiple of T. At each sample:
//   1. plant.normalize(x) if the plant has one (MRP shadow switch),
//   2. controller(t_k, x, u)   — computes the command u from the state (the caller applies its own
//                                measurement model); u still holds the previous command on entry
//                                (zero at k = 0), so a controller that fails may simply keep it,
//   3. observer(t_k, x, u)     — recording and metrics; sees the command just computed,
//   4. integrator.reset(t_k, x) (CVodeReInit: the command changed and x may be re-parameterised),
//      integrator.advance(t_{k+1}, u, x) with u held (ZOH).
// Finally, at t_end: plant.normalize(x) if any, then observer(t_end, x, u) once more with the last
// command. So normalize and the observer are called N + 1 times, the controller N times.
//
// Progress: while a ProgressScope is alive on the calling thread (adcs-sim installs one around
// Scenario::run when progress is wanted), the loop reports (t_{k+1}, t_end) after every
// interval as (t0, t_{k+1}, t_end); the sink rate-limits its output. Without one the cost is one test per sample.
#include <cmath>
#include <cstddef>
#include <functional>
#include <string>
#include <utility>

#include "sim/intervals.hpp"
#include "sim/plant_traits.hpp"
#include "sim/sim_error.hpp"

namespace adcs::sim {

//! Progress sink of run_sampled_data: (start of the loop t0, simulated time t, end t_end) [s].
using ProgressFn = std::function<void(double t0_s, double t_s, double t_end_s)>;

//! The calling thread's current progress sink (empty: none).
inline ProgressFn& current_progress() {
  thread_local ProgressFn sink;
  return sink;
}

//! Installs `sink` as the thread's progress sink for its lifetime (restores the previous one).
class ProgressScope {
 public:
  explicit ProgressScope(ProgressFn sink) : previous_(std::move(current_progress())) {
    current_progress() = std::move(sink);
  }
  ~ProgressScope() { current_progress() = std::move(previous_); }
  ProgressScope(const ProgressScope&) = delete;
  ProgressScope& operator=(const ProgressScope&) = delete;

 private:
  ProgressFn previous_;
};

struct SampledDataOptions {
  double t0 = 0.0;             //!< [s] time of the first sample
  double t_end = 0.0;          //!< [s] end of the run, >= t0
  double sample_period = 0.0;  //!< [s] controller sample period T, > 0
};

//! Runs the loop described above. x is the state at t0 on entry and at t_end on return.
//! ControllerFn: void(double t, const State& x, Input& u); ObserverFn: void(double t, const State&
//! x, const Input& u). Throws SimError on invalid options; integrator errors propagate.
template <class Plant, class Integrator, class ControllerFn, class ObserverFn>
void run_sampled_data(const Plant& plant, Integrator& integrator, typename Plant::State& x,
                      const SampledDataOptions& options, ControllerFn&& controller,
                      ObserverFn&& observer) {
  using Input = typename Plant::Input;
  const double t0 = options.t0;
  const double period = options.sample_period;
  if (!std::isfinite(t0) || !std::isfinite(options.t_end) || !(options.t_end >= t0))
    throw SimError("run_sampled_data: need finite t0 <= t_end (t0 = " + format_double(t0) +
                   " s, t_end = " + format_double(options.t_end) + " s)");
  const std::size_t n = interval_count(options.t_end - t0, period);  // checks period > 0

  const ProgressFn& progress = current_progress();
  Input u = Input::Zero();
  for (std::size_t k = 0; k < n; ++k) {
    // Why t0 + k*T and not t += T: no drift of the sample times over long runs.
    const double t_k = t0 + static_cast<double>(k) * period;
    const double t_next = (k + 1 == n) ? options.t_end : t0 + static_cast<double>(k + 1) * period;
    normalize_if_any(plant, x);
    controller(t_k, std::as_const(x), u);
    observer(t_k, std::as_const(x), std::as_const(u));
    integrator.reset(t_k, x);
    integrator.advance(t_next, std::as_const(u), x);
    if (progress) progress(t0, t_next, options.t_end);
  }
  normalize_if_any(plant, x);
  observer(options.t_end, std::as_const(x), std::as_const(u));
}

}  // namespace adcs::sim
