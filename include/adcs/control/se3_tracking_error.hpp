#pragma once
// The SE(3) tracking error that both seed 003 laws (prescribed-time backstepping and the FTSMC
// baseline) act on, spec §A.2.3-§A.2.4 (seed 003 eqs. (6)-(11)):
//
//   g_e = g_d⁻¹ g:  C_e = C_dᵀ C,  R_e = C_dᵀ (R − R_d)
//   ξ_e = ξ − Ad_{g_e⁻¹} ξ_d,  η = [θ; β] = log(g_e)^∨,  η̇ = G(η) ξ_e                   seed 003 eq. (8)
//   ξ̇_e = F0 + Ξ0⁻¹ u_c + d,
//   F0 = Ξ0⁻¹ (ad*_ξ Ξ0 ξ + M_g(J0, m0)) + ad_{ξ_e} Ad_{g_e⁻¹} ξ_d − Ad_{g_e⁻¹} ξ̇_d         seed 003 eq. (11)
//
// with the nominal inertia Ξ0 = diag(J0, m0 I3) and the gravity wrench of the nominal model at
// the chaser's pose. Also G⁻¹ and Ġ ξ_e (the derivative of η ↦ G(η) ξ_e along η̇), which both
// laws need. Ordering [rotational; translational]; body components; SI.
#include "adcs/core/status.hpp"
#include "adcs/core/types.hpp"
#include "adcs/math/se3.hpp"
#include "adcs/plant/se3_spacecraft.hpp"

