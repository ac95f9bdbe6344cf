#pragma once
// Active disturbance rejection control of a drag-free satellite, seed 004 eqs. (44)-(46) and §4
// gains (spec §B.7): a nonlinear PID (Han's fal) per loop plus compensation of the estimated
// disturbances and of the modelled s/c-TM coupling, clipped to the actuator cube [−ρ, ρ]³:
//
//   T_Csc = I_sc T_Csc0 − T̂_Dsc                                                        seed 004 eq. (44)
//   F_Csc = −F_Csc0 + m_sc ĥ_idf − F̂_Dsc,   ĥ_idf = −(K_trans r̂ + D_trans ṙ̂)/m_tm         seed 004 eq. (45)
//   T_Ctm = I_tm T_Ctm0 − T̂_Dtm − I_tm ĥ_itm, ĥ_itm = I_tm⁻¹(K_rot φ̂_rel + D_rot φ̇̂_rel)   seed 004 eq. (46)
//   X_0 = k_p fal(e_p) + k_i fal(e_i) + k_d fal(e_d) componentwise, fal(e, 0.5, 0.01)
//
// The integral is e_i = h Σ e_p with the integral gains halved by default (spec §B.7 [D]: the
// paper's raw sum makes both linear-zone loops unstable); the literal raw sum is selectable.
// The tracking differentiator is bypassed (the paper gives no parameters, spec B.10 #16).
#include <cmath>

#include "adcs/actuator/saturation.hpp"
#include "adcs/control/pid.hpp"
#include "adcs/core/component.hpp"
#include "adcs/core/failure_policy.hpp"
#include "adcs/core/status.hpp"
#include "adcs/core/types.hpp"
#include "adcs/core/validation.hpp"
#include "adcs/plant/drag_free.hpp"

namespace adcs {

//! Han's fal: e/δ^{1−α} for |e| ≤ δ, sign(e)|e|^α beyond (continuous at ±δ, odd, slope δ^{α−1}
//! at 0).   Han 2009, IEEE TIE 56(3); seed 004 §2.4
//! delta_pow = δ^{1−α}, computed once by the caller (DragFreeAdrcT: 27 fal terms per sample, whose
//! pow(δ, 1−α) calls were ~5 % of the drag-free sample's host instructions and 3,400 of the
//! Cortex-M7's; issue 20). The same values as the three-argument form, bit for bit.
template <class S>
S fal(S e, identity_t<S> alpha, identity_t<S> delta, identity_t<S> delta_pow) noexcept {
  const S a = std::abs(e);
  if (a <= delta) return e / delta_pow;
  return std::copysign(std::pow(a, alpha), e);
}
template <class S>
S fal(S e, identity_t<S> alpha, identity_t<S> delta) noexcept {
  return fal<S>(e, alpha, delta, std::pow(delta, S(1) - alpha));
}

enum class IntegralForm {
  scaled_sum,  //!< e_i = h Σ e_p (spec §B.7 default [D], used with halved integral gains)
  raw_sum,     //!< e_i = Σ e_p (the paper's literal form; linearly unstable with its gains)
};

//! The X-axis force law: the paper's NLPID, or the Fig. 9 baselines.
enum class DragFreeXLaw {
  nlpid,            //!< ADRC as (45)
  pid,              //!< F_x = −(K_P e_p + K_I e_i + K_D e_d): linear, no compensation (Fig. 9 PID)
  pid_compensated,  //!< the same PID + (m_sc ĥ_idf,x − F̂_Dsc,x) (Fig. 9 "ADRC")
};

//! Gains of one nonlinear PID loop (finite, >= 0: the errors carry the sign, e = command − state).
//! 0 switches a term off; DragFreeAdrcParams sets every loop to its seed 004 §4 value.
template <class S = double>
struct NlpidGainsT {
  S kp = S(0), ki = S(0), kd = S(0);  //!< on fal(e_p), fal(e_i), fal(e_d)

