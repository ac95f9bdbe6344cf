#pragma once
// Replay core of seed 004: one 0.1 s sample of the dragfree-adrc loop of
// src/scenarios/drag_free.cpp with its defaults, in its order (as BM_DragFreeAdrc_Step):
//   1. predictions with u_{k-1}: Algorithm 1 (DragFreeEskf) and the three Algorithm 2 filters
//      (SaturatedEsf, truncated update, accelerometer range +-6e-6 m/s²),
//   2. Algorithm 1 update with the position/attitude sensors Y (9),
//   3. ADRC (control/adrc.hpp) on Algorithm 1's posterior and Algorithm 2's predicted f̂,
//   4. Algorithm 2 updates with the (saturated) accelerometer readings y_c (3) and u_F,
//   5. Algorithm 3 fusion per axis (estimate/fusion.hpp).
// The accelerometer reading depends on this sample's command, so the recorder runs the sample in
// two halves (step_a: 1-3, step_b: 4-5); step() is both, and is what the replay and the cost
// measure. Cost stages (replay_system.hpp): predict (1), eskf_update (2), adrc_step (3),
// esf_update_fuse (4-5). Filter parameters as DragFreeConfig::eskf()/esf() of the scenario.
// The discrete model comes from the table designed on the host (replay_model_dragfree.hpp, written
// by design_dragfree_model.cpp), so no board compiles the 27-state matrix exponential.
// S = double is the Cortex-M7 System "dragfree", S = float the Cortex-M4F System "dragfree_f"
// (issue 19: as dragfree-adrc --set scalar=float, the parameters are the double ones rounded once,
// EskfParams/SaturatedEsfParams/DragFreeAdrcParams::cast, and each reading is converted to float
// where its stage reads it, as a sensor interface would hand it over; the conversions, library
// calls on the M4F, are counted in the stage that reads them).
#include <cmath>
#include <type_traits>

#include "adcs/control/adrc.hpp"
#include "adcs/estimate/fusion.hpp"
#include "adcs/plant/drag_free.hpp"
#include "replay_model_dragfree.hpp"  // generated in the build tree by design_dragfree_model
#include "replay_system.hpp"

namespace replay {

template <class S>
class DragFreeSystem {
 public:
  using Alg1 = adcs::DragFreeEskfT<S>;
  using Alg2 = adcs::SaturatedEsfT<S>;
  using Adrc = adcs::DragFreeAdrcT<S>;
  static constexpr const char* kName = std::is_same_v<S, float> ? "dragfree_f" : "dragfree";
  // Row: Y (9: φ_sc, r_rel, φ_rel sensors), y_c (3: saturated accelerometers), φ_cmd (3).
  static constexpr int kInputWidth = 15;
  static constexpr int kCommandSize = 9, kParts = 2;
  static constexpr int kCostStages = 4;
  static constexpr const char* kStageNames[kCostStages] = {"predict", "eskf_update", "adrc_step",
                                                           "esf_update_fuse"};
  static constexpr double kPeriod = 0.1;  // [s] h, DragFreeParams default (seed 004 §4)
  static_assert(kPeriod == kDragFreeModelPeriod, "the generated model is for another period");
  // Comparison scales (replay_system.hpp, Column): per group of like outputs, a power of ten at
  // or below the smallest of their largest |value|s over the recorded run, so that the 1e-12
  // tolerance means 12 significant digits of the signal, not of a value passing through zero.
  // Commands and disturbance estimates 6e-3 .. 8e-2 N (N m), T_Ctm and T̂_Dtm 2e-9 .. 2e-8 N m,
  // attitudes and positions 4e-6 .. 2e-4 rad (m), their rates 6.5e-7 .. 1.4e-5; the covariance
  // summaries (tr P¹ 0.16, P_ff 1e-8 .. 3.5e-3 at the start) get far smaller scales, as they
  // converge to ~1e-8 and ~1e-16.
  static constexpr double kT = 1e-3, kF = 1e-3, kTtm = 1e-9, kAng = 1e-6, kRate = 1e-7, kPos = 1e-6,
                          kDist = 1e-3, kP1 = 1e-8, kP2 = 1e-16;
  static constexpr Column kColumns[] = {
      {"st_predict", 0.0}, {"st_update", 0.0}, {"st_adrc", 0.0}, {"st_alg2", 0.0}, {"st_fuse", 0.0},
      {"T_sc1", kT}, {"T_sc2", kT}, {"T_sc3", kT}, {"F_sc1", kF}, {"F_sc2", kF}, {"F_sc3", kF},
      {"T_tm1", kTtm}, {"T_tm2", kTtm}, {"T_tm3", kTtm},
      // Algorithm 1 posterior after fusion (DragFreeIndex order)
      {"phi_sc1", kAng}, {"phi_sc2", kAng}, {"phi_sc3", kAng}, {"phid_sc1", kRate}, {"phid_sc2", kRate},
      {"phid_sc3", kRate}, {"T_Dsc1", kDist}, {"T_Dsc2", kDist}, {"T_Dsc3", kDist}, {"r1", kPos},
      {"r2", kPos}, {"r3", kPos}, {"rd1", kRate}, {"rd2", kRate}, {"rd3", kRate}, {"F_Dsc1", kDist},
      {"F_Dsc2", kDist}, {"F_Dsc3", kDist}, {"phi_rel1", kAng}, {"phi_rel2", kAng}, {"phi_rel3", kAng},
      {"phid_rel1", kRate}, {"phid_rel2", kRate}, {"phid_rel3", kRate}, {"T_Dtm1", kTtm},
      {"T_Dtm2", kTtm}, {"T_Dtm3", kTtm},
      // Algorithm 2 estimates [r, ṙ, f] per axis
      {"a2x_r", kPos}, {"a2x_rd", kRate}, {"a2x_f", kDist}, {"a2y_r", kPos}, {"a2y_rd", kRate},
      {"a2y_f", kDist}, {"a2z_r", kPos}, {"a2z_rd", kRate}, {"a2z_f", kDist},
      // filter confidence: trace of Algorithm 1's covariance, Algorithm 2's P(2,2) per axis
      {"trP1", kP1}, {"P2x_ff", kP2}, {"P2y_ff", kP2}, {"P2z_ff", kP2}};

