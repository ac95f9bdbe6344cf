#pragma once
// Prescribed-performance adaptive RBF attitude tracking (PPATC) for a flexible spacecraft,
// seed 002 eq. (12), spec §B.3 steps 1-15, in x-y-z Euler angles:
//
//   e = ϑ − ϑ_d,  ε = S⁻¹(e/ρ) (adapt/ppc.hpp),  s = λ ε + ε̇                    seed 002 eq. (10)
//   u = B⁻¹ ( −A − R⁻¹V − D̂ − μ̂² s/(μ̂‖s‖ + σ) − K s ),  B⁻¹ = J G             seed 002 eq. (12)
//   (R⁻¹V)_i = (λ_i + ṙ_i/r_i) q_i − (ė_i ρ̇_i ρ_i + e_i ρ̈_i ρ_i − e_i ρ̇_i²)/ρ_i² − ϑ̈_d,i   seed 002 eq. (11)
//   Ŵ̇_i = τ_wi (s_i h − β Ŵ_i),  μ̂̇ = τ_μ (‖s‖ − γ μ̂),  h = h((180/π)[e; ė])      seed 002 eqs. (13)-(14)
//
// giving ṡ = R (D̄ − D̂ − μ̂² s/(μ̂‖s‖ + σ) − K s). The paper's law is continuous; here it is a
// discrete-time object at period_s with the estimates stepped inside step() (exact ZOH
// steps). The s-loop rate R K reaches ~1.1e4 s⁻¹ as ρ → ρ∞ (spec §B.3 step 15), so the period
// must be ~1e-4 s in the paper's unit convention; the scenario's sample-rate study measures it.
//
// Unit convention (spec B.4 #18): U_rad (default) — every controller quantity in SI radians, the
// RBF input in degrees; U_deg — the law's angle-valued quantities in degrees (the option the
// spec keeps for comparison). Only the numeric weight of −K s, D̂ and μ̂ changes between them.
#include <cstdint>

#include "adcs/adapt/ppc.hpp"
#include "adcs/adapt/rbf_compensator.hpp"
#include "adcs/control/euler_tracking_common.hpp"
#include "adcs/core/component.hpp"
#include "adcs/core/signals.hpp"
#include "adcs/core/status.hpp"
#include "adcs/core/types.hpp"

namespace adcs {

template <class S = double>
struct PpcNeuralParamsT {
  EulerTrackingGainsT<S> gains{};  //!< J, λ, K, RBF compensator, units, period
  PpcParams<3, S> ppc = seed002_performance<S>();  //!< ρ0, ρ∞, k, δ per axis [rad], seed 002 Table 2
  template <class T>
  PpcNeuralParamsT<T> cast() const noexcept {
    return {gains.template cast<T>(), ppc.template cast<T>()};
  }
};
using PpcNeuralParams = PpcNeuralParamsT<double>;

//! Optional per-step diagnostics (caller-owned).
template <class S = double>
struct PpcNeuralDiagnosticsT {
  PpcSample<3, S> ppc{};                //!< ρ, z, ε, r, ... (law units)
  Vec<3, S> s = Vec<3, S>::Zero();      //!< [-/s] sliding variable λε + ε̇
  Vec<3, S> D_hat = Vec<3, S>::Zero();  //!< [law units/s²] Ŵᵀh
  Vec<3, S> robust = Vec<3, S>::Zero(); //!< [law units/s²] μ̂²s/(μ̂‖s‖ + σ)
  Vec<3, S> e = Vec<3, S>::Zero();      //!< [rad] ϑ − ϑ_d
  S funnel_margin = S(0);               //!< [-] min distance of z to its interval edge (> 0 inside)
  bool funnel_reopened = false;         //!< this step re-opened the funnel (ppc.recovery = reopen)
};
using PpcNeuralDiagnostics = PpcNeuralDiagnosticsT<double>;

//! S: the scalar the law computes in (issue 19); `PpcNeural` is the double instance.
template <class S = double>
class PpcNeuralT {
 public:
  using Params = PpcNeuralParamsT<S>;
  using Input = EulerTrackingInputT<S>;
  using Output = BodyTorqueT<S>;
  using Diagnostics = PpcNeuralDiagnosticsT<S>;
  using Core = EulerTrackingCoreT<S>;
  using Vec3S = Vec<3, S>;

  explicit PpcNeuralT(const Params& p) noexcept
      : p_(p), core_(p.gains), ppc_(scaled(p.ppc, core_.angle_scale())) {
    status_ = core_.status() == Status::ok && ppc_.status() == Status::ok ? Status::ok : Status::invalid_parameter;
    reset();
  }

  Status status() const noexcept { return status_; }
  S period_s() const noexcept { return core_.period_s(); }
  const Params& params() const noexcept { return p_; }

  //! Estimates to Ŵ = 0, μ̂ = 0, no recoveries; the funnel is fixed again by the next step's e.
  void reset() noexcept {
    core_.reset();
    started_ = false;
    recoveries_ = 0;
  }

