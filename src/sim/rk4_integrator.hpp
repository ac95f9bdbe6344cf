#pragma once
// Classical fixed-step Runge-Kutta 4 integrator with the same interface as CvodeIntegrator:
// reset(t0, x0) then advance(t1, u, x) with u held over [t, t1]. A second, independent
// implementation to cross-check CVODE against, and a cheap integrator for smooth plants.
#include <cmath>
#include <cstddef>
#include <string>

#include "adcs/core/types.hpp"
#include "sim/intervals.hpp"
#include "sim/sim_error.hpp"

namespace adcs::sim {

//! The plant is held by pointer: it must outlive the integrator. Copyable and movable.
template <class Plant>
class Rk4Integrator {
 public:
  using State = typename Plant::State;
  using Input = typename Plant::Input;

  //! max_substep [s] > 0: advance() uses ceil((t1 - t) / max_substep) equal substeps.
  //! Throws SimError if max_substep is not finite and positive.
  explicit Rk4Integrator(const Plant& plant, double max_substep)
      : plant_(&plant), max_substep_(max_substep) {
    if (!(max_substep > 0.0) || !std::isfinite(max_substep))
      throw SimError("Rk4Integrator: max_substep must be finite and > 0, got " +
                     format_double(max_substep));
  }

  //! Sets the time [s] and state. Throws SimError on non-finite t0 or x0.
  void reset(double t0, const State& x0) {
    if (!std::isfinite(t0) || !adcs::all_finite(x0))
      throw SimError("Rk4Integrator::reset: non-finite t0 or x0");
    t_ = t0;
    x_ = x0;
  }

  //! Integrates from time() to exactly t1 [s] with u held, in equal substeps of at most
  //! max_substep (see interval_count() for the rounding), and writes x(t1) to x.
  //! Throws SimError if t1 < time() or t1 is not finite.
  void advance(double t1, const Input& u, State& x) {
    if (!(t1 >= t_) || !std::isfinite(t1))
      throw SimError("Rk4Integrator::advance: t1 = " + format_double(t1) +
                     " s is not a finite time at or after the current time " +
                     format_double(t_) + " s");
    const std::size_t n = interval_count(t1 - t_, max_substep_);
    const double t_start = t_;
    const double h = (t1 - t_start) / static_cast<double>(n);
    for (std::size_t i = 0; i < n; ++i) {
      // Why t_start + i*h and not t += h: no accumulated round-off in the stage times.
      step(t_start + static_cast<double>(i) * h, h, u);
    }
    steps_ += static_cast<long>(n);
    t_ = t1;
    x = x_;
  }

  double time() const noexcept { return t_; }               //!< [s]
  long steps() const noexcept { return steps_; }            //!< cumulative RK4 substeps
  double max_substep() const noexcept { return max_substep_; }  //!< [s]

 private:
  void step(double t, double h, const Input& u) noexcept {
    State k1, k2, k3, k4;
    plant_->derivative(t, x_, u, k1);
    plant_->derivative(t + 0.5 * h, State(x_ + (0.5 * h) * k1), u, k2);
    plant_->derivative(t + 0.5 * h, State(x_ + (0.5 * h) * k2), u, k3);
    plant_->derivative(t + h, State(x_ + h * k3), u, k4);
    x_ += (h / 6.0) * (k1 + 2.0 * k2 + 2.0 * k3 + k4);
  }

  const Plant* plant_;
  double max_substep_;  //!< [s]
  double t_ = 0.0;      //!< [s]
  State x_ = State::Zero();
  long steps_ = 0;
};

}  // namespace adcs::sim