  //! Everything the scenario derives from its defaults (make_config, eskf(), esf()), in double.
  struct Built {
    adcs::DragFreeParams plant{};
    adcs::DragFreeEskf::Params e1{};
    adcs::SaturatedEsfParams e2[3]{};
    adcs::DragFreeAdrcParams adrc{};
  };
  static Built build() noexcept {
    Built b;
    b.plant.period_s = kPeriod;
    const adcs::DragFreeParams& d = b.plant;
    adcs::DragFreeDiscrete model;
    adcs::DragFreeAxisModel axes[3];
    dragfree_model(model, axes);  // drag_free_discretize, drag_free_axis_model on the host
    const adcs::DragFreeNoise n = adcs::drag_free_noise(d);
    // q = (max|ḟ| h)² from the Table 2 disturbance (amplitude 7.7 mN, ω_d 1.2e-3 rad/s), spec §B.8
    const double qv = std::pow(7.7e-3 * 1.2e-3 * d.period_s, 2);
    b.e1.A_d = model.A_d;
    b.e1.B_d = model.B_d;
    b.e1.B_e = model.B_e;
    b.e1.C_d = model.C_d;
    b.e1.q << adcs::Vec3::Constant(qv), adcs::Vec3::Constant(qv), adcs::Vec3::Zero();
    adcs::Vec<9> s;
    s << adcs::Vec3::Constant(n.sigma_T_sc * n.sigma_T_sc), adcs::Vec3::Constant(n.sigma_F_sc * n.sigma_F_sc),
        adcs::Vec3::Constant(n.sigma_T_tm * n.sigma_T_tm);
    b.e1.S = s.asDiagonal();
    b.e1.R = (n.sigma_pos * n.sigma_pos) * adcs::Mat<9, 9>::Identity();
    b.e1.period_s = d.period_s;  // h of the discretisation
    for (int j = 0; j < 3; ++j) {
      const adcs::DragFreeAxisModel& m = axes[j];
      adcs::SaturatedEsfParams& e = b.e2[j];
      e.A_d = m.A_d;
      e.B_d = m.B_d;
      e.B_e = m.B_e;
      e.C = m.C;
      e.D = m.D;
      e.q = qv;
      e.S = n.sigma_F_sc * n.sigma_F_sc;
      e.R_a = n.sigma_acc * n.sigma_acc;
      e.y_min = d.accel_min;
      e.y_max = d.accel_max;
      e.period_s = d.period_s;
    }
    b.adrc.plant = d;  // gains, limit 0.03, scaled-sum integral: the DragFreeAdrcParams defaults
    return b;
  }

  DragFreeSystem() noexcept : DragFreeSystem(build()) {}
  explicit DragFreeSystem(const Built& b) noexcept
      : alg1_(in_scalar(b.e1)),
        alg2_{Alg2(in_scalar(b.e2[0])), Alg2(in_scalar(b.e2[1])), Alg2(in_scalar(b.e2[2]))},
        adrc_(in_scalar(b.adrc)) {}

  adcs::Status init_status() const noexcept {
    adcs::Status s = alg1_.status();
    for (const Alg2& f : alg2_) s = adcs::worst(s, f.status());
    return adcs::worst(s, adrc_.status());
  }