  template <class T>
  NlpidGainsT<T> cast() const noexcept {
    return NlpidGainsT<T>{narrow_scalar<T>(kp), narrow_scalar<T>(ki), narrow_scalar<T>(kd)};
  }
};
using NlpidGains = NlpidGainsT<double>;

//! True when every gain is finite and >= 0.
template <class S>
bool valid(const NlpidGainsT<S>& g) noexcept {
  return finite_nonnegative(g.kp) && finite_nonnegative(g.ki) && finite_nonnegative(g.kd);
}

//! Every default is seed 004's (§4 gains with k_i halved per spec §B.7 [D], Table 2 plant,
//! Fig. 9 PID): the paper's configuration, as dragfree-adrc runs it. S is the law's scalar
//! (issue 19; DragFreeAdrcParams: double).
template <class S = double>
struct DragFreeAdrcParamsT {
  DragFreeParamsT<S> plant{};                                //!< masses, inertias, couplings, h
  NlpidGainsT<S> attitude{S(0.001), S(0.00005), S(0.01)};    //!< seed 004 §4; k_i halved [D]
  NlpidGainsT<S> drag_free{S(0.5), S(0.005), S(1.9)};        //!< seed 004 §4; k_i halved [D]
  NlpidGainsT<S> tm_attitude{S(0.0001), S(0.0), S(0.0021)};  //!< seed 004 §4 (no integral)
  S alpha = S(0.5);                                          //!< fal exponent (seed 004 §4)
  S delta = S(0.01);                                         //!< fal linear zone (seed 004 §4)
  IntegralForm integral = IntegralForm::scaled_sum;          //!< spec §B.7 [D]
  S limit = S(0.03);                                         //!< ρ1 = ρ2 = ρ3 [N m, N, N m]
  DragFreeXLaw x_law = DragFreeXLaw::nlpid;
  S pid_kp = S(5.55), pid_ki = S(0.0), pid_kd = S(9.0);      //!< Fig. 9 PID [N/m, -, N s/m]
  FailurePolicy on_failure = FailurePolicy::safe_command;    //!< after a failed sample: u = 0, or hold

  //! The same parameters in the scalar T, each value rounded once (narrow_scalar).
  template <class T>
  DragFreeAdrcParamsT<T> cast() const noexcept {
    DragFreeAdrcParamsT<T> o;
    o.plant = plant.template cast<T>();
    o.attitude = attitude.template cast<T>();
    o.drag_free = drag_free.template cast<T>();
    o.tm_attitude = tm_attitude.template cast<T>();
    o.alpha = narrow_scalar<T>(alpha);
    o.delta = narrow_scalar<T>(delta);
    o.integral = integral;
    o.limit = narrow_scalar<T>(limit);
    o.x_law = x_law;
    o.pid_kp = narrow_scalar<T>(pid_kp);
    o.pid_ki = narrow_scalar<T>(pid_ki);
    o.pid_kd = narrow_scalar<T>(pid_kd);
    o.on_failure = on_failure;
    return o;
  }
};
using DragFreeAdrcParams = DragFreeAdrcParamsT<double>;

//! What the law reads each sample (spec §B.7 execution order).
template <class S = double>
struct DragFreeAdrcInputT {
  Vec<27, S> x_hat = Vec<27, S>::Zero();     //!< Algorithm 1's posterior (27 states, fused), DragFreeIndex order
  Vec<3, S> F_D_hat_N = Vec<3, S>::Zero();   //!< [N] Algorithm 2's predicted f̂ per axis
  Vec<3, S> phi_sc_cmd_rad = Vec<3, S>::Zero();  //!< [rad] spacecraft attitude command
};
using DragFreeAdrcInput = DragFreeAdrcInputT<double>;

//! The drag-free satellite's actuation: [T_Csc; F_Csc; T_Ctm], each within ±limit.
template <class S = double>
struct DragFreeActuationT {
  Vec<3, S> T_Csc_Nm = Vec<3, S>::Zero();  //!< [N m] spacecraft control torque
  Vec<3, S> F_Csc_N = Vec<3, S>::Zero();   //!< [N] spacecraft control force
  Vec<3, S> T_Ctm_Nm = Vec<3, S>::Zero();  //!< [N m] test-mass control torque
  //! [T_Csc; F_Csc; T_Ctm], the plant's input order u (9).
  Vec<9, S> stacked() const noexcept {
    Vec<9, S> u;
    u << T_Csc_Nm, F_Csc_N, T_Ctm_Nm;
    return u;
  }
  static DragFreeActuationT from_stacked(const Vec<9, S>& u) noexcept {
    return DragFreeActuationT{u.template segment<3>(0), u.template segment<3>(3), u.template segment<3>(6)};
  }
};
using DragFreeActuation = DragFreeActuationT<double>;

//! What the sample did beyond its output.
struct DragFreeAdrcDiagnostics {
  int clipped = 0;  //!< components clipped to ±limit this sample
};

template <class S = double>
class DragFreeAdrcT {
 public:
  using Scalar = S;
  using Params = DragFreeAdrcParamsT<S>;
  using Input = DragFreeAdrcInputT<S>;
  using Output = DragFreeActuationT<S>;
  using Diagnostics = DragFreeAdrcDiagnostics;
  using Vec3s = Vec<3, S>;
  using Vec9s = Vec<9, S>;

