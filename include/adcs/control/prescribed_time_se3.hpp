#pragma once
// Backstepping practical prescribed-time control on SE(3) with input-quantization compensation
// and an adaptive estimate of the squared disturbance bound (BsPdTC), seed 003 §2.3 eqs.
// seed 003 eqs. (29)-(47) as reconstructed in spec §A.5 (the paper's display equations were lost):
//
//   z1 = η,   c = π/(pT)
//   α(z1) = −K2 z1 − c [Λ S(z1; ε1) + Υ sig^{1+p}(z1)]                                  seed 003 eqs. (29)-(35)
//   z2 = G(z1) ξ_e − α,   α̇ = diag(∂α_i/∂z1i) G ξ_e
//   u1 = Ξ0 G⁻¹ [−Ġξ_e − G F0 + α̇ − K3 z2 − c (Λ' S(z2; ε2) + Υ' sig^{1+p}(z2))]
//   b = Ξ0⁻¹ Gᵀ z2,   u2 = −ζ ⊙ tanh(ζ ⊙ b / ε_q)   (ζ_i ≥ ϖ_i of the quantizer)
//   u3 = −(ψ̂/(2a²)) Ξ0 G⁻¹ z2
//   ψ̂̇ = γ ‖z2‖²/(2a²) − σ1 ψ̂ − σ2 ψ̂³   (forward Euler at the control rate, ψ̂ ≥ 0)
//   u = u1 + u2 + u3                                                                     seed 003 eq. (47)
//
// The prescribed time T is one parameter. The command u = [M; F] (body, N m; N) goes through
// sat → Q → actuator outside (actuator/quantizer.hpp, saturate_then_quantize). Per spec §A.5's
// caveat the default gains (Table 1, [A]) violate the high-power sufficient conditions under the
// actuator limits, so T acts as a monotone tuning knob, not a certified bound.
#include <cmath>

#include "adcs/actuator/quantizer.hpp"
#include "adcs/control/nonsingular_power.hpp"
#include "adcs/control/se3_tracking_error.hpp"
#include "adcs/core/component.hpp"
#include "adcs/core/failure_policy.hpp"
#include "adcs/core/signals.hpp"
#include "adcs/core/status.hpp"
#include "adcs/core/types.hpp"
#include "adcs/core/validation.hpp"

namespace adcs {

//! ζ_i = margin · ϖ_i of each quantizer channel (spec §A.5: "ζ > ϖ"; Table 1 [A]: margin 1.05).
template <class S>
inline Vec<6, S> quantization_compensation_gain(const CompositeQuantizerParams<6, S>& q,
                                               identity_t<S> margin = S(1.05)) noexcept {
  Vec<6, S> zeta;
  for (int i = 0; i < 6; ++i) zeta(i) = margin * quantizer_error_bound(q.channel[static_cast<std::size_t>(i)]);
  return zeta;
}

//! Gains; channels [rotation x3; translation x3]. Every default is spec §A.8 "Proposed Table 1"
//! [A] (the paper's Table 1 was lost). No default for the nominal model (the controller's
//! knowledge of the vehicle) nor for ζ, which depends on the quantizer in front of the plant:
//! both are NaN until set, and refused. Scalar S (issue 19): `PrescribedTimeSe3Params` is the
//! double instance; cast<float>() gives the float law's.
template <class S = double>
struct PrescribedTimeSe3ParamsT {
  using V6 = Vec<6, S>;
  S p = S(0.5);              //!< [-] power, 0 < p < 1
  S T = S(120.0);            //!< [s] prescribed time (paper: 80, 100, 120, 140)
  V6 K2 = (V6() << S(0.02), S(0.02), S(0.02), S(0.003), S(0.003), S(0.003)).finished();  //!< [1/s]
  V6 Lambda = (V6() << S(2.0), S(2.0), S(2.0), S(3.75), S(3.75), S(3.75)).finished();   //!< Λ, low-power gain
  V6 Upsilon = (V6() << S(0.05), S(0.05), S(0.05), S(0.005), S(0.005), S(0.005)).finished();  //!< Υ, high-power
  S eps1 = S(0.01);          //!< [rad | m] ε1, switch of S(z1)
  V6 K3 = V6::Constant(S(0.5));          //!< [1/s]
  V6 Lambda2 = V6::Constant(S(1.0));     //!< Λ'
  V6 Upsilon2 = V6::Constant(S(0.1));    //!< Υ'
  S eps2 = S(0.01);          //!< ε2, switch of S(z2)
  V6 zeta = V6::Constant(unset_v<S>);  //!< [N m | N] ζ ≥ ϖ (quantization_compensation_gain), no default
  S eps_q = S(1e-3);         //!< ε_q, tanh width of u2
  S a = S(0.05);             //!< robust-term scale
  S gamma = S(1e-7);         //!< adaptation gain
  S sigma1 = S(0.05);        //!< [1/s] leakage
  S sigma2 = S(1e4);         //!< cubic leakage
  S psi_hat0 = S(1e-4);      //!< ψ̂(0) (GIVEN by the paper)
  S period_s = S(0.125);     //!< [s] h, control period (8 Hz, GIVEN)
  Se3SpacecraftParamsT<S> nominal{};  //!< J0, m0: the controller's model of the chaser (no default)
  FailurePolicy on_failure = FailurePolicy::safe_command;  //!< after a failed tick: zero wrench, or hold

