#pragma once
// Replay cores of the Euler-angle tracking laws that fly seed 002's flexible spacecraft beside its
// PPATC, in float (issue 19, the Cortex-M4F Systems "atc_f" and "eso_adrc_f"): seed 002's ATC
// baseline, AdaptiveTrackingT<float>, with the paper's gains (seed002_tracking_gains(), T = 1e-4
// s) as flexible-atc flies it, and the ESO-based ADRC of the cross pairing, EsoAdrcAttitudeT<float>
// (the true J, ω_o = 2 rad/s, ω_c = 0.5 rad/s, h = 0.05 s), as flexible-eso-adrc flies it, each
// with its parameters rounded once to float. Row as seed 002's (replay_ppc.hpp): t, ϑ, ω, ϑ_d,
// ϑ̇_d, ϑ̈_d; each System's own loop is recorded (record_inputs atc_f, eso_adrc_f: the flexible
// spacecraft of flexible-ppc at the law's period). Two stages: the row's conversion to float
// ("inputs", the replay's, not flight code) and the law's step() ("law_step").
#include <type_traits>

#include "adcs/control/adaptive_tracking.hpp"
#include "adcs/control/eso_adrc_attitude.hpp"
#include "adcs/plant/flexible_configurations.hpp"  // seed002_tracking_gains(), flexible_params_seed002()
#include "replay_euler_row.hpp"
#include "replay_system.hpp"

namespace replay {

//! What differs between the two laws: name, period, parameters (double, rounded once by the
//! System) and the outputs beyond status and torque. Comparison scales: per group of like
//! outputs, a power of ten at or below the smallest of their largest |value|s over the recorded
//! run (replay_system.hpp, Column): u as seed 002's (1 N m), the ATC's weights Ŵ as the PPATC's
//! (1e-12: one scale for all, the smallest row's), the ESO's estimates 1e-6 (rad, rad/s, rad/s²).
template <class Law>
struct EulerFloatLaw;
template <>
struct EulerFloatLaw<adcs::AdaptiveTrackingT<float>> {
  static constexpr const char* kName = "atc_f";
  static constexpr double kPeriod = 1.0e-4;  // [s] EulerTrackingGains default (spec §B.5)
  static adcs::AdaptiveTrackingParams params() noexcept {
    adcs::AdaptiveTrackingParams p{adcs::seed002_tracking_gains()};
    p.gains.period_s = kPeriod;
    return p;
  }
  static constexpr double kTorque = 1.0, kW = 1e-12;
  static constexpr Column kColumns[] = {
      {"status", 0.0}, {"u1", kTorque}, {"u2", kTorque}, {"u3", kTorque}, {"W11", kW}, {"W21", kW}, {"W31", kW},
      {"W41", kW},     {"W51", kW},     {"W61", kW},     {"W71", kW},     {"W12", kW}, {"W22", kW}, {"W32", kW},
      {"W42", kW},     {"W52", kW},     {"W62", kW},     {"W72", kW},     {"W13", kW}, {"W23", kW}, {"W33", kW},
      {"W43", kW},     {"W53", kW},     {"W63", kW},     {"W73", kW}};
  static void extra(const adcs::AdaptiveTrackingT<float>& law, double* v) noexcept {
    const adcs::Mat<7, 3, float>& W = law.weights();
    for (int j = 0; j < 3; ++j)
      for (int i = 0; i < 7; ++i) *v++ = static_cast<double>(W(i, j));
  }
};
template <>
struct EulerFloatLaw<adcs::EsoAdrcAttitudeT<float>> {
  static constexpr const char* kName = "eso_adrc_f";
  static constexpr double kPeriod = 0.05;  // [s] flexible-eso-adrc's control_period_s default
  static adcs::EsoAdrcAttitudeParams params() noexcept {
    adcs::EsoAdrcAttitudeParams p;  // flexible-eso-adrc's defaults (adrc_J_scale = 1)
    p.J_B_kgm2 = adcs::flexible_params_seed002().J;
    p.omega_o_rad_s = 2.0;
    p.omega_c_rad_s = 0.5;
    p.period_s = kPeriod;
    return p;
  }
  static constexpr double kTorque = 1.0, kZ = 1e-6;
  static constexpr Column kColumns[] = {{"status", 0.0}, {"u1", kTorque}, {"u2", kTorque}, {"u3", kTorque},
                                        {"z11", kZ},     {"z12", kZ},     {"z13", kZ},     {"z21", kZ},
                                        {"z22", kZ},     {"z23", kZ},     {"z31", kZ},     {"z32", kZ},
                                        {"z33", kZ}};
  static void extra(const adcs::EsoAdrcAttitudeT<float>& law, double* v) noexcept {
    for (int i = 0; i < 3; ++i) *v++ = static_cast<double>(law.angles_hat_rad()(i));
    for (int i = 0; i < 3; ++i) *v++ = static_cast<double>(law.angles_dot_hat_rad_s()(i));
    for (int i = 0; i < 3; ++i) *v++ = static_cast<double>(law.f_hat_rad_s2()(i));
  }
};

template <class Law>
class EulerFloatSystem : public EulerRowSystem<Law> {
 public:
  using Controller = Law;
  using Traits = EulerFloatLaw<Law>;
  static constexpr const char* kName = Traits::kName;
  static constexpr int kInputWidth = kEulerRowWidth;  // replay_euler_row.hpp
  static constexpr int kCommandSize = 3, kParts = 1;
  static constexpr double kPeriod = Traits::kPeriod;
  static constexpr int kCostStages = 2;
  static constexpr const char* kStageNames[kCostStages] = {"inputs", "law_step"};
  static constexpr auto& kColumns = Traits::kColumns;

  EulerFloatSystem() noexcept : EulerRowSystem<Law>(Traits::params().template cast<float>()) {}
  void outputs(double* v) const noexcept {
    *v++ = static_cast<double>(this->status_);
    for (int i = 0; i < 3; ++i) *v++ = static_cast<double>(this->cmd_.torque_B_Nm(i));
    Traits::extra(this->ctrl_, v);
  }
};

}  // namespace replay
