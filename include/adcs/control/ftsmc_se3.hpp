#pragma once
// Finite-time (fast terminal) sliding-mode baseline on SE(3), seed 003 §3.2 2) as reconstructed in
// spec §A.6 (ref. [33] lost; Yu & Man 2002 fast TSM, Lee & Vukovich 2016 SE(3) TSM):
//
//   s = η̇ + C1 η + C2 S(η; ε),   η̇ = G ξ_e   (S of exponent r = 1 − p_s, non-singular patch)
//   ν = −Ġξ_e − G F0 − C1 η̇ − C2 diag(S'(η)) η̇ − K_a s − K_b sig^ρ(s) − k_s tanh(s/φ)
//   u = Ξ0 G⁻¹ ν
//
// No quantization compensation and no adaptation: a pure baseline. The command goes through the
// same sat → Q → actuator chain as the prescribed-time law.
#include <cmath>

#include "adcs/control/nonsingular_power.hpp"
#include "adcs/control/se3_tracking_error.hpp"
#include "adcs/core/component.hpp"
#include "adcs/core/failure_policy.hpp"
#include "adcs/core/signals.hpp"
#include "adcs/core/status.hpp"
#include "adcs/core/types.hpp"
#include "adcs/core/validation.hpp"

namespace adcs {

//! Gains; channels [rotation x3; translation x3]. Defaults: spec §A.8 "Proposed Table 2" [A]
//! (the paper's Table 2 was lost). Scalar S (issue 19): `FtsmcSe3Params` is the double instance.
template <class S = double>
struct FtsmcSe3ParamsT {
  using V6 = Vec<6, S>;
  S p_s = S(0.5);   //!< [-] S exponent r = 1 − p_s = 0.5
  S eps = S(0.01);  //!< [rad | m] switch of S
  V6 C1 = (V6() << S(0.05), S(0.05), S(0.05), S(0.03), S(0.03), S(0.03)).finished();  //!< [1/s]
  V6 C2 = (V6() << S(0.1), S(0.1), S(0.1), S(0.2), S(0.2), S(0.2)).finished();
  V6 K_a = V6::Constant(S(0.5));   //!< [1/s]
  V6 K_b = V6::Constant(S(0.05));
  S rho = S(0.5);                  //!< [-] power of the reaching term
  S k_s = S(0);                    //!< switching gain (0 in Table 2)
  S phi = S(0.01);                 //!< tanh boundary layer
  S period_s = S(0.125);           //!< [s] control period (seed 003: 8 Hz, GIVEN)
  Se3SpacecraftParamsT<S> nominal{};  //!< J0, m0: the controller's model of the chaser (no default)
  FailurePolicy on_failure = FailurePolicy::safe_command;  //!< after a failed tick: zero wrench, or hold

  //! The same parameters in another scalar (each value rounded once; validated by the law).
  template <class U>
  FtsmcSe3ParamsT<U> cast() const noexcept {
    FtsmcSe3ParamsT<U> q;
    q.p_s = narrow_scalar<U>(p_s);
    q.eps = narrow_scalar<U>(eps);
    q.C1 = scalar_cast<U>(C1);
    q.C2 = scalar_cast<U>(C2);
    q.K_a = scalar_cast<U>(K_a);
    q.K_b = scalar_cast<U>(K_b);
    q.rho = narrow_scalar<U>(rho);
    q.k_s = narrow_scalar<U>(k_s);
    q.phi = narrow_scalar<U>(phi);
    q.period_s = narrow_scalar<U>(period_s);
    q.nominal = nominal.template cast<U>();
    q.on_failure = on_failure;
    return q;
  }
};
using FtsmcSe3Params = FtsmcSe3ParamsT<double>;

//! The sliding variable of the tick.
template <class S = double>
struct FtsmcSe3DiagnosticsT {
  Vec<6, S> s = Vec<6, S>::Zero();  //!< [rad/s | m/s] s = η̇ + C1 η + C2 S(η)
};
using FtsmcSe3Diagnostics = FtsmcSe3DiagnosticsT<double>;

//! Scalar S (issue 19): `FtsmcSe3` is the double instance; in float see PrescribedTimeSe3T.
template <class S = double>
class FtsmcSe3T {
 public:
  using Params = FtsmcSe3ParamsT<S>;
  using Input = Se3TrackingInputT<S>;
  using Output = WrenchT<S>;
  using Diagnostics = FtsmcSe3DiagnosticsT<S>;
  using V6 = Vec<6, S>;

