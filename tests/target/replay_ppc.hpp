#pragma once
// Replay core of seed 002 (control/ppc_neural.hpp): the PPATC law with the paper's gains, true
// inertia and performance functions (seed002_tracking_gains(), seed002_performance(); U_rad,
// T = 1e-4 s), as flexible-ppc in src/scenarios/flexible_ppc.cpp. One step() = the recorded row
// converted to the law's Input ("inputs") + one PpcNeural::step() with the reference sample as
// input ("ppc_step"; BM_FlexiblePPC_Step also samples the reference; here it is recorded so that
// its sin/cos are not part of the step).
// S = double is the Cortex-M7 System "ppc", S = float the Cortex-M4F System "ppc_f" (issue 19:
// PpcNeuralT<float> on a single-precision FPU; its parameters are the double ones rounded once,
// and each row is converted to float before the step, as a flight computer's sensor interface
// would hand it over).
#include <type_traits>

#include "adcs/control/ppc_neural.hpp"
#include "adcs/plant/flexible_configurations.hpp"  // seed002_tracking_gains()
#include "replay_euler_row.hpp"
#include "replay_system.hpp"

namespace replay {

template <class S>
class PpcSystem : public EulerRowSystem<adcs::PpcNeuralT<S>> {
 public:
  using Controller = adcs::PpcNeuralT<S>;
  using Vec3S = adcs::Vec<3, S>;
  static constexpr const char* kName = std::is_same_v<S, float> ? "ppc_f" : "ppc";
  // Row: t, ϑ (3), ω (3), ϑ_d (3), ϑ̇_d (3), ϑ̈_d (3).
  static constexpr int kInputWidth = kEulerRowWidth;
  static constexpr int kCommandSize = 3, kParts = 1;
  static constexpr double kPeriod = 1.0e-4;  // [s] EulerTrackingGains default (spec §B.5)
  // Comparison scales (replay_system.hpp, Column): per group of like outputs, a power of ten at
  // or below the smallest of their largest |value|s over the recorded run, so that the 1e-12
  // tolerance means 12 significant digits of the signal, not of a value passing through zero.
  // u 14 .. 38 N m (the initial transient), μ̂ 4.7e-3, Ŵ entries 7e-12 .. 8e-6 (one scale for
  // all, the smallest row's).
  static constexpr double kTorque = 1.0, kMu = 1e-3, kW = 1e-12;
  static constexpr int kCostStages = 2;
  static constexpr const char* kStageNames[kCostStages] = {"inputs", "ppc_step"};
  static constexpr Column kColumns[] = {
      {"status", 0.0}, {"branch1", 0.0}, {"branch2", 0.0}, {"branch3", 0.0}, {"u1", kTorque},
      {"u2", kTorque}, {"u3", kTorque},  {"mu", kMu},      {"W11", kW},      {"W21", kW},
      {"W31", kW},     {"W41", kW},      {"W51", kW},      {"W61", kW},      {"W71", kW},
      {"W12", kW},     {"W22", kW},      {"W32", kW},      {"W42", kW},      {"W52", kW},
      {"W62", kW},     {"W72", kW},      {"W13", kW},      {"W23", kW},      {"W33", kW},
      {"W43", kW},     {"W53", kW},      {"W63", kW},      {"W73", kW}};

  static typename Controller::Params params() noexcept {
    adcs::PpcNeuralParams p{adcs::seed002_tracking_gains(), adcs::seed002_performance()};
    p.gains.period_s = kPeriod;
    return p.template cast<S>();
  }

  PpcSystem() noexcept : EulerRowSystem<Controller>(params()) {}

  void outputs(double* v) const noexcept {
    *v++ = static_cast<double>(this->status_);
    for (int i = 0; i < 3; ++i) *v++ = static_cast<double>(static_cast<int>(this->ctrl_.branch(i)));
    for (int i = 0; i < 3; ++i) *v++ = static_cast<double>(this->cmd_.torque_B_Nm(i));
    *v++ = static_cast<double>(this->ctrl_.mu());
    const adcs::Mat<7, 3, S>& W = this->ctrl_.weights();
    for (int j = 0; j < 3; ++j)
      for (int i = 0; i < 7; ++i) *v++ = static_cast<double>(W(i, j));
  }
};

}  // namespace replay
