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
inline Vec6 quantization_compensation_gain(const CompositeQuantizerParams<6>& q, double margin = 1.05) noexcept {
  Vec6 zeta;
  for (int i = 0; i < 6; ++i) zeta(i) = margin * quantizer_error_bound(q.channel[static_cast<std::size_t>(i)]);
  return zeta;
}

//! Gains; channels [rotation x3; translation x3]. Every default is spec §A.8 "Proposed Table 1"
//! [A] (the paper's Table 1 was lost). No default for the nominal model (the controller's
//! knowledge of the vehicle) nor for ζ, which depends on the quantizer in front of the plant:
//! both are NaN until set, and refused.
struct PrescribedTimeSe3Params {
  double p = 0.5;            //!< [-] power, 0 < p < 1
  double T = 120.0;          //!< [s] prescribed time (paper: 80, 100, 120, 140)
  Vec6 K2 = (Vec6() << 0.02, 0.02, 0.02, 0.003, 0.003, 0.003).finished();  //!< [1/s]
  Vec6 Lambda = (Vec6() << 2.0, 2.0, 2.0, 3.75, 3.75, 3.75).finished();   //!< Λ, low-power gain
  Vec6 Upsilon = (Vec6() << 0.05, 0.05, 0.05, 0.005, 0.005, 0.005).finished();  //!< Υ, high-power
  double eps1 = 0.01;        //!< [rad | m] ε1, switch of S(z1)
  Vec6 K3 = Vec6::Constant(0.5);          //!< [1/s]
  Vec6 Lambda2 = Vec6::Constant(1.0);     //!< Λ'
  Vec6 Upsilon2 = Vec6::Constant(0.1);    //!< Υ'
  double eps2 = 0.01;        //!< ε2, switch of S(z2)
  Vec6 zeta = Vec6::Constant(kUnset);  //!< [N m | N] ζ ≥ ϖ (quantization_compensation_gain), no default
  double eps_q = 1e-3;       //!< ε_q, tanh width of u2
  double a = 0.05;           //!< robust-term scale
  double gamma = 1e-7;       //!< adaptation gain
  double sigma1 = 0.05;      //!< [1/s] leakage
  double sigma2 = 1e4;       //!< cubic leakage
  double psi_hat0 = 1e-4;    //!< ψ̂(0) (GIVEN by the paper)
  double period_s = 0.125;   //!< [s] h, control period (8 Hz, GIVEN)
  Se3SpacecraftParams nominal{};  //!< J0, m0: the controller's model of the chaser (no default)
  FailurePolicy on_failure = FailurePolicy::safe_command;  //!< after a failed tick: zero wrench, or hold
};

//! One tick's intermediate quantities, for logging and tests.
struct PrescribedTimeSe3Terms {
  Vec6 z1 = Vec6::Zero(), z2 = Vec6::Zero(), alpha = Vec6::Zero();
  Vec6 u1 = Vec6::Zero(), u2 = Vec6::Zero(), u3 = Vec6::Zero();
};

class PrescribedTimeSe3 {
 public:
  using Params = PrescribedTimeSe3Params;
  using Input = Se3TrackingInput;
  using Output = Wrench;
  using Diagnostics = PrescribedTimeSe3Terms;

