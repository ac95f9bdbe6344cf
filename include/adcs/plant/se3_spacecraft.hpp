#pragma once
// Rigid spacecraft on SE(3) in Earth orbit: the chaser and target plants of seed 003 eqs. (1)–(5),
// spec §A.2.2 (Lee & Vukovich 2016; Sun & Huo 2015), the desired configuration of spec §A.2.3 and
// the scenario data of spec §A.8.
//
//   Ċ = C ω×,   Ṙ = C v                                         (kinematics, ġ = g ξ^)
//   J ω̇ = −ω × J ω + τ_gg + M_c + M_d                          (Ξ ξ̇ = ad*_ξ Ξ ξ + M_g + τ_c + τ_d)
//   m v̇ = −m ω × v + f_g + f_J2 + F_c + F_d
//
// State: C = C_NB (active rotation body → ECI, v_N = C_NB v_B), R_N (ECI position of the centre
// of mass), ω = omega_BN_B (body rate w.r.t. ECI, body components) and v = v_B (the INERTIAL
// velocity in body components, ≈7.7 km/s in orbit, not a relative velocity). Generalised velocity
// ξ = [ω; v] and wrenches [torque; force] are always rotational first; Ξ = diag(J, m I3).
// Gravity terms (τ_gg, f_g, f_J2) are in plant/orbit_environment.hpp.
//
// The target is the same model with J_o, m_o and no control or disturbance [P: "the target's
// space disturbances are not considered"]. The desired configuration is g_d = g_o χ_d with a
// constant χ_d = (C_χ, r_χ), so ξ_d = Ad_{χ_d⁻¹} ξ_o and ξ̇_d = Ad_{χ_d⁻¹} ξ̇_o, written here with
// explicit 3 × 3 blocks (no dependency on the SE(3) maths header).
//
// Units: SI throughout (m, m/s, rad, rad/s, kg, kg m², N, N m, s); degrees only in the A.8 table.
#include <array>
#include <cmath>

#include <Eigen/Cholesky>

#include "adcs/core/failure_hook.hpp"
#include "adcs/core/status.hpp"
#include "adcs/core/types.hpp"
#include "adcs/core/validation.hpp"
#include "adcs/math/euler.hpp"
#include "adcs/math/so3.hpp"
#include "adcs/plant/orbit_environment.hpp"

namespace adcs {

//! [rad/deg] degrees appear only in the A.8 table and its inclination.
inline constexpr double kSe3RadPerDeg = 3.14159265358979323846 / 180.0;

// ---------------------------------------------------------------------------------------------
// Plant

//! Configuration and generalised velocity of one rigid spacecraft (chaser or target).
struct Se3SpacecraftState {
  Mat3 C_NB = Mat3::Identity();    //!< [-] spec's C: active rotation body → ECI (v_N = C_NB v_B)
  Vec3 R_N = Vec3::Zero();         //!< [m] centre-of-mass position, ECI (origin Earth centre)
  Vec3 omega_BN_B = Vec3::Zero();  //!< [rad/s] ω, body rate w.r.t. ECI, body components
  Vec3 v_B = Vec3::Zero();         //!< [m/s] v, inertial velocity in body components (Ṙ = C v)

  //! ξ = [ω; v] [rad/s; m/s].
  Vec6 xi() const noexcept {
    return stack3(omega_BN_B, v_B);
  }
  //! Inertial velocity in ECI components V_N = C_NB v_B [m/s].
  Vec3 V_N() const noexcept { return C_NB * v_B; }
};

//! Time derivatives at one state. Ċ = C_NB [ω]× is implied (integrate it on the group, see
//! se3_spacecraft_attitude_step), so it is not stored.
struct Se3SpacecraftRates {
  Vec3 R_dot_N = Vec3::Zero();      //!< [m/s] Ṙ = C v, ECI
  Vec3 omega_dot_B = Vec3::Zero();  //!< [rad/s²] ω̇, body
  Vec3 v_dot_B = Vec3::Zero();      //!< [m/s²] v̇, body

