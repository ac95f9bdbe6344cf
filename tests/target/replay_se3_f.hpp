#pragma once
// Replay core of seed 003 in float (issue 19, the Cortex-M4F Systems "se3_f" and "se3_ftsmc_f"):
// one 8 Hz tick of the BsPdTC law, PrescribedTimeSe3T<float>, with the spec Table 1 gains rounded
// to float, as `se3-ptc --set scalar=float` flies it, or of the FTSMC baseline, FtsmcSe3T<float>
// with the spec Table 2 gains, as `se3-ftsmc --set scalar=float`. What the float law computes is the law alone: the
// desired state (the target's model, J2 gravity) and sat -> Q (the actuator) stay with the
// double ground code in that scenario, so here the recorder computes them on the host
// (record_inputs se3_f) and the row carries the chaser state and the desired state; the System
// rounds the row to float (stage "inputs", the replay's conversion, not flight code) and steps
// the law (stage "controller_step").
#include "adcs/control/ftsmc_se3.hpp"
#include "adcs/control/prescribed_time_se3.hpp"
#include "replay_se3.hpp"
#include "replay_system.hpp"

namespace replay {

//! What differs between the two float SE(3) laws: name, parameters (double, rounded once by the
//! System) and the outputs beyond the command. Comparison scales as the double System's
//! (replay_se3.hpp): M 0.27 .. 2.6 N m, F 52 .. 102 N, ψ̂ 3.2e-4; the FTSMC's sliding variable s
//! is compared relative to 1e-6 (rad/s | m/s; its entries start at 8e-4 .. 1.7 and the rotational
//! ones reach ~1e-5 by tick 200).
template <class Law>
struct Se3FloatLaw;
template <>
struct Se3FloatLaw<adcs::PrescribedTimeSe3T<float>> {
  static constexpr const char* kName = "se3_f";
  static adcs::PrescribedTimeSe3Params params() noexcept { return Se3System::params(Se3System::scenario_params()); }
  static constexpr double kM = Se3System::kM, kF = Se3System::kF, kPsi = Se3System::kPsi;
  static constexpr Column kColumns[] = {{"status_law", 0.0}, {"M1", kM}, {"M2", kM}, {"M3", kM}, {"F1", kF},
                                        {"F2", kF},          {"F3", kF}, {"psi_hat", kPsi}};
  static void extra(const adcs::PrescribedTimeSe3T<float>& law, double* v) noexcept {
    *v = static_cast<double>(law.psi_hat());
  }
};
template <>
struct Se3FloatLaw<adcs::FtsmcSe3T<float>> {
  static constexpr const char* kName = "se3_ftsmc_f";
  static adcs::FtsmcSe3Params params() noexcept {
    adcs::FtsmcSe3Params p;  // spec Table 2, the se3-ftsmc defaults
    p.period_s = Se3System::kPeriod;
    p.nominal = adcs::se3_chaser_nominal_params(Se3System::scenario_params());
    return p;
  }
  static constexpr double kM = Se3System::kM, kF = Se3System::kF, kS = 1e-6;
  static constexpr Column kColumns[] = {{"status_law", 0.0}, {"M1", kM}, {"M2", kM}, {"M3", kM}, {"F1", kF},
                                        {"F2", kF},          {"F3", kF}, {"s1", kS},  {"s2", kS}, {"s3", kS},
                                        {"s4", kS},          {"s5", kS}, {"s6", kS}};
  static void extra(const adcs::FtsmcSe3T<float>& law, double* v) noexcept {
    for (int i = 0; i < 6; ++i) v[i] = static_cast<double>(law.sliding_variable()(i));
  }
};

template <class Law>
class Se3FloatSystem {
 public:
  using Controller = Law;
  using Traits = Se3FloatLaw<Law>;
  static constexpr const char* kName = Traits::kName;
  // Row: chaser C_NB (9, column-major), R_N (3), ω (3), v_B (3); desired C_ND (9), R_N (3), ω_d
  // (3), v_d (3), ω̇_d (3), v̇_d (3).
  static constexpr int kInputWidth = 42;
  static constexpr int kCommandSize = 6, kParts = 1;
  static constexpr int kCostStages = 2;
  static constexpr const char* kStageNames[kCostStages] = {"inputs", "controller_step"};
  static constexpr double kPeriod = Se3System::kPeriod;
  static constexpr auto& kColumns = Traits::kColumns;

  Se3FloatSystem() noexcept : law_(Traits::params().template cast<float>()) {}
  adcs::Status init_status() const noexcept { return law_.status(); }

  void step(const double* row) noexcept { step_stages(kCostStages, row); }
  //! The first n stages of step() (cost mode). The Input is a member, so that the first stage
  //! alone is not dead code.
  void step_stages(int n, const double* row) noexcept {
    fill(row, in_);
    if (n < 2) return;
    adcs::WrenchT<float> w;
    status_law_ = law_.step(in_, w);
    u_ = w.stacked();
  }
  void step_part(int, const double* row) noexcept { step(row); }
  //! The law's raw command [M; F] (the recorder saturates and quantizes it on the host).
  void command(double* u) const noexcept {
    for (int i = 0; i < 6; ++i) u[i] = static_cast<double>(u_(i));
  }
  void outputs(double* v) const noexcept {
    *v++ = static_cast<double>(status_law_);
    for (int i = 0; i < 6; ++i) *v++ = static_cast<double>(u_(i));
    Traits::extra(law_, v);
  }

  //! The row into the law's Input, rounded to float.
  static void fill(const double* row, typename Controller::Input& in) noexcept {
    in.state.C_NB = adcs::Mat3::Map(row).cast<float>();
    in.state.R_N = adcs::Vec3::Map(row + 9).cast<float>();
    in.state.omega_BN_B = adcs::Vec3::Map(row + 12).cast<float>();
    in.state.v_B = adcs::Vec3::Map(row + 15).cast<float>();
    in.desired.C_ND = adcs::Mat3::Map(row + 18).cast<float>();
    in.desired.R_N = adcs::Vec3::Map(row + 27).cast<float>();
    in.desired.omega_DN_D = adcs::Vec3::Map(row + 30).cast<float>();
    in.desired.v_D = adcs::Vec3::Map(row + 33).cast<float>();
    in.desired.omega_dot_D = adcs::Vec3::Map(row + 36).cast<float>();
    in.desired.v_dot_D = adcs::Vec3::Map(row + 39).cast<float>();
  }

 private:
  Controller law_;
  typename Controller::Input in_{};
  adcs::Vec<6, float> u_ = adcs::Vec<6, float>::Zero();
  adcs::Status status_law_ = adcs::Status::ok;
};

}  // namespace replay
