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

}  // namespace adcs::bench