  //! The same parameters in another scalar (each value rounded once; validated by the law).
  template <class U>
  PrescribedTimeSe3ParamsT<U> cast() const noexcept {
    PrescribedTimeSe3ParamsT<U> q;
    q.p = narrow_scalar<U>(p);
    q.T = narrow_scalar<U>(T);
    q.K2 = scalar_cast<U>(K2);
    q.Lambda = scalar_cast<U>(Lambda);
    q.Upsilon = scalar_cast<U>(Upsilon);
    q.eps1 = narrow_scalar<U>(eps1);
    q.K3 = scalar_cast<U>(K3);
    q.Lambda2 = scalar_cast<U>(Lambda2);
    q.Upsilon2 = scalar_cast<U>(Upsilon2);
    q.eps2 = narrow_scalar<U>(eps2);
    q.zeta = scalar_cast<U>(zeta);
    q.eps_q = narrow_scalar<U>(eps_q);
    q.a = narrow_scalar<U>(a);
    q.gamma = narrow_scalar<U>(gamma);
    q.sigma1 = narrow_scalar<U>(sigma1);
    q.sigma2 = narrow_scalar<U>(sigma2);
    q.psi_hat0 = narrow_scalar<U>(psi_hat0);
    q.period_s = narrow_scalar<U>(period_s);
    q.nominal = nominal.template cast<U>();
    q.on_failure = on_failure;
    return q;
  }
};
using PrescribedTimeSe3Params = PrescribedTimeSe3ParamsT<double>;

//! One tick's intermediate quantities, for logging and tests.
template <class S = double>
struct PrescribedTimeSe3TermsT {
  Vec<6, S> z1 = Vec<6, S>::Zero(), z2 = Vec<6, S>::Zero(), alpha = Vec<6, S>::Zero();
  Vec<6, S> u1 = Vec<6, S>::Zero(), u2 = Vec<6, S>::Zero(), u3 = Vec<6, S>::Zero();
};
using PrescribedTimeSe3Terms = PrescribedTimeSe3TermsT<double>;

//! Scalar S (issue 19): `PrescribedTimeSe3` is the double instance. In float the law is only as
//! good as its float input: the ECI positions carry 0.5 m (se3_tracking_error).
template <class S = double>
class PrescribedTimeSe3T {
 public:
  using Params = PrescribedTimeSe3ParamsT<S>;
  using Input = Se3TrackingInputT<S>;
  using Output = WrenchT<S>;
  using Diagnostics = PrescribedTimeSe3TermsT<S>;
  using V6 = Vec<6, S>;

  explicit PrescribedTimeSe3T(const Params& p) noexcept
      : p_(p),
        nominal_(p.nominal),
        S1_(NonsingularPowerParamsT<S>{p.p, p.eps1}),
        S2_(NonsingularPowerParamsT<S>{p.p, p.eps2}) {
    // p ∈ (0, 1) and ε1, ε2 are checked by S1_, S2_ (NonsingularPower).
    const bool ok = finite_positive(p_.T) && finite_positive(p_.period_s) && finite_positive(p_.a) &&
                    finite_positive(p_.eps_q) && finite_nonnegative(p_.gamma) && finite_nonnegative(p_.sigma1) &&
                    finite_nonnegative(p_.sigma2) && finite_nonnegative(p_.psi_hat0) && finite_nonnegative(p_.K2) &&
                    finite_nonnegative(p_.K3) && finite_nonnegative(p_.zeta) && finite_nonnegative(p_.Lambda) &&
                    finite_nonnegative(p_.Upsilon) && finite_nonnegative(p_.Lambda2) &&
                    finite_nonnegative(p_.Upsilon2) && nominal_.status() == Status::ok && S1_.status() == Status::ok &&
                    S2_.status() == Status::ok;
    status_ = ok ? Status::ok : Status::invalid_parameter;
    reset();
  }

  //! ok, or invalid_parameter: p outside (0, 1) or ε1, ε2 not finite > 0 (NonsingularPower); T,
  //! h, a, ε_q not finite > 0; a gain (K2, Λ, Υ, K3, Λ', Υ', ζ), γ, σ1, σ2 or ψ̂(0) not finite
  //! or < 0 (ψ̂ estimates a squared bound; negative gains destabilise the backstepping); the
  //! nominal model refused (Se3Spacecraft). A refused law answers invalid_parameter from every
  //! step() with its failure command.
  Status status() const noexcept { return status_; }
  S period_s() const noexcept { return p_.period_s; }
  const Params& params() const noexcept { return p_; }
  void reset() noexcept {
    psi_hat_ = p_.psi_hat0;
    u_.setZero();
  }
  //! ψ̂, the estimate of the squared disturbance bound.
  S psi_hat() const noexcept { return psi_hat_; }
  //! The last good command [N m; N].
  const V6& command() const noexcept { return u_; }
  const Diagnostics& terms() const noexcept { return terms_; }

