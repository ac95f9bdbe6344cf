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
//! (the paper's Table 2 was lost).
struct FtsmcSe3Params {
  double p_s = 0.5;   //!< [-] S exponent r = 1 − p_s = 0.5
  double eps = 0.01;  //!< [rad | m] switch of S
  Vec6 C1 = (Vec6() << 0.05, 0.05, 0.05, 0.03, 0.03, 0.03).finished();  //!< [1/s]
  Vec6 C2 = (Vec6() << 0.1, 0.1, 0.1, 0.2, 0.2, 0.2).finished();
  Vec6 K_a = Vec6::Constant(0.5);   //!< [1/s]
  Vec6 K_b = Vec6::Constant(0.05);
  double rho = 0.5;                 //!< [-] power of the reaching term
  double k_s = 0.0;                 //!< switching gain (0 in Table 2)
  double phi = 0.01;                //!< tanh boundary layer
  double period_s = 0.125;          //!< [s] control period (seed 003: 8 Hz, GIVEN)
  Se3SpacecraftParams nominal{};    //!< J0, m0: the controller's model of the chaser (no default)
  FailurePolicy on_failure = FailurePolicy::safe_command;  //!< after a failed tick: zero wrench, or hold
};

//! The sliding variable of the tick.
struct FtsmcSe3Diagnostics {
  Vec6 s = Vec6::Zero();  //!< [rad/s | m/s] s = η̇ + C1 η + C2 S(η)
};

class FtsmcSe3 {
 public:
  using Params = FtsmcSe3Params;
  using Input = Se3TrackingInput;
  using Output = Wrench;
  using Diagnostics = FtsmcSe3Diagnostics;

  explicit FtsmcSe3(const Params& p) noexcept
      : p_(p), nominal_(p.nominal), S_(NonsingularPowerParams{p.p_s, p.eps}) {
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
  double period_s() const noexcept { return p_.period_s; }
  const Params& params() const noexcept { return p_; }
  void reset() noexcept { u_.setZero(); }
  const Vec6& command() const noexcept { return u_; }
  //! The sliding variable of the last good tick.
  const Vec6& sliding_variable() const noexcept { return s_; }

  //! One control tick. On a status that is not usable u is the failure command (zero wrench, or the last good
  //! command under on_failure = hold_last).
  [[nodiscard]] Status step(const Input& in, Output& out, Diagnostics* diag = nullptr) noexcept {
    Se3TrackingError e;
    const Status se = se3_law_error(status_, in.state, in.desired, nominal_, e);
    if (se != Status::ok) {
      out = Wrench::from_stacked(failure_command(p_.on_failure, u_, Vec6(Vec6::Zero())));
      return se;
    }
    const Vec6 s = e.eta_dot + p_.C1.cwiseProduct(e.eta) + p_.C2.cwiseProduct(S_.value(e.eta));
    Vec6 reach;
    for (int i = 0; i < 6; ++i)
      reach(i) = p_.K_a(i) * s(i) + p_.K_b(i) * sig(s(i), p_.rho) + p_.k_s * std::tanh(s(i) / p_.phi);
    const Vec6 nu = -e.G_dot_xi_e - e.G.times(e.F0) - p_.C1.cwiseProduct(e.eta_dot) -
                    p_.C2.cwiseProduct(S_.derivative(e.eta)).cwiseProduct(e.eta_dot) - reach;
    const Vec6 u_new = se3_apply_inertia(nominal_.params(), e.G.inverse_times(nu));
    if (!all_finite(u_new)) {
      out = Wrench::from_stacked(failure_command(p_.on_failure, u_, Vec6(Vec6::Zero())));
      return Status::out_of_range;
    }
    u_ = u_new;
    s_ = s;
    out = Wrench::from_stacked(u_);
    if (diag) diag->s = s;
    return Status::ok;
  }

 private:
  Params p_;
  Se3Spacecraft nominal_;
  NonsingularPower S_;
  Status status_ = Status::ok;
  Vec6 u_ = Vec6::Zero();
  Vec6 s_ = Vec6::Zero();
};

ADCS_ASSERT_COMPONENT(FtsmcSe3);

}  // namespace adcs
