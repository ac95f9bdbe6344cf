#pragma once
// Replay core of seed 001 (control/hybrid_adaptive.hpp): HybridAdaptive<4, 3, S> on the A-REF
// configuration (replay_hybrid_params.hpp), built from the gain table designed on the host
// (replay_gains_hybrid.hpp, written by design_gains.cpp) as a flight build would be. One
// step() = one HybridAdaptive::step() (as BM_HybridAdaptive_Step). Used by the host and target
// replays and by record_inputs.cpp, which closes the loop around this very object.
// S = double is the Cortex-M7 System "hybrid", S = float the Cortex-M4F System "hybrid_f" (issue
// 19: the law on a single-precision FPU; its parameters are the double ones rounded once, its
// gains the table's float rows, and each row is converted to float before the step, as a flight
// computer's sensor interface would hand it over; that conversion is its own cost stage, library
// calls on the M4F, the driver's cost, not the law's).
#include <type_traits>

#include "replay_gains_hybrid.hpp"  // generated in the build tree by design_gains
#include "replay_hybrid_params.hpp"
#include "replay_system.hpp"

namespace replay {

//! The float System's cost stages (replay_system.hpp); the double System is measured whole, as
//! before the float one existed.
template <class S>
struct HybridStages {};
template <>
struct HybridStages<float> {
  static constexpr int kCostStages = 2;
  static constexpr const char* kStageNames[kCostStages] = {"inputs", "hybrid_step"};
};

template <class S>
class HybridSystem : public HybridStages<S> {
 public:
  using Controller = adcs::HybridAdaptive<4, 3, S>;
  static constexpr const char* kName = std::is_same_v<S, float> ? "hybrid_f" : "hybrid";
  // Row: σ_BN (3), ω_BN_B (3), γ (4), Ω_w (3), σ_d (3), σ̇_d (3), σ̈_d (3).
  static constexpr int kInputWidth = 22;
  static constexpr int kCommandSize = 7, kParts = 1;
  static constexpr double kPeriod = kHybridPeriod;
  // Comparison scales (replay_system.hpp, Column): per group of like outputs, a power of ten at
  // or below the smallest of their largest |value|s over the recorded run, so that the 1e-12
  // tolerance means 12 significant digits of the signal, not of a value passing through zero.
  // γ̇ 8.6e-4 .. 2.6e-3 rad/s, Ω̇_w 1.9e-6 .. 6.3e-6 rad/s², Θ̂_F 3.4e-6 .. 6.4e-6 N m s, Θ̂_cG:
  // Δt̂ part 1.0e-9 .. 2.7e-7, Δŝ part 1.2e-13 .. 1.9e-10, Θ̂_wG 4.4e-15 .. 1.3e-12 (the
  // deviation estimates are barely excited in 0.4 s).
  static constexpr double kUg = 1e-4, kUw = 1e-6, kThF = 1e-6, kThT = 1e-10, kThS = 1e-13, kThW = 1e-15;
  static constexpr Column kColumns[] = {
      {"status", 0.0}, {"safeguards", 0.0}, {"u_g1", kUg},   {"u_g2", kUg},   {"u_g3", kUg},
      {"u_g4", kUg},   {"u_w1", kUw},       {"u_w2", kUw},   {"u_w3", kUw},   {"thF1", kThF},
      {"thF2", kThF},  {"thF3", kThF},      {"thc11", kThT}, {"thc12", kThT}, {"thc13", kThT},
      {"thc14", kThS}, {"thc15", kThS},     {"thc16", kThS}, {"thc21", kThT}, {"thc22", kThT},
      {"thc23", kThT}, {"thc24", kThS},     {"thc25", kThS}, {"thc26", kThS}, {"thc31", kThT},
      {"thc32", kThT}, {"thc33", kThT},     {"thc34", kThS}, {"thc35", kThS}, {"thc36", kThS},
      {"thc41", kThT}, {"thc42", kThT},     {"thc43", kThT}, {"thc44", kThS}, {"thc45", kThS},
      {"thc46", kThS}, {"thw11", kThW},     {"thw12", kThW}, {"thw13", kThW}, {"thw21", kThW},
      {"thw22", kThW}, {"thw23", kThW},     {"thw31", kThW}, {"thw32", kThW}, {"thw33", kThW}};

