// libFuzzer harness, seed 001: HybridAdaptive<4, 3> (with its pseudo-inverse steering), the
// steering call on its own, and MrpPd<4>. Input format: fuzz_common.hpp; first byte = target.
//
// Asserted on every step (besides "no crash, no sanitizer report"):
//  - the command is finite, whatever the status;
//  - a non-finite input gives exactly non_finite_input;
//  - a status that is not usable() ("nothing applied") outputs the failure command (zero, or the
//    last applied one under hold_last) and leaves every estimate / counter bitwise unchanged;
//  - an applied step keeps the estimates finite and each Θ̂_G block inside its invariant ball
//    ‖Θ̂_Gk‖² ≤ β + δ, and counts a safeguard event exactly when it returns constraint_violated;
//  - MrpPd: an applied step's diagnostics (σ_BR, ω_BR) are finite; RwTorqueAllocator: a usable
//    status gives finite wheel torques within the limit (scale in (0, 1]), any other zero torques.
#include <cmath>
#include <cstdint>

#include "adcs/actuator/rw_allocation.hpp"
#include "adcs/actuator/steering.hpp"
#include "adcs/control/hybrid_adaptive.hpp"
#include "adcs/control/mrp_pd.hpp"
#include "adcs/core/signals.hpp"
#include "adcs/plant/vscmg_configurations.hpp"
#include "fuzz_common.hpp"