  //! One control sample at in.t_s [s] since the start of the manoeuvre (ρ(t) is measured from it).
  //! ok; constraint_violated (usable, the law's command: robust mode clamped an error at its
  //! funnel edge, or the funnel was re-opened — see below); out_of_range (funnel violated with
  //! ppc.recovery = none, or an overflow); non_finite_input; singular (|θ| at gimbal lock). Except
  //! for ok and constraint_violated, `out` is the failure command (zero torque, or the last good
  //! command under gains.on_failure = hold_last) and the estimates and the funnel are untouched.
  //!
  //! Funnel recovery (ppc.recovery = reopen, the default; ours, issue 15): when e has left its
  //! funnel — or starts outside it — the violated channels' funnels are re-opened from the current
  //! error (PrescribedPerformance::reopen), the law runs on them, the step returns
  //! constraint_violated and funnel_recoveries() counts it. The adaptive estimates carry on.
  [[nodiscard]] Status step(const Input& in, Output& out, Diagnostics* diag = nullptr) noexcept {
    out = core_.failure_command();
    if (diag) diag->funnel_reopened = false;
    if (status_ != Status::ok) return status_;
    typename Core::Kinematics k;
    const Status ks = core_.kinematics(in, k);
    if (ks != Status::ok) return ks;
    const S c = core_.angle_scale();
    const Vec3S e = c * k.e, e_dot = c * k.e_dot;  // law units
    const bool recover = p_.ppc.recovery == FunnelRecovery::reopen;
    Status s = Status::ok;
    if (started_) {
      s = apply(ppc_, in, k, e, e_dot, out, diag);
      if (s != Status::out_of_range || !recover) return s;
    }
    // First step, or a violation to recover from: change a copy of the funnel (the branches fixed
    // from e(0), or re-opened), kept only if the step is applied, so a rejected sample (e.g. an
    // overflow further down) never latches a funnel from its e.
    PrescribedPerformance<3, S> funnel = ppc_;
    if (!started_) {
      const Status init = funnel.init(e);
      if (init != Status::ok && !(init == Status::out_of_range && recover)) return init;
      s = apply(funnel, in, k, e, e_dot, out, diag);
    }  // else: the funnel in force already gave out_of_range above; no need to run it again
    int reopened = 0;
    if (s == Status::out_of_range && recover && funnel.reopen(in.t_s, e, reopened) == Status::ok && reopened > 0)
      s = apply(funnel, in, k, e, e_dot, out, diag);
    if (!usable(s)) return s;
    ppc_ = funnel;
    started_ = true;
    if (reopened > 0) {
      ++recoveries_;
      if (diag) diag->funnel_reopened = true;
      return Status::constraint_violated;
    }
    return s;
  }

  //! Funnel re-openings since construction or reset() (each counts once, whatever the channels).
  long funnel_recoveries() const noexcept { return recoveries_; }
  //! The funnel in force (branches, performance functions, their start times).
  const PrescribedPerformance<3, S>& funnel() const noexcept { return ppc_; }

  const Mat<7, 3, S>& weights() const noexcept { return core_.compensator().weights(); }
  S mu() const noexcept { return core_.compensator().mu(); }
  RbfCompensator<6, 7, 3, S>& compensator() noexcept { return core_.compensator(); }
  PpcBranch branch(int i) const noexcept { return ppc_.branch(i); }

 private:
  //! Steps 2-14 with the funnel `ppc` (branches fixed); commits the estimates and the command
  //! only when it returns ok or constraint_violated.
  Status apply(const PrescribedPerformance<3, S>& ppc, const Input& in, const typename Core::Kinematics& k,
               const Vec3S& e, const Vec3S& e_dot, Output& out, Diagnostics* diag) noexcept {
    const S c = core_.angle_scale();
    PpcSample<3, S> ps;
    const Status ts = ppc.transform(in.t_s, e, e_dot, ps);                             // steps 2-7
    if (!usable(ts)) return ts;
    const Vec3S& lambda = p_.gains.lambda;
    const Vec3S s = lambda.cwiseProduct(ps.eps) + ps.eps_dot;                        // seed 002 eq. (10)
    const Vec3S RinvV = (lambda + ps.r_dot.cwiseQuotient(ps.r)).cwiseProduct(ps.q) + ps.q_dot_offset -
                       c * in.reference.angles_ddot;                                            // seed 002 eq. (11)
    const Vec3S law = -c * k.affine.A - RinvV;                                        // seed 002 eq. (12), model part
    typename Core::Compensation comp;
    const Status cs = core_.compensate_and_adapt(k, s, law, out, comp);             // steps 11-14
    if (diag) {
      diag->ppc = ps;
      diag->s = s;
      diag->D_hat = comp.D_hat;
      diag->robust = comp.robust;
      diag->e = k.e;
      diag->funnel_margin = ps.margin_min;
    }
    if (cs != Status::ok) return cs;
    return ts;
  }

  static PpcParams<3, S> scaled(PpcParams<3, S> p, S c) noexcept {
    for (auto& f : p.rho) {
      f.rho0 *= c;
      f.rho_inf *= c;
    }
    return p;
  }

  Params p_;
  Core core_;
  PrescribedPerformance<3, S> ppc_;
  bool started_ = false;
  //! 32 bits on every platform (a long is 64 on x86-64, 32 on the Cortex-M), so that the C
  //! interface's state has one layout everywhere (include/adcs/c/adcs.h).
  std::int32_t recoveries_ = 0;
  Status status_ = Status::ok;
};

using PpcNeural = PpcNeuralT<double>;
ADCS_ASSERT_COMPONENT(PpcNeural);
ADCS_ASSERT_COMPONENT(PpcNeuralT<float>);

}  // namespace adcs