  explicit DragFreeAdrcT(const Params& p) noexcept
      : p_(p), delta_pow_(std::pow(p.delta, S(1) - p.alpha)), pid_x_(pid_params(p)) {
    const bool ok = std::isfinite(p_.alpha) && p_.alpha > S(0) && p_.alpha <= S(1) && finite_positive(p_.delta) &&
                    finite_positive(p_.limit) && valid(p_.plant) && valid(p_.attitude) && valid(p_.drag_free) &&
                    valid(p_.tm_attitude) && pid_x_.status() == Status::ok;
    status_ = ok ? Status::ok : Status::invalid_parameter;
    reset();
  }
  //! ok, or invalid_parameter: fal exponent α outside (0, 1]; δ or the limit ρ not finite > 0;
  //! the plant invalid (valid(DragFreeParams): masses, SPD inertias, h, ...); an NLPID gain not
  //! finite or < 0; the Fig. 9 PID refused (Pid: gains finite >= 0). A refused controller answers
  //! invalid_parameter from every step() with its failure command.
  Status status() const noexcept { return status_; }
  S period_s() const noexcept { return p_.plant.period_s; }
  const Params& params() const noexcept { return p_; }

  void reset() noexcept {
    e_i_att_.setZero();
    e_i_df_.setZero();
    pid_x_.reset();
    last_.setZero();
  }