// File-local, and named: the five harnesses are compiled in one unit (tests/fuzz/CMakeLists.txt).
namespace ADCS_UNITY_ID {
using adcs::Status;
using adcs::Vec3;
using Hybrid = adcs::HybridAdaptive<4, 3>;
using Pd = adcs::MrpPd<4>;
constexpr int kMaxSteps = 12;

// Four prototypes: {explicit Euler, normalized} x {T_c = 1 ms (paper), 0.1 s (safeguard active)}.
const Hybrid& hybrid_proto(int variant) {
  static const Hybrid protos[4] = {
      Hybrid([] { Hybrid::Params p; p.nominal = adcs::pyramid_4cmg_3rw_nominal(); return p; }()),
      Hybrid([] {
        Hybrid::Params p;
        p.nominal = adcs::pyramid_4cmg_3rw_nominal();
        p.adaptation_step = adcs::AdaptationStep::normalized;
        p.on_failure = adcs::FailurePolicy::hold_last;  // both failure policies get fuzzed
        return p;
      }()),
      Hybrid([] {
        Hybrid::Params p;
        p.nominal = adcs::pyramid_4cmg_3rw_nominal();
        p.period_s = 0.1;
        return p;
      }()),
      Hybrid([] {
        Hybrid::Params p;
        p.nominal = adcs::pyramid_4cmg_3rw_nominal();
        p.adaptation_step = adcs::AdaptationStep::normalized;
        p.period_s = 0.1;
        p.on_failure = adcs::FailurePolicy::hold_last;
        return p;
      }()),
  };
  return protos[variant & 3];
}

struct HybridSnapshot {
  Vec3 theta_F;
  adcs::Mat<6, 4> theta_c;
  adcs::Mat<3, 3> theta_w;
  std::uint32_t safeguards;
  explicit HybridSnapshot(const Hybrid& c) : theta_F(c.theta_F()), safeguards(c.safeguard_count()) {
    for (int i = 0; i < 4; ++i) theta_c.col(i) = c.theta_cG(i);
    for (int j = 0; j < 3; ++j) theta_w.col(j) = c.theta_wG(j);
  }
  bool operator==(const HybridSnapshot& o) const {
    return fuzz::same_bits_mat(theta_F, o.theta_F) && fuzz::same_bits_mat(theta_c, o.theta_c) &&
           fuzz::same_bits_mat(theta_w, o.theta_w) && safeguards == o.safeguards;
  }
};

void fuzz_hybrid(fuzz::Reader& r) {
  const int config = r.u8();
  Hybrid ctrl = hybrid_proto(config);
  const double bound = ctrl.params().beta_G + ctrl.params().delta_G;
  if (config & 4) {  // warm start from fuzzed estimates: reaches the projection and the safeguard
    const Vec3 tF = r.vec<3>();
    adcs::Mat<6, 4> tc;
    adcs::Mat<3, 3> tw;
    for (int i = 0; i < 4; ++i) tc.col(i) = r.vec<6>();
    for (int j = 0; j < 3; ++j) tw.col(j) = r.vec<3>();
    const HybridSnapshot before(ctrl);
    const Status s = ctrl.set_estimates(tF, tc, tw);
    if (!fuzz::finite(tF) || !fuzz::finite(tc) || !fuzz::finite(tw))
      FUZZ_CHECK(s == Status::non_finite_input, "HybridAdaptive::set_estimates: non-finite accepted");
    if (s != Status::ok) FUZZ_CHECK(HybridSnapshot(ctrl) == before, "set_estimates: rejected but changed");
  }
  adcs::Vec<Hybrid::L> last = adcs::Vec<Hybrid::L>::Zero();  // the held command [γ̇; Ω̇_w] (zero after construction)
  Hybrid::Diagnostics diag;
  for (int k = 0; k < kMaxSteps && !r.empty(); ++k) {
    if (config & 16) {  // FDIR: a fuzzed actuator mask (bits beyond M+N must be refused)
      const adcs::ActuatorMask mask = r.u8() | (r.u8() & 1u ? 0x80u : 0u);
      const adcs::ActuatorMask old_mask = ctrl.available();
      const Status sm = ctrl.set_available(mask);
      if (mask & ~adcs::all_actuators<Hybrid::L>()) {
        FUZZ_CHECK(sm == Status::out_of_range && ctrl.available() == old_mask,
                   "HybridAdaptive::set_available: accepted a bit beyond M+N");
      } else {
        FUZZ_CHECK(sm == Status::ok && ctrl.available() == mask, "HybridAdaptive::set_available: refused");
        for (int i = 0; i < Hybrid::L; ++i)  // documented: the held command drops failed actuators
          if (!((mask >> i) & 1u)) last(i) = 0.0;
      }
    }
    Hybrid::Input in;
    in.state.sigma_BN = Vec3(0.01, -0.02, 0.03) + r.vec<3>();
    in.state.omega_BN_B = Vec3(1e-3, 2e-3, -1e-3) + r.vec<3>();
    in.actuators.gamma_rad = r.vec<4>();
    in.actuators.Omega_rad_s = r.vec<3>();
    adcs::MrpReferenceSample& ref = in.reference;
    ref.sigma = r.vec<3>();
    ref.sigma_dot = r.vec<3>();
    ref.sigma_ddot = r.vec<3>();
    const bool finite_in = fuzz::finite(in.state.sigma_BN) && fuzz::finite(in.state.omega_BN_B) &&
                           fuzz::finite(in.actuators.gamma_rad) && fuzz::finite(in.actuators.Omega_rad_s) &&
                           fuzz::finite(ref.sigma) && fuzz::finite(ref.sigma_dot) && fuzz::finite(ref.sigma_ddot);
    const HybridSnapshot before(ctrl);
    Hybrid::Output cmd;
    cmd.gamma_dot_rad_s.setConstant(fuzz::kNaN);  // must be overwritten
    cmd.Omega_dot_rad_s2.setConstant(fuzz::kNaN);
    const Status s = ctrl.step(in, cmd, (config & 8) ? &diag : nullptr);
    fuzz::stat(0, "HybridAdaptive", s);
    const adcs::Vec<Hybrid::L> out = cmd.stacked();  // [γ̇; Ω̇_w]
    FUZZ_CHECK(fuzz::finite(out), "HybridAdaptive: non-finite command");
    fuzz::check_status_vs_input(s, finite_in, "HybridAdaptive: non-finite input not rejected");
    const HybridSnapshot after(ctrl);
    if (!fuzz::applied(s)) {
      FUZZ_CHECK(after == before, "HybridAdaptive: rejected step changed the estimates");
      FUZZ_CHECK(fuzz::is_failure_command(ctrl.params().on_failure, out, last),
                 "HybridAdaptive: rejected step did not output the failure command");
      continue;
    }
    last = out;
    for (int i = 0; i < Hybrid::L; ++i)
      if (!((ctrl.available() >> i) & 1u)) FUZZ_CHECK(out(i) == 0.0, "HybridAdaptive: failed actuator commanded");
    FUZZ_CHECK(fuzz::finite(after.theta_F) && fuzz::finite(after.theta_c) && fuzz::finite(after.theta_w),
               "HybridAdaptive: non-finite estimate committed");
    const double tol = bound * (1.0 + 1e-12);
    FUZZ_CHECK((after.theta_c.colwise().squaredNorm().array() <= tol).all() &&
                   (after.theta_w.colwise().squaredNorm().array() <= tol).all(),
               "HybridAdaptive: an estimate left the invariant ball");
    FUZZ_CHECK(after.safeguards == before.safeguards + (s == Status::constraint_violated ? 1u : 0u),
               "HybridAdaptive: safeguard count does not match constraint_violated");
  }
}

// The graded statuses of a written steering command agree with the torque error it reports.
void check_torque_error(const adcs::SteeringInfo& info, double bound, Status s) {
  if (s == Status::request_not_met) {
    FUZZ_CHECK(!(info.torque_error <= bound), "steering: request_not_met with the torque error within its bound");
  } else {
    FUZZ_CHECK(info.torque_error <= bound, "steering: usable status with the torque error beyond its bound");
  }
}

// steer_escape<7> on the same X and v, at the sample time k * 0.1 s (no extra input bytes, so
// the committed corpus keeps its meaning): a written command is finite and within the bound
// ‖u‖ ≤ ‖v‖ / (s √(λ (1 − 2ε0))); request_not_met only beyond max_torque_error; anything else
// leaves u untouched.
void fuzz_escape_steering(const adcs::Mat<3, 7>& X, const Vec3& v, int config, int k) {
  static const adcs::EscapeSteeringParams kEscape[4] = {
      {}, {1.0, 0.0, 0.0}, {1e-6, 100.0, 0.49}, {0.01, 10.0, 0.01, 1e3}};
  const adcs::EscapeSteeringParams& p = kEscape[(config >> 3) & 3];
  adcs::Vec<7> u = adcs::Vec<7>::Constant(-7.0);
  const adcs::Vec<7> u0 = u;
  adcs::SteeringInfo info;
  const Status s = adcs::steer_escape<7>(X, v, p, 0.1 * k, u, &info);
  fuzz::stat(5, "steer_escape<7>", s);
  fuzz::check_status_vs_input(s, fuzz::finite(X) && fuzz::finite(v), "steer_escape: non-finite input not rejected");
  if (adcs::written(s)) {
    FUZZ_CHECK(fuzz::finite(u), "steer_escape: written command not finite");
    FUZZ_CHECK(info.mode == adcs::SteeringMode::singularity_escape, "steer_escape: wrong mode");
    if (s != Status::ok) check_torque_error(info, p.max_torque_error, s);
    const double scale = X.colwise().norm().maxCoeff();
    // stableNorm: a finite u of ~1e156 (X ~ 1e-154) would overflow norm()'s sum of squares; the
    // bound is checked where v and X are normal numbers (subnormals carry few significant bits).
    const double v_norm = v.stableNorm();
    if (scale > 1e-280 && v_norm > 1e-280 && info.regularization > 0.0) {
      const double bound = v_norm / (scale * std::sqrt(info.regularization * (1.0 - 2.0 * p.epsilon0)));
      FUZZ_CHECK(u.stableNorm() <= bound * (1.0 + 1e-6) || !std::isfinite(bound), "steer_escape: |u| beyond its bound");
    }
  } else {
    FUZZ_CHECK(fuzz::same_bits_mat(u, u0), "steer_escape: rejected but wrote u");
  }
}

// steer<7> / steer_available<7> on fuzzed X, v, mask: usable statuses and request_not_met give a
// finite u (exact zeros for unavailable actuators) whose torque error matches the status; the
// others leave u untouched.
void fuzz_steering(fuzz::Reader& r) {
  static const adcs::SteeringParams kParams[4] = {{1e-3, 1e-2}, {1e-3, 0.0}, {0.0, 1e-2}, {1.0, 1.0}};
  const int config = r.u8();
  const adcs::SteeringParams& p = kParams[config & 3];
  const bool masked = (config & 4) != 0;
  for (int k = 0; k < kMaxSteps && !r.empty(); ++k) {
    adcs::Mat<3, 7> X;
    const double scale = r.value();
    for (int i = 0; i < 7; ++i) X.col(i) = r.vec<3>();
    if (fuzz::finite(scale) && scale != 0.0) X.row(r.u8() % 3) *= scale;  // near-rank-deficient X
    const Vec3 v = r.vec<3>();
    adcs::Vec<7> u = adcs::Vec<7>::Constant(-7.0);
    const adcs::Vec<7> u0 = u;
    adcs::SteeringInfo info;
    const adcs::ActuatorMask mask = masked ? r.u8() : adcs::all_actuators<7>();
    const Status s = masked ? adcs::steer_available<7>(X, v, p, mask, u, &info) : adcs::steer<7>(X, v, p, u, &info);
    fuzz::stat(masked ? 4 : 1, masked ? "steer_available<7>" : "steer<7>", s);
    if (mask & ~adcs::all_actuators<7>()) {
      FUZZ_CHECK(s == Status::out_of_range && fuzz::same_bits_mat(u, u0), "steer_available: bad mask accepted");
      continue;
    }
    // steer_available zeroes the columns of unavailable actuators first (documented), so only
    // the available columns and v count as inputs.
    bool finite_in = fuzz::finite(v);
    for (int i = 0; i < 7; ++i)
      if ((mask >> i) & 1u) finite_in = finite_in && fuzz::finite(adcs::Vec3(X.col(i)));
    fuzz::check_status_vs_input(s, finite_in, "steer: non-finite input not rejected");
    if (adcs::written(s)) {  // usable, or request_not_met: written, finite, bounded
      FUZZ_CHECK(fuzz::finite(u), "steer: usable status with a non-finite u");
      for (int i = 0; i < 7; ++i)
        if (!((mask >> i) & 1u)) FUZZ_CHECK(u(i) == 0.0, "steer_available: unavailable actuator commanded");
    } else {
      FUZZ_CHECK(fuzz::same_bits_mat(u, u0), "steer: rejected but wrote u");
    }
    FUZZ_CHECK((s == Status::ill_conditioned) == (info.mode == adcs::SteeringMode::singularity_robust) ||
                   !fuzz::applied(s),
               "steer: status and mode disagree");
    if (adcs::written(s) && s != Status::ok) check_torque_error(info, p.max_torque_error, s);
    if (!masked) fuzz_escape_steering(X, v, config, k);
  }
}

Pd make_pd() {
  Pd::Params p;
  p.K = 3.0;
  p.P = 40.0 * adcs::Mat3::Identity();
  p.J_rw_B = Vec3(900, 800, 600).asDiagonal();
  const double s = 1.0 / std::sqrt(3.0);
  p.G_s_B << 1, 0, 0, s, 0, 1, 0, s, 0, 0, 1, s;
  p.J_s.setConstant(0.1);
  p.period_s = 0.1;  // [s] validated only (the law is static); rigid-rw-mrp-pd's 10 Hz
  return Pd(p);
}

// RwTorqueAllocator: usable statuses give a finite u_s within the limit; others zero torques (the
// wheels coast).
void check_allocation(const Vec3& L) {
  static const adcs::RwTorqueAllocator<4> alloc([] {
    adcs::RwAllocationParams<4> p;
    const double s = 1.0 / std::sqrt(3.0);
    p.G_s_B << 1, 0, 0, s, 0, 1, 0, s, 0, 0, 1, s;
    p.torque_limit = 0.2;
    return p;
  }());
  adcs::WheelTorques<4> out;
  out.u_s_Nm.setConstant(-7.0);  // must be overwritten, whatever the status
  adcs::RwAllocationDiagnostics diag;
  diag.scale = fuzz::kNaN;
  const Status s = alloc.step(adcs::BodyTorque{L}, out, &diag);
  const adcs::Vec<4>& us = out.u_s_Nm;
  fuzz::stat(3, "RwTorqueAllocator", s);
  fuzz::check_status_vs_input(s, fuzz::finite(L), "RwTorqueAllocator: non-finite input not rejected");
  if (fuzz::applied(s)) {
    FUZZ_CHECK(fuzz::finite(us) && us.cwiseAbs().maxCoeff() <= 0.2, "RwTorqueAllocator: bad wheel torques");
    FUZZ_CHECK(diag.scale > 0.0 && diag.scale <= 1.0 && (s == Status::saturated || diag.scale == 1.0),
               "RwTorqueAllocator: bad scale diagnostic");
  } else {
    FUZZ_CHECK((us.array() == 0.0).all(), "RwTorqueAllocator: rejected but did not output zero wheel torques");
  }
}

void fuzz_mrp_pd(fuzz::Reader& r) {
  static const Pd proto = make_pd();
  Pd ctrl = proto;
  adcs::BodyTorque last;
  for (int k = 0; k < kMaxSteps && !r.empty(); ++k) {
    Pd::Input in;
    in.state.sigma_BN = Vec3(0.1, -0.2, 0.3) + r.vec<3>();
    in.state.omega_BN_B = Vec3(0.01, 0.0, -0.02) + r.vec<3>();
    in.Omega_rad_s = adcs::Vec<4>(10, 20, 30, 40) + r.vec<4>();
    adcs::AttitudeReference& ref = in.reference;
    ref.sigma_RN = r.vec<3>();
    ref.omega_RN_N = r.vec<3>();
    ref.domega_RN_N = r.vec<3>();
    const bool finite_in = fuzz::finite(in.state.sigma_BN) && fuzz::finite(in.state.omega_BN_B) &&
                           fuzz::finite(in.Omega_rad_s) && fuzz::finite(ref.sigma_RN) &&
                           fuzz::finite(ref.omega_RN_N) && fuzz::finite(ref.domega_RN_N);
    adcs::BodyTorque out;
    out.torque_B_Nm.setConstant(fuzz::kNaN);
    Pd::Diagnostics diag;  // σ_BR, ω_BR: defined on an applied step
    const Status s = ctrl.step(in, out, &diag);
    fuzz::stat(2, "MrpPd", s);
    FUZZ_CHECK(fuzz::finite(out.torque_B_Nm), "MrpPd: non-finite command");
    fuzz::check_status_vs_input(s, finite_in, "MrpPd: non-finite input not rejected");
    check_allocation(r.vec<3>());  // the allocator on its own, any request
    if (!fuzz::applied(s)) {
      const adcs::FailurePolicy policy = adcs::FailurePolicy::safe_command;  // make_pd(): the default
      FUZZ_CHECK(fuzz::is_failure_command(policy, out.torque_B_Nm, last.torque_B_Nm),
                 "MrpPd: rejected step did not output the failure command");
      continue;
    }
    FUZZ_CHECK(s == Status::ok, "MrpPd: undocumented usable status");
    FUZZ_CHECK(fuzz::finite(diag.sigma_BR) && fuzz::finite(diag.omega_BR_B), "MrpPd: non-finite diagnostics");
    last = out;
    check_allocation(out.torque_B_Nm);
  }
}
}  // namespace ADCS_UNITY_ID

ADCS_FUZZ_ENTRY(fuzz_seed001) {
  using namespace ADCS_UNITY_ID;
  fuzz::Reader r(data, size);
  switch (r.u8() % 3) {
    case 0: fuzz_hybrid(r); break;
    case 1: fuzz_steering(r); break;
    default: fuzz_mrp_pd(r); break;
  }
  return 0;
}
