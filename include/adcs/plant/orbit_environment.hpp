#pragma once
// Earth gravity acting on a rigid spacecraft in orbit, seed 003 eqs. (1)–(5), spec §A.2.2:
//
//   τ_gg = (3μ/r⁵) R_B × (J R_B)                                   gravity-gradient torque [N m]
//   f_g  = −(m μ / r³) R_B                                         point-mass gravity [N]
//   F_J2 = −(3 m μ J2 R_E² / (2 r⁵)) [(1−5Z²/r²)X, (1−5Z²/r²)Y, (3−5Z²/r²)Z]ᵀ   J2 force [N], ECI
//   f_J2 = Cᵀ F_J2                                                 J2 force [N], body
//
// with R_N = [X, Y, Z]ᵀ the centre-of-mass position in ECI (Z = polar axis), r = ‖R_N‖ and
// R_B = Cᵀ R_N the same vector in body components; C = C_NB is the active rotation body → ECI
// (v_N = C_NB v_B). The J2 term is the standard zonal acceleration (Vallado; Schaub & Junkins).
//
// Also the circular reference orbit with its LVLH frame at t = 0 (spec §A.8 "Target initial
// state [A]"), which seeds the target spacecraft of seed 003.
//
// Every function here is defined for r ≥ kOrbitMinRadius; below that (a corrupted state, deep
// inside the Earth) the 1/r⁵ terms would overflow, so the callers that must not fail
// (Se3Spacecraft::derivative) check r first.
#include <cmath>

#include "adcs/core/status.hpp"
#include "adcs/core/types.hpp"