  //! The A-REF law (replay_hybrid_params.hpp), its gains from the table designed on the host
  //! (checked by the constructor against Q_L, as an uploaded table would be).
  HybridSystem() noexcept : ctrl_(hybrid_params().template cast<S>(), hybrid_gains<S>()) {}
  adcs::Status init_status() const noexcept { return ctrl_.status(); }

  //! One sample. The double System (the Cortex-M7's, measured whole) fills a local Input, as it
  //! did before the float System existed, so its committed instruction counts stay comparable.
  void step(const double* row) noexcept {
    if constexpr (std::is_same_v<S, double>) {
      typename Controller::Input in;
      fill(row, in);
      status_ = ctrl_.step(in, cmd_);
    } else {
      step_stages(2, row);
    }
  }
  //! The first n stages of step() (the float System's cost mode): the row into the law's Input,
  //! then the law's step(). The Input is a member, so that neither stage alone is dead code.
  void step_stages(int n, const double* row) noexcept {
    fill(row, in_);
    if (n < 2) return;
    status_ = ctrl_.step(in_, cmd_);
  }
  void step_part(int, const double* row) noexcept { step(row); }
  //! u = [γ̇ (4); Ω̇_w (3)].
  void command(double* u) const noexcept {
    for (int i = 0; i < 4; ++i) u[i] = static_cast<double>(cmd_.gamma_dot_rad_s(i));
    for (int j = 0; j < 3; ++j) u[4 + j] = static_cast<double>(cmd_.Omega_dot_rad_s2(j));
  }

  //! The row into the law's Input, in S (reference ω_f, ω̇_f are not read by the law).
  static void fill(const double* row, typename Controller::Input& in) noexcept {
    in.state.sigma_BN = adcs::Vec3::Map(row).cast<S>();
    in.state.omega_BN_B = adcs::Vec3::Map(row + 3).cast<S>();
    in.actuators.gamma_rad = adcs::Vec<4>::Map(row + 6).cast<S>();
    in.actuators.Omega_rad_s = adcs::Vec3::Map(row + 10).cast<S>();
    in.reference.sigma = adcs::Vec3::Map(row + 13).cast<S>();
    in.reference.sigma_dot = adcs::Vec3::Map(row + 16).cast<S>();
    in.reference.sigma_ddot = adcs::Vec3::Map(row + 19).cast<S>();
  }

  void outputs(double* v) const noexcept {
    *v++ = static_cast<double>(status_);
    *v++ = static_cast<double>(ctrl_.safeguard_count());
    for (int i = 0; i < 4; ++i) *v++ = static_cast<double>(cmd_.gamma_dot_rad_s(i));
    for (int j = 0; j < 3; ++j) *v++ = static_cast<double>(cmd_.Omega_dot_rad_s2(j));
    for (int i = 0; i < 3; ++i) *v++ = static_cast<double>(ctrl_.theta_F()(i));
    for (int i = 0; i < 4; ++i)
      for (int k = 0; k < 6; ++k) *v++ = static_cast<double>(ctrl_.theta_cG(i)(k));
    for (int j = 0; j < 3; ++j)
      for (int k = 0; k < 3; ++k) *v++ = static_cast<double>(ctrl_.theta_wG(j)(k));
  }

 private:
  Controller ctrl_;
  typename Controller::Input in_{};
  typename Controller::Output cmd_{};  // γ̇, Ω̇_w
  adcs::Status status_ = adcs::Status::ok;
};

}  // namespace replay