  //! The first n cost stages (kStageNames) of step(), in its order. noinline: every cost prefix
  //! (step_prefix_on<S, n>) and the whole step then run this same code, so stage boundaries are
  //! exact rather than shifted by each wrapper's own inlining.
  __attribute__((noinline)) void step_stages(int n, const double* row) noexcept {
    predict();
    if (n < 2) return;
    eskf_update(row);
    if (n < 3) return;
    adrc_step(row);
    if (n < 4) return;
    esf_update_fuse(row);
  }
  //! Steps 1-3 (uses row[0..8] and row[12..14]): cost stages 1-3.
  void step_a(const double* row) noexcept { step_stages(3, row); }
  //! Steps 4-5 (uses row[9..11]): cost stage 4 alone, after step_a.
  void step_b(const double* row) noexcept { esf_update_fuse(row); }
  void step(const double* row) noexcept { step_stages(kCostStages, row); }
  void step_part(int part, const double* row) noexcept {
    if (part == 0)
      step_a(row);
    else
      step_b(row);
  }
  //! The command u = [T_Csc; F_Csc; T_Ctm] of the last step_a().
  void command(double* u) const noexcept {
    for (int i = 0; i < 9; ++i) u[i] = static_cast<double>(u_(i));
  }

  void outputs(double* v) const noexcept {
    *v++ = static_cast<double>(st_predict_);
    *v++ = static_cast<double>(st_update_);
    *v++ = static_cast<double>(st_adrc_);
    *v++ = static_cast<double>(st_alg2_);
    *v++ = static_cast<double>(st_fuse_);
    for (int i = 0; i < 9; ++i) *v++ = static_cast<double>(u_(i));
    for (int i = 0; i < 27; ++i) *v++ = static_cast<double>(alg1_.state()(i));
    for (const Alg2& f : alg2_)
      for (int i = 0; i < 3; ++i) *v++ = static_cast<double>(f.state()(i));
    *v++ = static_cast<double>(alg1_.covariance().trace());
    for (const Alg2& f : alg2_) *v++ = static_cast<double>(f.covariance()(2, 2));
  }

 private:
  //! The double parameters in S: themselves for the double System (constructed as before the
  //! float one existed), rounded once (cast) for the float one.
  template <class P>
  static decltype(auto) in_scalar(const P& p) noexcept {
    if constexpr (std::is_same_v<S, double>)
      return (p);
    else
      return p.template cast<S>();
  }
  //! Stage 1 (step 1): the predictions with u_{k-1}.
  void predict() noexcept {
    st_predict_ = adcs::Status::ok;
    if (started_) {
      st_predict_ = alg1_.predict(u_);  // u_ still holds u_{k-1}
      for (int j = 0; j < 3; ++j) st_predict_ = adcs::worst(st_predict_, alg2_[j].predict(u_(3 + j)));
    }
    started_ = true;
  }
  //! Stage 2 (step 2): Algorithm 1 update with Y = row[0..8].
  void eskf_update(const double* row) noexcept {
    st_update_ = alg1_.update(adcs::Vec<9>::Map(row).template cast<S>());
  }
  //! Stage 3 (step 3): ADRC with φ_cmd = row[12..14].
  void adrc_step(const double* row) noexcept {
    const adcs::DragFreeAdrcInputT<S> in{alg1_.state(),
                                         adcs::Vec<3, S>(alg2_[0].state()(2), alg2_[1].state()(2), alg2_[2].state()(2)),
                                         adcs::Vec3::Map(row + 12).template cast<S>()};
    adcs::DragFreeActuationT<S> act;
    st_adrc_ = adrc_.step(in, act);
    u_ = act.stacked();  // [T_Csc; F_Csc; T_Ctm]
  }
  //! Stage 4 (steps 4-5): Algorithm 2 updates with y_c = row[9..11], fusion.
  void esf_update_fuse(const double* row) noexcept {
    st_alg2_ = adcs::Status::ok;
    st_fuse_ = adcs::Status::ok;
    for (int j = 0; j < 3; ++j) {
      st_alg2_ = adcs::worst(st_alg2_, alg2_[j].update(static_cast<S>(row[9 + j]), u_(3 + j)));
      st_fuse_ = adcs::worst(st_fuse_, adcs::fuse_axis(alg1_, alg2_[j], j));
    }
  }

  Alg1 alg1_;
  Alg2 alg2_[3];
  Adrc adrc_;
  adcs::Vec<9, S> u_ = adcs::Vec<9, S>::Zero();
  bool started_ = false;
  adcs::Status st_predict_ = adcs::Status::ok, st_update_ = adcs::Status::ok, st_adrc_ = adcs::Status::ok,
               st_alg2_ = adcs::Status::ok, st_fuse_ = adcs::Status::ok;
};

}  // namespace replay
