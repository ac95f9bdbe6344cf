#pragma once
// Replay core of seed 003 (control/prescribed_time_se3.hpp): one 8 Hz tick of the se3-ptc loop
// of src/scenarios/se3_loop.cpp with its defaults (state 1, quantize = 1): the desired state from
// the target's state (se3_desired_state, as BM_SE3PrescribedTime_Step), the BsPdTC law with the
// spec Table 1 gains, then sat -> Q (saturate_then_quantize, seed 003 quantizer). Inputs: the
// chaser's and the target's states as the loop hands them to the controller. Cost stages
// (replay_system.hpp): desired_state, controller_step (the law alone: the issue's "controller
// step()"), saturate_quantize.
#include "adcs/actuator/quantizer.hpp"
#include "adcs/control/prescribed_time_se3.hpp"
#include "adcs/plant/se3_spacecraft.hpp"
#include "replay_system.hpp"
#include "scenarios/seed003_data.hpp"  // seed 003's scenario data (paper data, not flight code)

namespace replay {

class Se3System {
 public:
  using Controller = adcs::PrescribedTimeSe3;
  using State = adcs::Se3SpacecraftState;
  static constexpr const char* kName = "se3";
  // Row: chaser C_NB (9, column-major), R_N (3), ω (3), v_B (3); target the same (18).
  static constexpr int kInputWidth = 36;
  static constexpr int kCommandSize = 6, kParts = 1;
  static constexpr int kCostStages = 3;
  static constexpr const char* kStageNames[kCostStages] = {"desired_state", "controller_step",
                                                           "saturate_quantize"};
  static constexpr double kPeriod = 0.125;  // [s] 8 Hz, Se3ScenarioParams::control_period (GIVEN)
  // Comparison scales (replay_system.hpp, Column): per group of like outputs, a power of ten at
  // or below the smallest of their largest |value|s over the recorded run, so that the 1e-12
  // tolerance means 12 significant digits of the signal, not of a value passing through zero.
  // Commands before sat/Q: M 0.27 .. 2.6 N m, F 52 .. 102 N; after: M_c 0.3 .. 0.5 N m, F_c 5 N;
  // ψ̂ 3.2e-4.
  static constexpr double kM = 0.1, kF = 10.0, kFc = 1.0, kPsi = 1e-4;
  static constexpr Column kColumns[] = {
      {"status_desired", 0.0}, {"status_law", 0.0}, {"status_quant", 0.0}, {"transmissions", 0.0},
      {"M1", kM},    {"M2", kM},    {"M3", kM},    {"F1", kF},    {"F2", kF},    {"F3", kF},
      {"Mc1", kM},   {"Mc2", kM},   {"Mc3", kM},   {"Fc1", kFc},  {"Fc2", kFc},  {"Fc3", kFc},
      {"psi_hat", kPsi}};

  static adcs::Se3ScenarioParams scenario_params() noexcept {
    adcs::Se3ScenarioParams sp;  // spec A.8 defaults
    sp.control_period = kPeriod;
    return sp;
  }
  static adcs::PrescribedTimeSe3Params params(const adcs::Se3ScenarioParams& sp) noexcept {
    adcs::PrescribedTimeSe3Params p;  // spec A.8 Table 1
    p.period_s = sp.control_period;
    p.zeta = adcs::quantization_compensation_gain(adcs::seed003_quantizer_params());  // ζ = 1.05 ϖ
    p.nominal = adcs::se3_chaser_nominal_params(sp);  // the controller's model of the chaser
    return p;
  }

  Se3System() noexcept
      : sp_(scenario_params()),
        target_model_(adcs::se3_target_params(sp_)),
        law_(params(sp_)),
        quantizer_(adcs::seed003_quantizer_params()),
        limit_(adcs::se3_actuator_limits(sp_)) {}

  adcs::Status init_status() const noexcept {
    if (target_model_.status() != adcs::Status::ok) return target_model_.status();
    if (quantizer_.status() != adcs::Status::ok) return quantizer_.status();
    return law_.status();
  }

  void step(const double* row) noexcept { step_stages(kCostStages, row); }
  //! The first n stages of step() (cost mode). The law's input (with the desired state) is a
  //! member, not a local, so that the first stage alone is not dead code.
  void step_stages(int n, const double* row) noexcept {
    status_desired_ = adcs::se3_desired_state(target_model_, get(row + 18), sp_, in_.desired);
    if (n < 2 || status_desired_ != adcs::Status::ok) return;  // not ok: command held (ZOH of the last one)
    in_.state = get(row);
    adcs::Wrench w;
    status_law_ = law_.step(in_, w);
    u_ = w.stacked();  // [M; F]
    if (n < 3) return;
    status_quant_ = adcs::saturate_then_quantize<6>(u_, limit_, quantizer_, u_c_);
  }

  void step_part(int, const double* row) noexcept { step(row); }
  //! The applied command u_c (after sat and Q).
  void command(double* u) const noexcept {
    for (int i = 0; i < 6; ++i) u[i] = u_c_(i);
  }

  void outputs(double* v) const noexcept {
    *v++ = static_cast<double>(status_desired_);
    *v++ = static_cast<double>(status_law_);
    *v++ = static_cast<double>(status_quant_);
    *v++ = static_cast<double>(quantizer_.transmissions());
    for (int i = 0; i < 6; ++i) *v++ = u_(i);
    for (int i = 0; i < 6; ++i) *v++ = u_c_(i);
    *v++ = law_.psi_hat();
  }

 private:
  static State get(const double* row) noexcept {
    State s;
    s.C_NB = adcs::Mat3::Map(row);
    s.R_N = adcs::Vec3::Map(row + 9);
    s.omega_BN_B = adcs::Vec3::Map(row + 12);
    s.v_B = adcs::Vec3::Map(row + 15);
    return s;
  }

  adcs::Se3ScenarioParams sp_;
  adcs::Se3Spacecraft target_model_;
  Controller law_;
  adcs::CompositeQuantizer<6> quantizer_;
  adcs::Vec6 limit_;
  adcs::Se3TrackingInput in_{};  //!< the chaser and desired states of the last tick
  adcs::Vec6 u_ = adcs::Vec6::Zero(), u_c_ = adcs::Vec6::Zero();
  adcs::Status status_desired_ = adcs::Status::ok, status_law_ = adcs::Status::ok,
               status_quant_ = adcs::Status::ok;
};

}  // namespace replay