  explicit FtsmcSe3T(const Params& p) noexcept
      : p_(p), nominal_(p.nominal), S_(NonsingularPowerParamsT<S>{p.p_s, p.eps}) {
    const bool ok = finite_nonnegative(p_.C1) && finite_nonnegative(p_.C2) && finite_nonnegative(p_.K_a) &&
                    finite_nonnegative(p_.K_b) && finite_positive(p_.rho) && finite_nonnegative(p_.k_s) &&
                    finite_positive(p_.phi) && finite_positive(p_.period_s) && nominal_.status() == Status::ok &&
                    S_.status() == Status::ok;
    status_ = ok ? Status::ok : Status::invalid_parameter;
  }

  //! ok, or invalid_parameter: S's p_s outside (0, 1) or ε not finite > 0 (NonsingularPower);
  //! C1, C2, K_a, K_b, k_s not finite or < 0 (the surface s = 0 and the reaching law are stable
  //! only for non-negative gains); ρ, φ or period_s not finite > 0; the nominal model refused
  //! (Se3Spacecraft). A refused law answers invalid_parameter from every step() with its
  //! failure command.
  Status status() const noexcept { return status_; }
  S period_s() const noexcept { return p_.period_s; }
  const Params& params() const noexcept { return p_; }
  void reset() noexcept { u_.setZero(); }
  const V6& command() const noexcept { return u_; }
  //! The sliding variable of the last good tick.
  const V6& sliding_variable() const noexcept { return s_; }

  //! One control tick. On a status that is not usable u is the failure command (zero wrench, or the last good
  //! command under on_failure = hold_last).
  [[nodiscard]] Status step(const Input& in, Output& out, Diagnostics* diag = nullptr) noexcept {
    Se3TrackingErrorT<S> e;
    const Status se = se3_law_error(status_, in.state, in.desired, nominal_, e);
    if (se != Status::ok) {
      out = Output::from_stacked(failure_command(p_.on_failure, u_, V6(V6::Zero())));
      return se;
    }
    const V6 s = e.eta_dot + p_.C1.cwiseProduct(e.eta) + p_.C2.cwiseProduct(S_.value(e.eta));
    V6 reach;
    for (int i = 0; i < 6; ++i)
      reach(i) = p_.K_a(i) * s(i) + p_.K_b(i) * sig(s(i), p_.rho) + p_.k_s * std::tanh(s(i) / p_.phi);
    const V6 nu = -e.G_dot_xi_e - e.G.times(e.F0) - p_.C1.cwiseProduct(e.eta_dot) -
                  p_.C2.cwiseProduct(S_.derivative(e.eta)).cwiseProduct(e.eta_dot) - reach;
    const V6 u_new = se3_apply_inertia(nominal_.params(), e.G.inverse_times(nu));
    if (!all_finite(u_new)) {
      out = Output::from_stacked(failure_command(p_.on_failure, u_, V6(V6::Zero())));
      return Status::out_of_range;
    }
    u_ = u_new;
    s_ = s;
    out = Output::from_stacked(u_);
    if (diag) diag->s = s;
    return Status::ok;
  }

 private:
  Params p_;
  Se3SpacecraftT<S> nominal_;
  NonsingularPowerT<S> S_;
  Status status_ = Status::ok;
  V6 u_ = V6::Zero();
  V6 s_ = V6::Zero();
};
using FtsmcSe3 = FtsmcSe3T<double>;

ADCS_ASSERT_COMPONENT(FtsmcSe3);
ADCS_ASSERT_COMPONENT(FtsmcSe3T<float>);

}  // namespace adcs