  //! One control tick: u from the chaser state x and the desired state d, then ψ̂ ← ψ̂ + h ψ̂̇.
  //! On a status that is not usable u is the failure command (zero wrench, or the last good
  //! command under on_failure = hold_last) and ψ̂ is unchanged.
  [[nodiscard]] Status step(const Input& in, Output& out, Diagnostics* diag = nullptr) noexcept {
    Se3TrackingErrorT<S> e;
    const Status se = se3_law_error(status_, in.state, in.desired, nominal_, e);
    if (se != Status::ok) {
      out = Output::from_stacked(failure_command(p_.on_failure, u_, V6(V6::Zero())));
      return se;
    }
    const S c = pi_v<S> / (p_.p * p_.T);
    // Plain locals (copied to terms_ on success): a zero-initialised Terms costs memset calls on
    // the Cortex-M7 (issue 7 budget).
    const V6& z1 = e.eta;
    V6 alpha, dalpha;  // α, ∂α_i/∂z1i
    for (int i = 0; i < 6; ++i) {
      const S z = z1(i);
      alpha(i) = -p_.K2(i) * z - c * (p_.Lambda(i) * S1_.value(z) + p_.Upsilon(i) * sig(z, S(1) + p_.p));
      dalpha(i) = -p_.K2(i) - c * (p_.Lambda(i) * S1_.derivative(z) +
                                   p_.Upsilon(i) * (S(1) + p_.p) * detail::abs_pow(std::fabs(z), p_.p));
    }
    const V6 z2 = e.eta_dot - alpha;  // z2 = G ξ_e − α   seed 003 eq. (29)
    const V6 alpha_dot = dalpha.cwiseProduct(e.eta_dot);  // seed 003 eq. (37)
    V6 shaping;
    for (int i = 0; i < 6; ++i)
      shaping(i) = p_.Lambda2(i) * S2_.value(z2(i)) + p_.Upsilon2(i) * sig(z2(i), S(1) + p_.p);
    const V6 v1 = -e.G_dot_xi_e - e.G.times(e.F0) + alpha_dot - p_.K3.cwiseProduct(z2) - c * shaping;
    const V6 u1 = se3_apply_inertia(nominal_.params(), e.G.inverse_times(v1));  // seed 003 eq. (41)
    const V6 b = se3_apply_inverse_inertia(nominal_, e.G.transpose_times(z2));  // Ξ0⁻¹ Gᵀ z2
    V6 u2;
    for (int i = 0; i < 6; ++i) u2(i) = -p_.zeta(i) * std::tanh(p_.zeta(i) * b(i) / p_.eps_q);  // seed 003 eq. (43)
    const S two_a2 = S(2) * p_.a * p_.a;
    // u3 = −(ψ̂/(2a²)) Ξ0 G⁻¹ z2   seed 003 eq. (46)
    const V6 u3 = -(psi_hat_ / two_a2) * se3_apply_inertia(nominal_.params(), e.G.inverse_times(z2));
    const V6 u_new = u1 + u2 + u3;  // seed 003 eq. (47)
    const S psi_dot = p_.gamma * z2.squaredNorm() / two_a2 - p_.sigma1 * psi_hat_ -
                      p_.sigma2 * psi_hat_ * psi_hat_ * psi_hat_;  // seed 003 eq. (44)
    const S psi_new = std::fmax(S(0), psi_hat_ + p_.period_s * psi_dot);
    if (!all_finite(u_new) || !std::isfinite(psi_new)) {
      out = Output::from_stacked(failure_command(p_.on_failure, u_, V6(V6::Zero())));
      return Status::out_of_range;
    }
    u_ = u_new;
    out = Output::from_stacked(u_);
    psi_hat_ = psi_new;
    terms_.z1 = z1;
    terms_.z2 = z2;
    terms_.alpha = alpha;
    terms_.u1 = u1;
    terms_.u2 = u2;
    terms_.u3 = u3;
    if (diag) *diag = terms_;
    return Status::ok;
  }

 private:
  Params p_;
  Se3SpacecraftT<S> nominal_;
  NonsingularPowerT<S> S1_, S2_;
  Status status_ = Status::ok;
  S psi_hat_ = S(0);
  V6 u_ = V6::Zero();
  Diagnostics terms_;
};
using PrescribedTimeSe3 = PrescribedTimeSe3T<double>;

ADCS_ASSERT_COMPONENT(PrescribedTimeSe3);
ADCS_ASSERT_COMPONENT(PrescribedTimeSe3T<float>);

}  // namespace adcs