  //! ξ̇ = [ω̇; v̇].
  Vec6 xi_dot() const noexcept {
    return stack3(omega_dot_B, v_dot_B);
  }
};

//! Mass properties and environment of one spacecraft. J_B and m have no default (NaN until set:
//! refused; se3_target_params, se3_chaser_nominal_params and se3_chaser_truth_params give seed
//! 003's); the environment defaults to seed 003's Earth constants (GIVEN).
struct Se3SpacecraftParams {
  Mat3 J_B = Mat3::Constant(kUnset);  //!< [kg m²] inertia about the centre of mass, body (SPD)
  double m = kUnset;                  //!< [kg] mass (> 0)
  OrbitEnvironmentParams env{};    //!< Earth constants (μ, J2, R_E)
};

//! Continuous-time SE(3) plant of spec §A.2.2 for one spacecraft. Stateless after construction
//! (J⁻¹ precomputed), so one object serves the chaser truth, the nominal controller model or the
//! target.
class Se3Spacecraft {
 public:
  using State = Se3SpacecraftState;
  using Rates = Se3SpacecraftRates;
  using Params = Se3SpacecraftParams;

  //! Validates the parameters: J symmetric positive definite, m > 0, valid environment.
  //! status() says the outcome (the failure hook is called on error).
  explicit Se3Spacecraft(const Params& p) noexcept : p_(p) {
    const Eigen::LDLT<Mat3> ldlt(p_.J_B);
    const bool symmetric = (p_.J_B - p_.J_B.transpose()).norm() <= 1e-12 * p_.J_B.norm();
    const bool ok = all_finite(p_.J_B) && symmetric && ldlt.info() == Eigen::Success &&
                    ldlt.isPositive() && (ldlt.vectorD().array() > 0.0).all() &&
                    std::isfinite(p_.m) && p_.m > 0.0 && orbit_environment_valid(p_.env);
    // Column-wise vector solves: a matrix right-hand side would pull in Eigen's blocked
    // triangular solver and its (never taken, but linked) heap fallback.
    if (ok) {
      for (int i = 0; i < 3; ++i) J_inv_.col(i) = ldlt.solve(Vec3::Unit(i));
    }
    status_ = ADCS_CHECK(ok, "Se3Spacecraft: J must be SPD, m > 0, mu > 0, R_E > 0")
                  ? Status::ok
                  : Status::invalid_parameter;
  }

  //! ok, or invalid_parameter: J_B not finite, not symmetric or not positive definite; m not
  //! finite > 0; the environment invalid (orbit_environment_valid). A refused plant answers
  //! invalid_parameter from derivative() with `out` untouched.
  Status status() const noexcept { return status_; }
  const Params& params() const noexcept { return p_; }
  const Mat3& J_inv() const noexcept { return J_inv_; }

  //! Ξ = diag(J, m I3) [kg m², kg].
  Mat6 inertia() const noexcept {
    Mat6 Xi = Mat6::Zero();
    Xi.topLeftCorner<3, 3>() = p_.J_B;
    Xi.bottomRightCorner<3, 3>() = p_.m * Mat3::Identity();
    return Xi;
  }

  //! Gravity-related wrench M_g = [τ_gg; f_g + f_J2] [N m; N], body components. Precondition
  //! ‖R_N‖ ≥ kOrbitMinRadius (derivative() checks it).   spec §A.2.2
  Vec6 gravity_wrench(const State& x) const noexcept {
    const Vec3 R_B = x.C_NB.transpose() * x.R_N;  // R_b = Cᵀ R
    return stack3(gravity_gradient_torque_B(p_.J_B, R_B, p_.env.mu),
                  point_mass_gravity_force(p_.m, R_B, p_.env.mu) + j2_force_B(p_.m, x.C_NB, x.R_N, p_.env));
  }