  explicit PrescribedTimeSe3(const Params& p) noexcept
      : p_(p), nominal_(p.nominal), S1_(NonsingularPowerParams{p.p, p.eps1}), S2_(NonsingularPowerParams{p.p, p.eps2}) {
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
  double period_s() const noexcept { return p_.period_s; }
  const Params& params() const noexcept { return p_; }
  void reset() noexcept {
    psi_hat_ = p_.psi_hat0;
    u_.setZero();
  }
  //! ψ̂, the estimate of the squared disturbance bound.
  double psi_hat() const noexcept { return psi_hat_; }
  //! The last good command [N m; N].
  const Vec6& command() const noexcept { return u_; }
  const PrescribedTimeSe3Terms& terms() const noexcept { return terms_; }

  //! One control tick: u from the chaser state x and the desired state d, then ψ̂ ← ψ̂ + h ψ̂̇.
  //! On a status that is not usable u is the failure command (zero wrench, or the last good
  //! command under on_failure = hold_last) and ψ̂ is unchanged.
  [[nodiscard]] Status step(const Input& in, Output& out, Diagnostics* diag = nullptr) noexcept {
    Se3TrackingError e;
    const Status se = se3_law_error(status_, in.state, in.desired, nominal_, e);
    if (se != Status::ok) {
      out = Wrench::from_stacked(failure_command(p_.on_failure, u_, Vec6(Vec6::Zero())));
      return se;
    }
    const double c = kPi / (p_.p * p_.T);
    // Plain locals (copied to terms_ on success): a zero-initialised Terms costs memset calls on
    // the Cortex-M7 (issue 7 budget).
    const Vec6& z1 = e.eta;
    Vec6 alpha, dalpha;  // α, ∂α_i/∂z1i
    for (int i = 0; i < 6; ++i) {
      const double z = z1(i);
      alpha(i) = -p_.K2(i) * z - c * (p_.Lambda(i) * S1_.value(z) + p_.Upsilon(i) * sig(z, 1.0 + p_.p));
      dalpha(i) = -p_.K2(i) - c * (p_.Lambda(i) * S1_.derivative(z) +
                                   p_.Upsilon(i) * (1.0 + p_.p) * detail::abs_pow(std::fabs(z), p_.p));
    }
    const Vec6 z2 = e.eta_dot - alpha;  // z2 = G ξ_e − α   seed 003 eq. (29)
    const Vec6 alpha_dot = dalpha.cwiseProduct(e.eta_dot);  // seed 003 eq. (37)
    Vec6 shaping;
    for (int i = 0; i < 6; ++i)
      shaping(i) = p_.Lambda2(i) * S2_.value(z2(i)) + p_.Upsilon2(i) * sig(z2(i), 1.0 + p_.p);
    const Vec6 v1 = -e.G_dot_xi_e - e.G.times(e.F0) + alpha_dot - p_.K3.cwiseProduct(z2) - c * shaping;
    const Vec6 u1 = se3_apply_inertia(nominal_.params(), e.G.inverse_times(v1));  // seed 003 eq. (41)
    const Vec6 b = se3_apply_inverse_inertia(nominal_, e.G.transpose_times(z2));  // Ξ0⁻¹ Gᵀ z2
    Vec6 u2;
    for (int i = 0; i < 6; ++i) u2(i) = -p_.zeta(i) * std::tanh(p_.zeta(i) * b(i) / p_.eps_q);  // seed 003 eq. (43)
    const double two_a2 = 2.0 * p_.a * p_.a;
    // u3 = −(ψ̂/(2a²)) Ξ0 G⁻¹ z2   seed 003 eq. (46)
    const Vec6 u3 = -(psi_hat_ / two_a2) * se3_apply_inertia(nominal_.params(), e.G.inverse_times(z2));
    const Vec6 u_new = u1 + u2 + u3;  // seed 003 eq. (47)
    const double psi_dot = p_.gamma * z2.squaredNorm() / two_a2 - p_.sigma1 * psi_hat_ -
                           p_.sigma2 * psi_hat_ * psi_hat_ * psi_hat_;  // seed 003 eq. (44)
    const double psi_new = std::fmax(0.0, psi_hat_ + p_.period_s * psi_dot);
    if (!all_finite(u_new) || !std::isfinite(psi_new)) {
      out = Wrench::from_stacked(failure_command(p_.on_failure, u_, Vec6(Vec6::Zero())));
      return Status::out_of_range;
    }
    u_ = u_new;
    out = Wrench::from_stacked(u_);
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
  static constexpr double kPi = 3.14159265358979323846;

  Params p_;
  Se3Spacecraft nominal_;
  NonsingularPower S1_, S2_;
  Status status_ = Status::ok;
  double psi_hat_ = 0.0;
  Vec6 u_ = Vec6::Zero();
  PrescribedTimeSe3Terms terms_;
};

ADCS_ASSERT_COMPONENT(PrescribedTimeSe3);

}  // namespace adcs
