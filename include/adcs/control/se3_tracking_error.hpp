#pragma once
// The SE(3) tracking error that both seed 003 laws (prescribed-time backstepping and the FTSMC
// baseline) act on, spec §A.2.3-§A.2.4 (seed 003 eqs. (6)-(11)):
//
//   g_e = g_d⁻¹ g:  C_e = C_dᵀ C,  R_e = C_dᵀ (R − R_d)
//   ξ_e = ξ − Ad_{g_e⁻¹} ξ_d,  η = [θ; β] = log(g_e)^∨,  η̇ = G(η) ξ_e                   (8)
//   ξ̇_e = F0 + Ξ0⁻¹ u_c + d,
//   F0 = Ξ0⁻¹ (ad*_ξ Ξ0 ξ + M_g(J0, m0)) + ad_{ξ_e} Ad_{g_e⁻¹} ξ_d − Ad_{g_e⁻¹} ξ̇_d         (11)
//
// with the nominal inertia Ξ0 = diag(J0, m0 I3) and the gravity wrench of the nominal model at
// the chaser's pose. Also G⁻¹ and Ġ ξ_e (the derivative of η ↦ G(η) ξ_e along η̇), which both
// laws need. Ordering [rotational; translational]; body components; SI.
#include "adcs/core/status.hpp"
#include "adcs/core/types.hpp"
#include "adcs/math/se3.hpp"
#include "adcs/plant/se3_spacecraft.hpp"

namespace adcs {

struct Se3TrackingError {
  Vec6 eta = Vec6::Zero();         //!< η = [θ; β] [rad; m]
  Vec6 xi_e = Vec6::Zero();        //!< ξ_e = [ω_e; v_e] [rad/s; m/s], body
  Vec6 eta_dot = Vec6::Zero();     //!< η̇ = G(η) ξ_e
  Mat6 G = Mat6::Identity();       //!< G(η)
  Mat6 G_inv = Mat6::Identity();   //!< G(η)⁻¹
  Vec6 G_dot_xi_e = Vec6::Zero();  //!< Ġ ξ_e along η̇
  Vec6 F0 = Vec6::Zero();          //!< nominal drift of ξ_e (11) [rad/s²; m/s²]
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
  Se3TrackingError e;
  Se3 g_e;
  g_e.C = d.C_ND.transpose() * x.C_NB;             // C_e = C_dᵀ C
  g_e.R = d.C_ND.transpose() * (x.R_N - d.R_N);    // R_e = C_dᵀ (R − R_d)
  const Mat6 Ad_inv = se3_Ad_inv(g_e);
  const Vec6 xi_d_e = Ad_inv * d.xi();             // Ad_{g_e⁻¹} ξ_d
  Vec6 xi;
  xi << x.omega_BN_B, x.v_B;
  e.xi_e = xi - xi_d_e;                            // spec §A.2.3
  e.eta = se3_log(g_e);
  e.G = se3_G(e.eta);
  e.G_inv = se3_G_inv(e.eta);
  e.eta_dot = e.G * e.xi_e;                        // (8)
  e.G_dot_xi_e = se3_G_dot_xi(e.eta, e.eta_dot, e.xi_e);
  const Se3SpacecraftParams& p0 = nominal.params();
  const Vec3& w = x.omega_BN_B;
  Vec6 rhs = nominal.gravity_wrench(x);            // M_g(J0, m0)
  rhs.head<3>() -= w.cross(p0.J_B * w);            // ad*_ξ Ξ0 ξ = [−ω×J0ω; −m0 ω×v]
  rhs.tail<3>() -= p0.m * w.cross(x.v_B);
  e.F0.head<3>() = nominal.J_inv() * rhs.head<3>();
  e.F0.tail<3>() = rhs.tail<3>() / p0.m;
  e.F0 += se3_ad(e.xi_e) * xi_d_e - Ad_inv * d.xi_dot();  // (11)
  if (!all_finite(e.eta) || !all_finite(e.G) || !all_finite(e.G_inv) || !all_finite(e.G_dot_xi_e) ||
      !all_finite(e.F0))
    return Status::out_of_range;
  out = e;
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
  Vec6 y;
  y << p.J_B * x.head<3>(), p.m * x.tail<3>();
  return y;
}

//! Ξ0⁻¹ y for Ξ0 = diag(J0, m0 I3), with the model's J0⁻¹.
inline Vec6 se3_apply_inverse_inertia(const Se3Spacecraft& model, const Vec6& y) noexcept {
  Vec6 x;
  x << model.J_inv() * y.head<3>(), y.tail<3>() / model.params().m;
  return x;
}

}  // namespace adcs
