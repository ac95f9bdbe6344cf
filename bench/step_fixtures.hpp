#pragma once
// One fixture per controller/estimator step measured by adcs-bench (Google Benchmark, wall time)
// and by adcs-stepcount (valgrind callgrind, instructions): the constructor builds the object
// once, operator() runs exactly one step with inputs that move every call, so nothing is
// constant-folded and both tools time the same code. Fixtures own no heap memory in operator().
#include <cmath>
#include <cstdlib>

#include "adcs/adcs.hpp"

namespace adcs::bench {

//! Keeps a value alive without a memory round trip (what benchmark::DoNotOptimize does).
template <class T>
inline void escape(const T& v) noexcept {
  asm volatile("" : : "g"(&v) : "memory");
}

inline Mat<3, 4> four_wheel_axes() {
  Mat<3, 4> G;
  const double s = 1.0 / std::sqrt(3.0);
  G << 1, 0, 0, s, 0, 1, 0, s, 0, 0, 1, s;
  return G;
}

// ------------------------------------------------------------------ rigid body + wheels
//! MrpPd::step() (the controller of rigid-rw-mrp-pd).
struct MrpPdStep {
  MrpPd<4> ctrl{params()};
  MrpPd<4>::Measurement m;
  AttitudeReference r;
  MrpPdCommand out;
  double k = 0.0;
  static MrpPdParams<4> params() {
    MrpPdParams<4> p;
    p.K = 1.44;
    p.P = Vec3(36, 32, 28).asDiagonal();
    p.J_rw_B = Vec3(900, 800, 600).asDiagonal();
    p.G_s_B = four_wheel_axes();
    p.J_s.setConstant(0.05);
    return p;
  }
  MrpPdStep() {
    m.sigma_BN << 0.1, -0.2, 0.3;
    m.omega_BN_B << 0.01, 0.002, -0.003;
    m.Omega << 10, 20, 30, 40;
    r.sigma_RN << 0.1, 0.2, -0.3;
  }
  void operator()() noexcept {
    m.sigma_BN(0) = 0.1 + 1e-9 * k;
    k += 1.0;
    escape(ctrl.step(m, r, out));
    escape(out.L_r_B);
  }
};

//! RwTorqueAllocator::allocate() (precomputed pseudo-inverse + scaling).
struct RwAllocationStep {
  RwTorqueAllocator<4> alloc{params()};
  Vec3 L{0.05, -0.3, 0.1};
  Vec<4> us;
  static RwAllocationParams<4> params() {
    RwAllocationParams<4> p;
    p.G_s_B = four_wheel_axes();
    return p;
  }
  void operator()() noexcept {
    L(0) += 1e-12;
    escape(alloc.allocate(L, us));
    escape(us);
  }
};

// ------------------------------------------------------------------ seed 001
//! HybridAdaptive::step() (M = 4 CMGs, N = 3 wheels): regressors, steering via LDLT of X Xᵀ,
//! adaptation with projection. Estimates reset every 4096 steps to stay near nominal.
struct HybridAdaptiveStep {
  HybridAdaptive<4, 3> ctrl;
  HybridAdaptive<4, 3>::Measurement m;
  MrpReferenceSample r = SinusoidalRateReference{}.sample(123.0, Vec3(0.29, -0.21, 0.1));
  HybridAdaptive<4, 3>::Command out;
  double k = 0.0;
  static HybridAdaptive<4, 3>::Params params(AdaptationStep a) {
    HybridAdaptive<4, 3>::Params p;
    p.nominal = pyramid_4cmg_3rw_nominal();
    p.adaptation_step = a;
    return p;
  }
  explicit HybridAdaptiveStep(AdaptationStep a = AdaptationStep::explicit_euler) : ctrl(params(a)) {
    m.sigma_BN << 0.3, -0.2, 0.1;
    m.omega_BN_B << 0.01, -0.02, 0.015;
    m.gamma << 0.1, -0.2, 0.15, 0.05;
  }
  void operator()() noexcept {
    m.gamma(0) = 0.1 + 1e-9 * k;
    k += 1.0;
    escape(ctrl.step(m, r, out));
    escape(out.u);
    if (static_cast<long>(k) % 4096 == 0) ctrl.reset();
  }
};
struct HybridAdaptiveNormalizedStep : HybridAdaptiveStep {
  HybridAdaptiveNormalizedStep() : HybridAdaptiveStep(AdaptationStep::normalized) {}
};

// ------------------------------------------------------------------ seed 002
//! One Euler-angle law step (PPATC or ATC) near the scenario's initial state, time and angles
//! moving: kinematics, (funnel transform,) RBF layer, adaptation.
template <class Law>
struct EulerTrackingStep {
  Law law;
  SinusoidalEulerReference ref;
  typename Law::Measurement m;
  typename Law::Command out;
  double k = 0.0;
  explicit EulerTrackingStep(const typename Law::Params& p) : law(p) {
    m.angles = Vec3(0.25, 0.15, -0.20) * (3.14159265358979 / 180.0);
    m.omega_BN_B = Vec3(2e-4, 1e-4, -3e-4);
  }
  void operator()() noexcept {
    m.t = 1e-9 * k;
    m.angles(0) += 1e-15;
    k += 1.0;
    escape(law.step(m, ref.sample(m.t), out));
    escape(out.torque_B);
    if (static_cast<long>(k) % 4096 == 0) law.reset();
  }
};
struct FlexiblePPCStep : EulerTrackingStep<PpcNeural> {
  FlexiblePPCStep() : EulerTrackingStep({seed002_tracking_gains(), seed002_performance()}) {}
};
struct AdaptiveTrackingStep : EulerTrackingStep<AdaptiveTracking> {
  AdaptiveTrackingStep() : EulerTrackingStep({seed002_tracking_gains()}) {}
};

// ------------------------------------------------------------------ seed 004 (one 0.1 s sample)
//! The drag-free filters' parameters, built from the model once.
struct DragFreeModel {
  DragFreeParams p;
  DragFreeDiscrete d;
  DragFreeEskf::Params e1;
  SaturatedEsfParams e2[3];
  DragFreeModel() {
    if (drag_free_discretize(p, d) != Status::ok) std::abort();
    const DragFreeNoise n = drag_free_noise(p);
    e1.A_d = d.A_d;
    e1.B_d = d.B_d;
    e1.B_e = d.B_e;
    e1.C_d = d.C_d;
    e1.q.head<6>().setConstant(8.538e-13);
    e1.S = (n.sigma_F_sc * n.sigma_F_sc) * Mat<9, 9>::Identity();
    e1.R = (n.sigma_pos * n.sigma_pos) * Mat<9, 9>::Identity();
    for (int j = 0; j < 3; ++j) {
      DragFreeAxisModel m;
      if (drag_free_axis_model(p, j, m) != Status::ok) std::abort();
      e2[j].A_d = m.A_d;
      e2[j].B_d = m.B_d;
      e2[j].C = m.C;
      e2[j].D = m.D;
      e2[j].q = 8.538e-13;
      e2[j].S = n.sigma_F_sc * n.sigma_F_sc;
      e2[j].R_a = n.sigma_acc * n.sigma_acc;
      e2[j].y_min = p.accel_min;
      e2[j].y_max = p.accel_max;
    }
  }
};

//! Algorithm 1 (ESKF, two uncoupled blocks): predict + update.
struct DragFreeEskfStep {
  DragFreeModel model;
  DragFreeEskf f{model.e1};
  Vec<9> Y = Vec<9>::Constant(1e-8), u = Vec<9>::Zero();
  void operator()() noexcept {
    Y(0) += 1e-12;
    escape(f.predict(u));
    escape(f.update(Y));
  }
};

//! Algorithm 2 (saturated ESF, one axis): predict + update, alternating in-range and saturated.
struct SaturatedEsfStep {
  DragFreeModel model;
  SaturatedEsf f{model.e2[0]};
  long k = 0;
  void operator()() noexcept {
    escape(f.predict(0.0));
    escape(f.update((++k & 1) ? 1e-7 : 6e-6, 0.0));
  }
};

//! Algorithms 1-3 + ADRC: the whole 0.1 s sample of dragfree-adrc.
struct DragFreeAdrcStep {
  DragFreeModel model;
  DragFreeEskf a1{model.e1};
  SaturatedEsf a2[3] = {SaturatedEsf(model.e2[0]), SaturatedEsf(model.e2[1]), SaturatedEsf(model.e2[2])};
  DragFreeAdrc ctrl{DragFreeAdrcParams{}};
  Vec<9> Y = Vec<9>::Constant(1e-8), u = Vec<9>::Zero();
  void operator()() noexcept {
    Y(0) += 1e-12;
    escape(a1.predict(u));
    for (auto& f : a2) escape(f.predict(u(4)));
    escape(a1.update(Y));
    const Vec3 F(a2[0].state()(2), a2[1].state()(2), a2[2].state()(2));
    escape(ctrl.step(a1.state(), F, Vec3::Zero(), u));
    for (int j = 0; j < 3; ++j) {
      escape(a2[j].update(1e-7, u(3 + j)));
      escape(fuse_axis(a1, a2[j], j));
    }
  }
};

//! Algorithm 3 alone, one axis (both filters leave with the fused estimate).
struct FusionStep {
  DragFreeAdrcStep sample;  // filters in a realistic state after one sample
  int axis = 0;
  FusionStep() { sample(); }
  void operator()() noexcept {
    escape(fuse_axis(sample.a1, sample.a2[axis], axis));
    axis = axis == 2 ? 0 : axis + 1;
  }
};

//! The ADRC law alone (PID + disturbance compensation, 9 channels) on a moving estimate.
struct AdrcStep {
  DragFreeAdrc ctrl{DragFreeAdrcParams{}};
  Vec<27> x_hat = Vec<27>::Constant(1e-9);
  Vec3 F{1e-6, -2e-6, 5e-7};
  Vec<9> u;
  void operator()() noexcept {
    x_hat(0) += 1e-15;
    escape(ctrl.step(x_hat, F, Vec3::Zero(), u));
    escape(u);
  }
};

//! A 3-channel PID sample (the baseline of dragfree-pid).
struct PidStep {
  Pid<3> pid{params()};
  Vec3 e_p{1e-6, -2e-6, 3e-7}, e_d{1e-8, 2e-8, -1e-8}, out;
  static PidParams<3> params() {
    PidParams<3> p;
    p.kp.setConstant(2.0);
    p.ki.setConstant(0.1);
    p.kd.setConstant(5.0);
    return p;
  }
  void operator()() noexcept {
    e_p(0) += 1e-15;
    escape(pid.step(e_p, e_d, out));
    escape(out);
    if (pid.integral()(0) > 1.0) pid.reset();
  }
};

// ------------------------------------------------------------------ seed 003 (one 8 Hz command)
//! Chaser and target of the paper's state 1; each step computes the desired state from the target
//! model, then the law (tracking error, G, G⁻¹, Ġξ_e, F0, the target's ξ̇_o feed-forward).
template <class Law>
struct Se3Step {
  Se3ScenarioParams sp;
  Se3Spacecraft target_model{se3_target_params(sp)};
  Se3SpacecraftState target, chaser;
  Law law;
  Vec6 u;
  explicit Se3Step(const typename Law::Params& p) : law(p, se3_chaser_nominal_params(sp)) {
    if (se3_target_initial_state(sp, target) != Status::ok) std::abort();
    chaser = se3_chaser_initial_state(target, kSe3InitialPoses[0]);
  }
  void operator()() noexcept {
    chaser.R_N(0) += 1e-9;
    Se3DesiredState d;
    escape(se3_desired_state(target_model, target, sp, d));
    escape(law.step(chaser, d, u));
    escape(u);
  }
};
struct SE3PrescribedTimeStep : Se3Step<PrescribedTimeSe3> {
  SE3PrescribedTimeStep() : Se3Step(PrescribedTimeSe3Params{}) {}
};
struct SE3FtsmcStep : Se3Step<FtsmcSe3> {
  SE3FtsmcStep() : Se3Step(FtsmcSe3Params{}) {}
};

//! sat → composite quantizer on the six SE(3) channels (seed 003 Table 1 parameters).
struct CompositeQuantizerStep {
  CompositeQuantizer<6> q{seed003_quantizer_params()};
  Vec6 u = (Vec6() << 0.3, -0.01, 0.002, 4.0, -0.5, 0.03).finished(), u_c;
  Vec6 limit = (Vec6() << 0.5, 0.5, 0.5, 5.0, 5.0, 5.0).finished();
  double k = 0.0;
  void operator()() noexcept {
    u(0) = 0.3 * std::sin(1e-3 * k);
    k += 1.0;
    escape(saturate_then_quantize<6>(u, limit, q, u_c));
    escape(u_c);
  }
};

}  // namespace adcs::bench
