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

//! What both SE(3) laws read: the chaser's measured state and the desired state.
struct Se3TrackingInput {
  Se3SpacecraftState state{};   //!< chaser C_NB, R_N, ω_BN_B, v_B
  Se3DesiredState desired{};    //!< C_ND, R_N, ω_DN_D, v_D and their rates
};

//! Filled by se3_tracking_error(). Like an Eigen matrix, a default-constructed one is
//! uninitialised: both laws make one per control step, and zeroing its ~100 doubles first cost
//! memset calls on the Cortex-M7 (issue 7 budget).
struct Se3TrackingError {
  Vec6 eta;         //!< η = [θ; β] [rad; m]
  Vec6 xi_e;        //!< ξ_e = [ω_e; v_e] [rad/s; m/s], body
  Vec6 eta_dot;     //!< η̇ = G(η) ξ_e
  Se3GBlocks G;     //!< G(η) and G(η)⁻¹ as blocks (G.times, G.inverse_times, …)
  Vec6 G_dot_xi_e;  //!< Ġ ξ_e along η̇
  Vec6 F0;          //!< nominal drift of ξ_e (11) [rad/s²; m/s²]
};

//! The tracking error of the chaser state x w.r.t. the desired state d under the nominal model
//! (J0, m0). non_finite_input for NaN/Inf inputs, out_of_range if the model rejects the pose or
//! a result is not finite; `out` is untouched unless ok.
[[nodiscard]] inline Status se3_tracking_error(const Se3SpacecraftState& x, const Se3DesiredState& d,
                                               const Se3Spacecraft& nominal, Se3TrackingError& out) noexcept {
  if (nominal.status() != Status::ok) return nominal.status();
  if (!all_finite(x.C_NB) || !all_finite(x.R_N) || !all_finite(x.omega_BN_B) || !all_finite(x.v_B) ||
      !all_finite(d.C_ND) || !all_finite(d.R_N) || !all_finite(d.xi()) || !all_finite(d.xi_dot()))
    return Status::non_finite_input;
  if (!(x.R_N.norm() >= kOrbitMinRadius)) return Status::out_of_range;
  // Locals, not a Se3TrackingError: its zero-initialised members cost memset calls on the
  // Cortex-M7 (issue 7 budget), and `out` is written only when everything is finite.
  Se3 g_e;
  g_e.C = d.C_ND.transpose() * x.C_NB;             // C_e = C_dᵀ C
  g_e.R = d.C_ND.transpose() * (x.R_N - d.R_N);    // R_e = C_dᵀ (R − R_d)
  const Vec6 xi_d_e = se3_Ad_inv_times(g_e, d.xi());  // Ad_{g_e⁻¹} ξ_d
  const Vec6 xi_e = x.xi() - xi_d_e;               // spec §A.2.3, seed 003 eq. (6)
  // η = log(g_e)^∨, G, G⁻¹, η̇ = G ξ_e (8) and Ġ ξ_e in one pass (shared coefficients).
  const Se3ErrorKinematics k = se3_error_kinematics(g_e, xi_e);
  const Se3SpacecraftParams& p0 = nominal.params();
  const Vec3& w = x.omega_BN_B;
  Vec6 rhs = nominal.gravity_wrench(x);            // M_g(J0, m0)
  rhs.head<3>() -= w.cross(p0.J_B * w);            // ad*_ξ Ξ0 ξ = [−ω×J0ω; −m0 ω×v]
  rhs.tail<3>() -= p0.m * w.cross(x.v_B);
  Vec6 F0 = stack3(nominal.J_inv() * rhs.head<3>(), rhs.tail<3>() / p0.m);
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
[[nodiscard]] inline Status se3_law_error(Status law_status, const Se3SpacecraftState& x, const Se3DesiredState& d,
                                          const Se3Spacecraft& nominal, Se3TrackingError& out) noexcept {
  if (law_status != Status::ok) return law_status;
  return se3_tracking_error(x, d, nominal, out);
}

//! Ξ0 x for Ξ0 = diag(J0, m0 I3).
inline Vec6 se3_apply_inertia(const Se3SpacecraftParams& p, const Vec6& x) noexcept {
  return stack3(p.J_B * x.head<3>(), p.m * x.tail<3>());
}

//! Ξ0⁻¹ y for Ξ0 = diag(J0, m0 I3), with the model's J0⁻¹.
inline Vec6 se3_apply_inverse_inertia(const Se3Spacecraft& model, const Vec6& y) noexcept {
  return stack3(model.J_inv() * y.head<3>(), y.tail<3>() / model.params().m);
}

}  // namespace adcs
