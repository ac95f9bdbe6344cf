#pragma once
// Seed 002's prescribed-performance law (PpcNeural) as a vehicle file flies it: through the x-y-z
// Euler view of the measured state and of the inertial reference (to_euler123,
// to_euler_reference), the reference angles moved by 2πk onto the measured angles' branch so that
// a target near ±180° is not read as a 360° error (the adapter of cross_vscmg.cpp's hybrid-ppc).
// Its member functions are compiled once, in ppc_law.cpp, not again in each of the nine loop
// instantiations (the law does not depend on the actuator set).
#include "adcs/control/ppc_neural.hpp"
#include "adcs/core/signals.hpp"

namespace adcs::sim::vehicle {

class PpcEulerLaw {
 public:
  explicit PpcEulerLaw(const PpcNeuralParams& p) noexcept;
  Status status() const noexcept;
  void reset() noexcept;
  double period_s() const noexcept;
  long funnel_recoveries() const noexcept;
  //! One sample at t_s [s]; `reopened`: this step re-opened the funnel. A reference at an Euler
  //! gimbal lock returns singular with the failure command (zero torque, or the last good one).
  Status step(double t_s, const AttitudeState& state, const AttitudeReference& reference, BodyTorque& out,
              bool& reopened) noexcept;

 private:
  PpcNeural law_;
  BodyTorque last_{};
};

}  // namespace adcs::sim::vehicle
