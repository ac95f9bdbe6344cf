#pragma once
// Step fixtures (bench/step_fixtures.hpp): seed 004's filters, fusion, ADRC and PID (one 0.1 s
// sample).
#include <cstdlib>

#include "adcs/control/adrc.hpp"
#include "adcs/control/pid.hpp"
#include "adcs/estimate/drag_free_eskf.hpp"
#include "adcs/estimate/fusion.hpp"
#include "adcs/estimate/saturated_esf.hpp"
#include "adcs/plant/drag_free.hpp"
#include "step_fixtures_common.hpp"

namespace adcs::bench {

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
    e1.period_s = p.period_s;  // h, the period A_d, B_d were discretised at
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
      e2[j].period_s = p.period_s;
    }
  }
};

//! Algorithm 1 (ESKF, two uncoupled blocks): step() = predict + update.
template <class Filter>
struct DragFreeEskfStepOf {
  DragFreeModel model;
  Filter f{model.e1};
  typename Filter::Input in = [] {
    typename Filter::Input i;  // u = 0, Δf̄ = 0
    i.y.setConstant(1e-8);
    return i;
  }();
  typename Filter::Output out;
  void operator()() noexcept {
    in.y(0) += 1e-12;
    escape(f.step(in, out));
    escape(out);
  }
};
//! The U-D form (DragFreeEskf) and the Joseph form it replaced, measured in the same run (issue 20).
using DragFreeEskfStep = DragFreeEskfStepOf<DragFreeEskf>;
using DragFreeEskfJosephStep = DragFreeEskfStepOf<DragFreeEskfJoseph>;

//! Algorithm 2 (saturated ESF, one axis): step() = predict + update, alternating in-range and
//! saturated readings.
struct SaturatedEsfStep {
  DragFreeModel model;
  SaturatedEsf f{model.e2[0]};
  SaturatedEsf::Input in;  // u_{k-1} = 0, Δf̄ = 0, u_k = 0
  SaturatedEsf::Output out;
  long k = 0;
  void operator()() noexcept {
    in.y_c_m_s2 = (++k & 1) ? 1e-7 : 6e-6;
    escape(f.step(in, out));
    escape(out);
  }
};

//! Algorithms 1-3 + ADRC: the whole 0.1 s sample of dragfree-adrc. The filters' two halves stay
//! apart (predict, control from the prediction, update with the new u), as the loop runs them.
struct DragFreeAdrcStep {
  DragFreeModel model;
  DragFreeEskf a1{model.e1};
  SaturatedEsf a2[3] = {SaturatedEsf(model.e2[0]), SaturatedEsf(model.e2[1]), SaturatedEsf(model.e2[2])};
  DragFreeAdrc ctrl{DragFreeAdrcParams{}};
  Vec<9> Y = Vec<9>::Constant(1e-8);
  DragFreeAdrcInput in;  // φ_cmd = 0
  DragFreeActuation u;   // [T_Csc; F_Csc; T_Ctm], zero before the first sample
  void operator()() noexcept {
    Y(0) += 1e-12;
    escape(a1.predict(u.stacked()));
    for (auto& f : a2) escape(f.predict(u.F_Csc_N(1)));
    escape(a1.update(Y));
    in.x_hat = a1.state();
    in.F_D_hat_N = Vec3(a2[0].state()(2), a2[1].state()(2), a2[2].state()(2));
    escape(ctrl.step(in, u));
    for (int j = 0; j < 3; ++j) {
      escape(a2[j].update(1e-7, u.F_Csc_N(j)));
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
  DragFreeAdrcInput in{Vec<27>::Constant(1e-9), Vec3(1e-6, -2e-6, 5e-7), Vec3::Zero()};
  DragFreeActuation u;
  void operator()() noexcept {
    in.x_hat(0) += 1e-15;
    escape(ctrl.step(in, u));
    escape(u);
  }
};

//! A 3-channel PID sample (the baseline of dragfree-pid).
struct PidStep {
  Pid<3> pid{params()};
  PidInput<3> in{Vec3(1e-6, -2e-6, 3e-7), Vec3(1e-8, 2e-8, -1e-8)};
  PidOutput<3> out;
  static PidParams<3> params() {
    PidParams<3> p;
    p.kp.setConstant(2.0);
    p.ki.setConstant(0.1);
    p.kd.setConstant(5.0);
    return p;
  }
  void operator()() noexcept {
    in.e_p(0) += 1e-15;
    escape(pid.step(in, out));
    escape(out);
    if (pid.integral()(0) > 1.0) pid.reset();
  }
};

}  // namespace adcs::bench