namespace adcs {

//! Smallest orbit radius [m] the gravity callers accept: keeps 1/r⁵ finite for any finite J, m.
//! Any real orbit is six orders of magnitude larger, so this only catches corrupted states.
inline constexpr double kOrbitMinRadius = 1.0;

//! Earth constants of seed 003 (all GIVEN by the paper, spec §A.1 [P]). J2 = 0 turns the J2
//! force off (point-mass gravity only), e.g. for energy-conservation checks. Scalar S (issue 19):
//! the float instance is the nominal model of a float SE(3) law (μ, R_E⁵-sized products such as
//! r⁵ ≈ 1.7e34 m⁵ at 400 km stay inside float's range, 3.4e38).
template <class S = double>
struct OrbitEnvironmentParamsT {
  S mu = S(3.986e14);     //!< [m³/s²] Earth gravitational parameter μ (GIVEN)
  S J2 = S(1.08263e-3);   //!< [-] second zonal harmonic (GIVEN)
  S R_E = S(6378e3);      //!< [m] Earth equatorial radius (GIVEN)
  //! The same constants in another scalar (each rounded once).
  template <class T>
  OrbitEnvironmentParamsT<T> cast() const noexcept {
    return OrbitEnvironmentParamsT<T>{narrow_scalar<T>(mu), narrow_scalar<T>(J2), narrow_scalar<T>(R_E)};
  }
};
using OrbitEnvironmentParams = OrbitEnvironmentParamsT<double>;

//! True when μ > 0, R_E > 0 and J2 finite (J2 may be 0 or of either sign).
template <class S>
inline bool orbit_environment_valid(const OrbitEnvironmentParamsT<S>& env) noexcept {
  return std::isfinite(env.mu) && env.mu > S(0) && std::isfinite(env.R_E) && env.R_E > S(0) &&
         std::isfinite(env.J2);
}

//! Gravity-gradient torque τ_gg = (3μ/r⁵) R_B × (J_B R_B) [N m], body components, from the
//! position R_B [m] in body components (r = ‖R_B‖ ≥ kOrbitMinRadius).   spec §A.2.2
//! Zero when R_B lies along a principal axis of J_B (J R_B ∥ R_B).
template <class S>
inline Vec<3, S> gravity_gradient_torque_B(const Mat<3, 3, S>& J_B, const Vec<3, S>& R_B, identity_t<S> mu) noexcept {
  const S r2 = R_B.squaredNorm();
  const S r5 = r2 * r2 * std::sqrt(r2);
  return (S(3) * mu / r5) * R_B.cross(J_B * R_B);
}

//! Point-mass gravity force f_g = −(m μ / r³) R [N], in the components of R (body: R_B gives the
//! spec's f_g; ECI: R_N gives F_g).   spec §A.2.2
template <class S>
inline Vec<3, S> point_mass_gravity_force(identity_t<S> m, const Vec<3, S>& R, identity_t<S> mu) noexcept {
  const S r2 = R.squaredNorm();
  return (-m * mu / (r2 * std::sqrt(r2))) * R;
}

//! J2 force F_J2 [N] in ECI components, from the ECI position R_N [m] (Z = polar axis).
//! At Z = 0 it is radial, inward, of magnitude (3/2) J2 (R_E/r)² m μ / r².   spec §A.2.2
template <class S>
inline Vec<3, S> j2_force_N(identity_t<S> m, const Vec<3, S>& R_N, const OrbitEnvironmentParamsT<S>& env) noexcept {
  const S r2 = R_N.squaredNorm();
  const S r5 = r2 * r2 * std::sqrt(r2);
  const S k = S(-1.5) * m * env.mu * env.J2 * env.R_E * env.R_E / r5;
  const S z2 = S(5) * R_N(2) * R_N(2) / r2;  // 5 Z²/r²
  return Vec<3, S>(k * (S(1) - z2) * R_N(0), k * (S(1) - z2) * R_N(1), k * (S(3) - z2) * R_N(2));
}

//! J2 force in body components f_J2 = C_NBᵀ F_J2 [N].   spec §A.2.2
template <class S>
inline Vec<3, S> j2_force_B(identity_t<S> m, const Mat<3, 3, S>& C_NB, const Vec<3, S>& R_N,
                            const OrbitEnvironmentParamsT<S>& env) noexcept {
  return C_NB.transpose() * j2_force_N(m, R_N, env);
}

//! Specific two-body orbital energy ε = ½‖V‖² − μ/r [J/kg] (frame-independent norms; V is the
//! inertial velocity, e.g. C_NB v_B). Conserved under point-mass gravity alone.
inline double specific_orbital_energy(const Vec3& R, const Vec3& V, double mu) noexcept {
  return 0.5 * V.squaredNorm() - mu / R.norm();
}

//! A circular orbit at t = 0 and its LVLH frame, used as the seed 003 target's initial state.
//! LVLH here (spec §A.8 [A]): x_b = V̂ (along-track), z_b = −R̂ (nadir), y_b = z_b × x_b
//! (= −orbit normal), so the frame rotates at ω = [0, −n, 0]ᵀ in its own components.
struct CircularOrbitLvlh {
  double a = 0.0;                   //!< [m] semi-major axis = radius
  double n = 0.0;                   //!< [rad/s] mean motion √(μ/a³)
  double speed = 0.0;               //!< [m/s] circular speed √(μ/a)
  Vec3 R_N = Vec3::Zero();          //!< [m] position, ECI
  Vec3 V_N = Vec3::Zero();          //!< [m/s] inertial velocity, ECI
  Mat3 C_NL = Mat3::Identity();     //!< [-] active rotation LVLH → ECI, columns [x_b y_b z_b]
  Vec3 omega_LN_L = Vec3::Zero();   //!< [rad/s] LVLH rate w.r.t. ECI, LVLH components [0,−n,0]
  Vec3 V_L = Vec3::Zero();          //!< [m/s] inertial velocity in LVLH components [‖V‖,0,0]
};

//! Circular orbit of altitude `altitude` [m] above R_E, inclination `inclination` [rad], RAAN
//! `raan` [rad] and argument of latitude `arg_latitude` [rad] at t = 0:
//!   R_N = a Rz(Ω) Rx(i) [cos u, sin u, 0]ᵀ,  V_N = √(μ/a) Rz(Ω) Rx(i) [−sin u, cos u, 0]ᵀ
//! (active rotations), which for Ω = u = 0 is the spec's R_o = a[1,0,0], V_o = √(μ/a)[0, cos i,
//! sin i] (spec §A.8 [A]). Returns invalid_parameter (out untouched) for an invalid environment,
//! non_finite_input for NaN/Inf angles or altitude, out_of_range when a < kOrbitMinRadius.
[[nodiscard]] inline Status circular_orbit_lvlh(double altitude, double inclination, double raan,
                                                double arg_latitude,
                                                const OrbitEnvironmentParams& env,
                                                CircularOrbitLvlh& out) noexcept {
  if (!orbit_environment_valid(env)) return Status::invalid_parameter;
  if (!std::isfinite(altitude) || !std::isfinite(inclination) || !std::isfinite(raan) ||
      !std::isfinite(arg_latitude)) {
    return Status::non_finite_input;
  }
  const double a = env.R_E + altitude;
  if (!(a >= kOrbitMinRadius)) return Status::out_of_range;
  CircularOrbitLvlh o;
  o.a = a;
  o.speed = std::sqrt(env.mu / a);
  o.n = o.speed / a;  // √(μ/a³)
  const double ci = std::cos(inclination), si = std::sin(inclination);
  const double cO = std::cos(raan), sO = std::sin(raan);
  const double cu = std::cos(arg_latitude), su = std::sin(arg_latitude);
  // In-plane unit vectors after Rx(i), then Rz(Ω) (both active).
  const Vec3 p_i(cu, ci * su, si * su);    // Rx(i) [cos u, sin u, 0]
  const Vec3 q_i(-su, ci * cu, si * cu);   // Rx(i) [−sin u, cos u, 0]
  const Vec3 r_hat(cO * p_i(0) - sO * p_i(1), sO * p_i(0) + cO * p_i(1), p_i(2));
  const Vec3 t_hat(cO * q_i(0) - sO * q_i(1), sO * q_i(0) + cO * q_i(1), q_i(2));
  o.R_N = a * r_hat;
  o.V_N = o.speed * t_hat;
  const Vec3 x_b = t_hat;             // along-track (V̂ for a circular orbit)
  const Vec3 z_b = -r_hat;            // nadir
  const Vec3 y_b = z_b.cross(x_b);    // −orbit normal
  o.C_NL.col(0) = x_b;
  o.C_NL.col(1) = y_b;
  o.C_NL.col(2) = z_b;
  o.omega_LN_L = Vec3(0.0, -o.n, 0.0);  // the frame turns about the orbit normal = −y_b
  o.V_L = o.C_NL.transpose() * o.V_N;   // = [speed, 0, 0]
  out = o;
  return Status::ok;
}

}  // namespace adcs