  //! (Ṙ, ω̇, v̇) at state x under the control wrench tau_c = [M_c; F_c] and the disturbance
  //! tau_d = [M_d; F_d] (both [N m; N], body components).   seed 003 eqs. (1)–(5), spec §A.2.2
  //! Returns invalid_parameter if construction failed, non_finite_input for NaN/Inf inputs,
  //! out_of_range when ‖R_N‖ < kOrbitMinRadius or the result overflows; `out` is untouched on
  //! any non-ok status.
  [[nodiscard]] Status derivative(const State& x, const Vec6& tau_c, const Vec6& tau_d,
                                  Rates& out) const noexcept {
    if (status_ != Status::ok) return status_;
    if (!all_finite(x.C_NB) || !all_finite(x.R_N) || !all_finite(x.omega_BN_B) ||
        !all_finite(x.v_B) || !all_finite(tau_c) || !all_finite(tau_d)) {
      return Status::non_finite_input;
    }
    if (!(x.R_N.norm() >= kOrbitMinRadius)) return Status::out_of_range;
    const Vec3& w = x.omega_BN_B;
    const Vec3& v = x.v_B;
    const Vec6 M_g = gravity_wrench(x);
    const Vec6 tau = M_g + tau_c + tau_d;
    Rates r;
    r.R_dot_N.noalias() = x.C_NB * v;                                            // Ṙ = C v
    r.omega_dot_B.noalias() = J_inv_ * (tau.head<3>() - w.cross(p_.J_B * w));   // J ω̇ = −ω×Jω + …
    r.v_dot_B = tau.tail<3>() / p_.m - w.cross(v);                               // m v̇ = −m ω×v + …
    if (!all_finite(r.R_dot_N) || !all_finite(r.omega_dot_B) || !all_finite(r.v_dot_B)) {
      return Status::out_of_range;
    }
    out = r;
    return Status::ok;
  }

 private:
  Params p_;
  Mat3 J_inv_ = Mat3::Identity();
  Status status_ = Status::ok;
};

//! Lie-group attitude update C_NB ← C_NB exp([Δθ]×) for a body-frame rotation increment Δθ [rad]
//! (e.g. dt·ω̄ of an RK4 step), followed by one symmetric re-orthonormalisation step
//! C ← C (3I − CᵀC)/2: for C = Q(I + E), E symmetric, it leaves Q(I − E²), so rounding drift
//! never accumulates while an exactly orthonormal C passes unchanged to rounding.
inline void se3_spacecraft_attitude_step(Mat3& C_NB, const Vec3& dtheta_B) noexcept {
  const Mat3 C = C_NB * so3_exp(dtheta_B);
  const Mat3 CtC = C.transpose() * C;
  C_NB.noalias() = 0.5 * C * (3.0 * Mat3::Identity() - CtC);
}

// ---------------------------------------------------------------------------------------------
// Desired configuration, spec §A.2.3 (first block)

//! g_d = g_o χ_d and its body velocity and acceleration (frame D = desired chaser body).
struct Se3DesiredState {
  Mat3 C_ND = Mat3::Identity();    //!< [-] C_d = C_o C_χ, desired body → ECI
  Vec3 R_N = Vec3::Zero();         //!< [m] R_d = R_o + C_o r_χ, ECI
  Vec3 omega_DN_D = Vec3::Zero();  //!< [rad/s] ω_d = C_χᵀ ω_o
  Vec3 v_D = Vec3::Zero();         //!< [m/s] v_d = C_χᵀ (v_o + ω_o × r_χ)
  Vec3 omega_dot_D = Vec3::Zero(); //!< [rad/s²] ω̇_d = C_χᵀ ω̇_o
  Vec3 v_dot_D = Vec3::Zero();     //!< [m/s²] v̇_d = C_χᵀ (v̇_o + ω̇_o × r_χ)