  //! One 0.1 s sample. x_hat: Algorithm 1's posterior (27 states, after fusion of the previous
  //! sample); F_D_hat: Algorithm 2's predicted f̂ per axis (spec §B.7 execution order);
  //! phi_cmd [rad]: s/c attitude command. u = [T_Csc; F_Csc; T_Ctm] clipped to ±limit.
  //! ok; saturated (some component clipped); non_finite_input / out_of_range (u = the failure
  //! command: zero, or the last command under on_failure = hold_last; integrals kept).
  [[nodiscard]] Status step(const Input& in, Output& out, Diagnostics* diag = nullptr) noexcept {
    out = Output::from_stacked(failure_command(p_.on_failure, last_, Vec9s(Vec9s::Zero())));
    if (status_ != Status::ok) return status_;
    const Vec<27, S>& x_hat = in.x_hat;
    const Vec3s& F_D_hat = in.F_D_hat_N;
    const Vec3s& phi_cmd = in.phi_sc_cmd_rad;
    if (!all_finite(x_hat) || !all_finite(F_D_hat) || !all_finite(phi_cmd)) return Status::non_finite_input;
    using Ix = DragFreeIndex;
    const DragFreeParamsT<S>& pl = p_.plant;
    const Vec3s phi = x_hat.template segment<3>(Ix::phi_sc), phi_dot = x_hat.template segment<3>(Ix::phi_sc_dot);
    const Vec3s r = x_hat.template segment<3>(Ix::r), r_dot = x_hat.template segment<3>(Ix::r_dot);
    const Vec3s phr = x_hat.template segment<3>(Ix::phi_rel), phr_dot = x_hat.template segment<3>(Ix::phi_rel_dot);
    const S w = p_.integral == IntegralForm::scaled_sum ? pl.period_s : S(1);
    const Vec3s e_p_att = phi_cmd - phi, e_p_df = -r;
    const Vec3s e_i_att = e_i_att_ + w * e_p_att, e_i_df = e_i_df_ + w * e_p_df;
    Vec3s T0, F0, Ttm0;
    for (int a = 0; a < 3; ++a) {
      T0(a) = nlpid(p_.attitude, e_p_att(a), e_i_att(a), -phi_dot(a));
      F0(a) = nlpid(p_.drag_free, e_p_df(a), e_i_df(a), -r_dot(a));
      Ttm0(a) = nlpid(p_.tm_attitude, -phr(a), S(0), -phr_dot(a));
    }
    const Vec3s h_idf = -(pl.K_trans * r + pl.D_trans * r_dot) / pl.m_tm;     // seed 004 eq. (45)
    const Vec3s h_itm_Itm = pl.K_rot * phr + pl.D_rot * phr_dot;              // I_tm ĥ_itm (46)
    Vec9s cmd;
    cmd.template segment<3>(0) = pl.I_sc * T0 - x_hat.template segment<3>(Ix::T_Dsc);  // seed 004 eq. (44)
    cmd.template segment<3>(3) = -F0 + pl.m_sc * h_idf - F_D_hat;                      // seed 004 eq. (45)
    Pid<1, S> pid_next = pid_x_;
    if (p_.x_law != DragFreeXLaw::nlpid) {  // Fig. 9 baselines: F_x = −(K_P e_p + K_I e_i + K_D e_d)
      PidOutput<1, S> pid_out;
      if (pid_next.step(PidInput<1, S>{Vec<1, S>(e_p_df(0)), Vec<1, S>(-r_dot(0))}, pid_out) != Status::ok)
        return Status::out_of_range;
      cmd(3) = -pid_out.u(0) + (p_.x_law == DragFreeXLaw::pid_compensated ? pl.m_sc * h_idf(0) - F_D_hat(0) : S(0));
    }
    cmd.template segment<3>(6) = pl.I_tm * Ttm0 - x_hat.template segment<3>(Ix::T_Dtm) - h_itm_Itm;  // seed 004 eq. (46)
    if (!all_finite(cmd)) return Status::out_of_range;
    const int clipped = saturate_each<9, S>(cmd, Vec9s::Constant(p_.limit));  // Note 2.5: [−ρ, ρ]³
    e_i_att_ = e_i_att;
    e_i_df_ = e_i_df;
    pid_x_ = pid_next;
    last_ = cmd;
    out = Output::from_stacked(cmd);
    if (diag) diag->clipped = clipped;
    return clipped > 0 ? Status::saturated : Status::ok;
  }

  const Vec3s& attitude_integral() const noexcept { return e_i_att_; }
  const Vec3s& drag_free_integral() const noexcept { return e_i_df_; }

 private:
  static PidParams<1, S> pid_params(const Params& p) noexcept {
    PidParams<1, S> q;
    q.kp(0) = p.pid_kp;
    q.ki(0) = p.pid_ki;
    q.kd(0) = p.pid_kd;
    q.period_s = p.plant.period_s;
    return q;
  }
  S nlpid(const NlpidGainsT<S>& g, S e_p, S e_i, S e_d) const noexcept {
    return g.kp * fal(e_p, p_.alpha, p_.delta, delta_pow_) + g.ki * fal(e_i, p_.alpha, p_.delta, delta_pow_) +
           g.kd * fal(e_d, p_.alpha, p_.delta, delta_pow_);
  }

  Params p_;
  S delta_pow_;  //!< δ^{1−α} of p_ (fal's linear zone), computed once
  Pid<1, S> pid_x_;
  Vec3s e_i_att_ = Vec3s::Zero(), e_i_df_ = Vec3s::Zero();
  Vec9s last_ = Vec9s::Zero();
  Status status_ = Status::ok;
};
using DragFreeAdrc = DragFreeAdrcT<double>;

ADCS_ASSERT_COMPONENT(DragFreeAdrc);
ADCS_ASSERT_COMPONENT(DragFreeAdrcT<float>);

}  // namespace adcs