namespace adcs {

//! What both SE(3) laws read: the chaser's measured state and the desired state (scalar S,
//! issue 19).
template <class S = double>
struct Se3TrackingInputT {
  Se3SpacecraftStateT<S> state{};   //!< chaser C_NB, R_N, ω_BN_B, v_B
  Se3DesiredStateT<S> desired{};    //!< C_ND, R_N, ω_DN_D, v_D and their rates
  //! The same input in another scalar (each value rounded once; beyond T's range: ±Inf).
  template <class T>
  Se3TrackingInputT<T> cast() const noexcept {
    return Se3TrackingInputT<T>{state.template cast<T>(), desired.template cast<T>()};
  }
};
using Se3TrackingInput = Se3TrackingInputT<double>;

//! Filled by se3_tracking_error(). Like an Eigen matrix, a default-constructed one is
//! uninitialised: both laws make one per control step, and zeroing its ~100 doubles first cost
//! memset calls on the Cortex-M7 (issue 7 budget).
template <class S = double>
struct Se3TrackingErrorT {
  Vec<6, S> eta;         //!< η = [θ; β] [rad; m]
  Vec<6, S> xi_e;        //!< ξ_e = [ω_e; v_e] [rad/s; m/s], body
  Vec<6, S> eta_dot;     //!< η̇ = G(η) ξ_e
  Se3GBlocksT<S> G;      //!< G(η) and G(η)⁻¹ as blocks (G.times, G.inverse_times, …)
  Vec<6, S> G_dot_xi_e;  //!< Ġ ξ_e along η̇
  Vec<6, S> F0;          //!< nominal drift of ξ_e (11) [rad/s²; m/s²]
};
using Se3TrackingError = Se3TrackingErrorT<double>;

//! The tracking error of the chaser state x w.r.t. the desired state d under the nominal model
//! (J0, m0). non_finite_input for NaN/Inf inputs, out_of_range if the model rejects the pose or
//! a result is not finite; `out` is untouched unless ok.
//! In float, R_e = C_dᵀ(R − R_d) is the difference of two ECI positions of ~6.8e6 m, each
//! carried to 0.5 m: the relative position is known to ~0.5 m, whatever the law does with it.
template <class S>
[[nodiscard]] inline Status se3_tracking_error(const Se3SpacecraftStateT<S>& x, const Se3DesiredStateT<S>& d,
                                               const Se3SpacecraftT<S>& nominal, Se3TrackingErrorT<S>& out) noexcept {
  using V3 = Vec<3, S>;
  using V6 = Vec<6, S>;
  if (nominal.status() != Status::ok) return nominal.status();
  if (!all_finite(x.C_NB) || !all_finite(x.R_N) || !all_finite(x.omega_BN_B) || !all_finite(x.v_B) ||
      !all_finite(d.C_ND) || !all_finite(d.R_N) || !all_finite(d.xi()) || !all_finite(d.xi_dot()))
    return Status::non_finite_input;
  if (!(x.R_N.norm() >= S(kOrbitMinRadius))) return Status::out_of_range;
  // Locals, not a Se3TrackingError: its zero-initialised members cost memset calls on the
  // Cortex-M7 (issue 7 budget), and `out` is written only when everything is finite.
  Se3T<S> g_e;
  g_e.C = d.C_ND.transpose() * x.C_NB;             // C_e = C_dᵀ C
  g_e.R = d.C_ND.transpose() * (x.R_N - d.R_N);    // R_e = C_dᵀ (R − R_d)
  const V6 xi_d_e = se3_Ad_inv_times(g_e, d.xi());  // Ad_{g_e⁻¹} ξ_d
  const V6 xi_e = x.xi() - xi_d_e;                 // spec §A.2.3, seed 003 eq. (6)
  // η = log(g_e)^∨, G, G⁻¹, η̇ = G ξ_e (8) and Ġ ξ_e in one pass (shared coefficients).
  const Se3ErrorKinematicsT<S> k = se3_error_kinematics(g_e, xi_e);
  const Se3SpacecraftParamsT<S>& p0 = nominal.params();
  const V3& w = x.omega_BN_B;
  V6 rhs = nominal.gravity_wrench(x);              // M_g(J0, m0)
  rhs.template head<3>() -= w.cross(p0.J_B * w);   // ad*_ξ Ξ0 ξ = [−ω×J0ω; −m0 ω×v]
  rhs.template tail<3>() -= p0.m * w.cross(x.v_B);
  V6 F0 = stack3(nominal.J_inv() * rhs.template head<3>(), rhs.template tail<3>() / p0.m);
  F0 += se3_ad_times(xi_e, xi_d_e) - se3_Ad_inv_times(g_e, d.xi_dot());  // seed 003 eq. (11)
  if (!all_finite(k.eta) || !k.G.finite() || !all_finite(k.G_dot_xi) || !all_finite(F0))
    return Status::out_of_range;
  out.eta = k.eta;
  out.xi_e = xi_e;
  out.eta_dot = k.eta_dot;
  out.G = k.G;
  out.G_dot_xi_e = k.G_dot_xi;
  out.F0 = F0;
  return Status::ok;
}

//! The tracking error for a law's step: the law's own status first (a rejected law computes
//! nothing), then se3_tracking_error.
template <class S>
[[nodiscard]] inline Status se3_law_error(Status law_status, const Se3SpacecraftStateT<S>& x,
                                          const Se3DesiredStateT<S>& d, const Se3SpacecraftT<S>& nominal,
                                          Se3TrackingErrorT<S>& out) noexcept {
  if (law_status != Status::ok) return law_status;
  return se3_tracking_error(x, d, nominal, out);
}

//! Ξ0 x for Ξ0 = diag(J0, m0 I3).
template <class S>
inline Vec<6, S> se3_apply_inertia(const Se3SpacecraftParamsT<S>& p, const Vec<6, S>& x) noexcept {
  return stack3(p.J_B * x.template head<3>(), p.m * x.template tail<3>());
}

//! Ξ0⁻¹ y for Ξ0 = diag(J0, m0 I3), with the model's J0⁻¹.
template <class S>
inline Vec<6, S> se3_apply_inverse_inertia(const Se3SpacecraftT<S>& model, const Vec<6, S>& y) noexcept {
  return stack3(model.J_inv() * y.template head<3>(), y.template tail<3>() / model.params().m);
}

}  // namespace adcs