  //! ξ_d = [ω_d; v_d].
  Vec6 xi() const noexcept {
    return stack3(omega_DN_D, v_D);
  }
  //! ξ̇_d = [ω̇_d; v̇_d].
  Vec6 xi_dot() const noexcept {
    return stack3(omega_dot_D, v_dot_D);
  }
};

//! Desired configuration from the target state and its rates, for a CONSTANT relative pose
//! χ_d = (C_χ, r_χ) (C_χ: desired chaser body → target body; r_χ [m] in target body):
//!   C_d = C_o C_χ,  R_d = R_o + C_o r_χ,  ξ_d = Ad_{χ_d⁻¹} ξ_o,  ξ̇_d = Ad_{χ_d⁻¹} ξ̇_o
//! with Ad_{χ⁻¹} = [[C_χᵀ, 0], [−C_χᵀ r_χ×, C_χᵀ]] (ξ̇_d has no Ȧd term because χ_d is
//! constant).   spec §A.2.3
inline Se3DesiredState se3_desired_state(const Se3SpacecraftState& target,
                                         const Se3SpacecraftRates& target_rates,
                                         const Mat3& C_chi, const Vec3& r_chi) noexcept {
  Se3DesiredState d;
  d.C_ND.noalias() = target.C_NB * C_chi;
  d.R_N = target.R_N + target.C_NB * r_chi;
  d.omega_DN_D.noalias() = C_chi.transpose() * target.omega_BN_B;
  d.v_D.noalias() = C_chi.transpose() * (target.v_B + target.omega_BN_B.cross(r_chi));
  d.omega_dot_D.noalias() = C_chi.transpose() * target_rates.omega_dot_B;
  d.v_dot_D.noalias() =
      C_chi.transpose() * (target_rates.v_dot_B + target_rates.omega_dot_B.cross(r_chi));
  return d;
}

// ---------------------------------------------------------------------------------------------
// Scenario of seed 003 (spec §A.8)

//! Every scenario value of seed 003 §4 / spec §A.8. GIVEN = stated by the paper; [A] = assumed
//! by the spec (reason in the comment). Controller and quantizer gains live with the controller.
struct Se3ScenarioParams {
  // Target orbit: circular.
  double altitude = 400e3;                //!< [m] GIVEN (400 km)
  double inclination = 45.0 * kSe3RadPerDeg;  //!< [rad] GIVEN (45°)
  double raan = 0.0;                      //!< [rad] [A] lost; 0 puts R_o on ECI x
  double arg_latitude = 0.0;              //!< [rad] [A] lost; 0 gives R_o = a[1,0,0]
  // Target (no uncertainty, no disturbance; body axes = principal axes).
  Mat3 J_o = Vec3(25.0, 22.0, 23.0).asDiagonal();  //!< [kg m²] GIVEN
  double m_o = 100.0;                     //!< [kg] GIVEN
  // Chaser nominal (the controller's Ξ0) and its uncertainty.
  Mat3 J0 = (Mat3() << 25, 1, 0.5, 1, 22, 1.2, 0.5, 1.2, 23).finished();  //!< [kg m²] GIVEN
  double m0 = 105.0;                      //!< [kg] GIVEN
  double dJ_ratio = 0.12;                 //!< [-] GIVEN magnitude: ΔJ = 0.12 J0
  double dm_ratio = 0.03;                 //!< [-] GIVEN magnitude: Δm = 0.03 m0
  int uncertainty_sign = +1;              //!< [-] [A] ±1; text gives magnitudes only. truth =
                                          //!< nominal + s·Δ; −1 is the robustness check (A.10 #5)
  // Desired relative pose χ_d (constant): chaser 5 m behind the target, same attitude.
  Mat3 C_chi = Mat3::Identity();          //!< [-] GIVEN (same attitude as the target)
  Vec3 r_chi = Vec3(-5.0, 0.0, 0.0);      //!< [m] GIVEN, target body frame
  // Disturbance u_d(t) = a [sin w1 t, cos w2 t, −sin w3 t, sin w1 t, cos w2 t, −sin w3 t]ᵀ,
  // torque first. Applied in the chaser body frame [A] (paper defers to its ref. [13]).
  double dist_amplitude = 0.005;          //!< [N m, N] GIVEN
  Vec3 dist_freq = Vec3(0.2, 0.1, 0.3);   //!< [rad/s] GIVEN (sin 0.2t, cos 0.1t, sin 0.3t)
  // Actuators and timing.
  double M_max = 0.5;                     //!< [N m] GIVEN |M_i| ≤ 0.5
  double F_max = 5.0;                     //!< [N] GIVEN |F_i| ≤ 5
  double control_period = 0.125;          //!< [s] GIVEN (8 Hz)
  double horizon = 200.0;                 //!< [s] GIVEN (1600 commands)
  OrbitEnvironmentParams env{};           //!< μ, J2, R_E: GIVEN
};

//! One row of the seed 003 initial-state table (spec §A.8 [P]): successive rotations about the
//! target-body z, y, x axes [deg] and the position [m] in the target body frame. The tabulated
//! ω, v are NOT used (internally inconsistent, spec §A.8 [D]); the velocity is the
//! zero-relative-twist one of se3_chaser_initial_state.
struct Se3InitialPose {
  std::array<double, 3> euler_zyx_deg;  //!< [deg] ψ (about z), ϑ (about y), φ (about x)
  std::array<double, 3> r_rel_T;        //!< [m] chaser position in the target body frame
};

//! The four initial states of seed 003 §4 (GIVEN); kSe3InitialPoses[k − 1] is the paper's state k.
inline constexpr std::array<Se3InitialPose, 4> kSe3InitialPoses{{
    {{80.26, 30.00, -35.26}, {15.0, -10.0, -20.0}},
    {{119.00, 68.910, -44.01}, {20.0, -15.0, -25.0}},
    {{-19.11, 48.59, 139.11}, {25.0, -20.0, -30.0}},
    {{0.49, 3.84, 165.49}, {30.0, -25.0, -35.0}},
}};

//! C_rel = Rz(ψ) Ry(ϑ) Rx(φ) with ACTIVE elementary rotations, zyx = [ψ, ϑ, φ] [rad]: the
//! intrinsic z-y-x sequence, chaser body → target body (spec §A.8 [A]). Equal to the transpose of
//! the passive 3-2-1 DCM R1(φ) R2(ϑ) R3(ψ) of math/euler.hpp.
inline Mat3 euler_zyx_active_dcm(const Vec3& zyx) noexcept {
  return euler321_to_dcm(zyx).transpose();
}

//! C_rel of a table row (degrees converted to rad).
inline Mat3 se3_relative_attitude(const Se3InitialPose& pose) noexcept {
  return euler_zyx_active_dcm(
      Vec3(pose.euler_zyx_deg[0], pose.euler_zyx_deg[1], pose.euler_zyx_deg[2]) * kSe3RadPerDeg);
}

//! Chaser state from the target state, its attitude C_rel (chaser body → target body) and
//! position r_rel_T [m] (target body), with zero relative twist (spec §A.8 [D]):
//!   C = C_o C_rel,  R = R_o + C_o r_rel,  ω = C_relᵀ ω_o,  v = C_relᵀ (v_o + ω_o × r_rel)
//! i.e. ξ = Ad_{χ⁻¹} ξ_o for χ = (C_rel, r_rel): the chaser moves as if rigidly attached to the
//! target, so ξ_e(0) = 0 for any constant χ_d.
inline Se3SpacecraftState se3_chaser_initial_state(const Se3SpacecraftState& target,
                                                   const Mat3& C_rel,
                                                   const Vec3& r_rel_T) noexcept {
  Se3SpacecraftState c;
  c.C_NB.noalias() = target.C_NB * C_rel;
  c.R_N = target.R_N + target.C_NB * r_rel_T;
  c.omega_BN_B.noalias() = C_rel.transpose() * target.omega_BN_B;
  c.v_B.noalias() = C_rel.transpose() * (target.v_B + target.omega_BN_B.cross(r_rel_T));
  return c;
}

//! Same, from a row of kSe3InitialPoses.
inline Se3SpacecraftState se3_chaser_initial_state(const Se3SpacecraftState& target,
                                                   const Se3InitialPose& pose) noexcept {
  return se3_chaser_initial_state(target, se3_relative_attitude(pose),
                                  Vec3(pose.r_rel_T[0], pose.r_rel_T[1], pose.r_rel_T[2]));
}

//! Target initial state: the LVLH frame of the circular orbit (spec §A.8 "Target initial state
//! [A]"): C_o = [x_b y_b z_b], R_o = a[1,0,0] (Ω = u = 0), ω_o = [0, −n, 0], v_o = C_oᵀ V_o =
//! [√(μ/a), 0, 0]. Status as circular_orbit_lvlh (out untouched on failure).
[[nodiscard]] inline Status se3_target_initial_state(const Se3ScenarioParams& p,
                                                     Se3SpacecraftState& out) noexcept {
  CircularOrbitLvlh o;
  const Status s = circular_orbit_lvlh(p.altitude, p.inclination, p.raan, p.arg_latitude, p.env, o);
  if (s != Status::ok) return s;
  out.C_NB = o.C_NL;
  out.R_N = o.R_N;
  out.omega_BN_B = o.omega_LN_L;
  out.v_B = o.V_L;
  return Status::ok;
}

//! Target plant parameters (J_o, m_o; GIVEN).
inline Se3SpacecraftParams se3_target_params(const Se3ScenarioParams& p) noexcept {
  return Se3SpacecraftParams{p.J_o, p.m_o, p.env};
}

//! Chaser nominal parameters (J0, m0): the controller's Ξ0.
inline Se3SpacecraftParams se3_chaser_nominal_params(const Se3ScenarioParams& p) noexcept {
  return Se3SpacecraftParams{p.J0, p.m0, p.env};
}

//! Chaser truth parameters J = J0 (1 + s·ΔJ/J0), m = m0 (1 + s·Δm/m0), s = uncertainty_sign
//! (default +1: J = 1.12 J0, m = 108.15 kg). Returns invalid_parameter (out untouched) unless
//! s = ±1 and both ratios are finite in [0, 1).   spec §A.8, §A.10 #5
[[nodiscard]] inline Status se3_chaser_truth_params(const Se3ScenarioParams& p,
                                                    Se3SpacecraftParams& out) noexcept {
  const bool ok = (p.uncertainty_sign == 1 || p.uncertainty_sign == -1) &&
                  p.dJ_ratio >= 0.0 && p.dJ_ratio < 1.0 && p.dm_ratio >= 0.0 && p.dm_ratio < 1.0;
  if (!ADCS_CHECK(ok, "se3_chaser_truth_params: need uncertainty_sign = +-1, ratios in [0,1)")) {
    return Status::invalid_parameter;
  }
  const double s = static_cast<double>(p.uncertainty_sign);
  out = Se3SpacecraftParams{p.J0 * (1.0 + s * p.dJ_ratio), p.m0 * (1.0 + s * p.dm_ratio), p.env};
  return Status::ok;
}

//! Environmental disturbance on the chaser u_d(t) = [M_d; F_d] [N m; N], chaser body frame [A]:
//!   0.005 [sin 0.2t, cos 0.1t, −sin 0.3t, sin 0.2t, cos 0.1t, −sin 0.3t]ᵀ   (spec §A.8, GIVEN)
inline Vec6 se3_disturbance(double t, const Se3ScenarioParams& p) noexcept {
  const double a = p.dist_amplitude;
  const Vec3 d(a * std::sin(p.dist_freq(0) * t), a * std::cos(p.dist_freq(1) * t),
               -a * std::sin(p.dist_freq(2) * t));
  Vec6 u;
  u << d, d;
  return u;
}

//! Per-channel actuator limits [M_max ×3; F_max ×3] [N m; N] (|M_i| ≤ 0.5, |F_i| ≤ 5, GIVEN).
inline Vec6 se3_actuator_limits(const Se3ScenarioParams& p) noexcept {
  Vec6 l;
  l << Vec3::Constant(p.M_max), Vec3::Constant(p.F_max);
  return l;
}

//! Desired state for the scenario's χ_d, with ξ̇_o from the (known, undisturbed) target model
//! (spec §A.2.4 [A]: the controller's feed-forward). Status as Se3Spacecraft::derivative.
[[nodiscard]] inline Status se3_desired_state(const Se3Spacecraft& target_model,
                                              const Se3SpacecraftState& target,
                                              const Se3ScenarioParams& p,
                                              Se3DesiredState& out) noexcept {
  Se3SpacecraftRates rates;
  const Status s = target_model.derivative(target, Vec6::Zero(), Vec6::Zero(), rates);
  if (s != Status::ok) return s;
  out = se3_desired_state(target, rates, p.C_chi, p.r_chi);
  return Status::ok;
}

}  // namespace adcs
