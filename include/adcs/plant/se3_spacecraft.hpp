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
#include <type_traits>

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

//! Configuration and generalised velocity of one rigid spacecraft (chaser or target).   seed 003 eq. (1)
//! Scalar S (issue 19): a float SE(3) law reads its measured state in float. Note what that
//! costs: R_N ≈ 6.8e6 m has a float ulp of 0.5 m and v_B ≈ 7.7 km/s one of 4.9e-4 m/s, so a
//! float state cannot carry a relative position finer than ~0.5 m (docs/TARGET.md).
template <class S = double>
struct Se3SpacecraftStateT {
  Mat<3, 3, S> C_NB = Mat<3, 3, S>::Identity();  //!< [-] spec's C: active rotation body → ECI (v_N = C_NB v_B)
  Vec<3, S> R_N = Vec<3, S>::Zero();             //!< [m] centre-of-mass position, ECI (origin Earth centre)
  Vec<3, S> omega_BN_B = Vec<3, S>::Zero();      //!< [rad/s] ω, body rate w.r.t. ECI, body components
  Vec<3, S> v_B = Vec<3, S>::Zero();             //!< [m/s] v, inertial velocity in body components (Ṙ = C v)

  //! ξ = [ω; v] [rad/s; m/s].   seed 003 eq. (2)
  Vec<6, S> xi() const noexcept {
    return stack3(omega_BN_B, v_B);
  }
  //! Inertial velocity in ECI components V_N = C_NB v_B [m/s].
  Vec<3, S> V_N() const noexcept { return C_NB * v_B; }
  //! The same state in another scalar (each value rounded once; beyond T's range: ±Inf).
  template <class T>
  Se3SpacecraftStateT<T> cast() const noexcept {
    return Se3SpacecraftStateT<T>{scalar_cast<T>(C_NB), scalar_cast<T>(R_N), scalar_cast<T>(omega_BN_B),
                                  scalar_cast<T>(v_B)};
  }
};
using Se3SpacecraftState = Se3SpacecraftStateT<double>;

//! Time derivatives at one state. Ċ = C_NB [ω]× is implied (integrate it on the group, see
//! se3_spacecraft_attitude_step), so it is not stored.
template <class S = double>
struct Se3SpacecraftRatesT {
  Vec<3, S> R_dot_N = Vec<3, S>::Zero();      //!< [m/s] Ṙ = C v, ECI
  Vec<3, S> omega_dot_B = Vec<3, S>::Zero();  //!< [rad/s²] ω̇, body
  Vec<3, S> v_dot_B = Vec<3, S>::Zero();      //!< [m/s²] v̇, body

  //! ξ̇ = [ω̇; v̇].
  Vec<6, S> xi_dot() const noexcept {
    return stack3(omega_dot_B, v_dot_B);
  }
};
using Se3SpacecraftRates = Se3SpacecraftRatesT<double>;

//! Mass properties and environment of one spacecraft. J_B and m have no default (NaN until set:
//! refused; se3_target_params, se3_chaser_nominal_params and se3_chaser_truth_params give seed
//! 003's); the environment defaults to seed 003's Earth constants (GIVEN).
template <class S = double>
struct Se3SpacecraftParamsT {
  Mat<3, 3, S> J_B = Mat<3, 3, S>::Constant(unset_v<S>);  //!< [kg m²] inertia about the centre of mass, body (SPD)
  S m = unset_v<S>;                                       //!< [kg] mass (> 0)
  OrbitEnvironmentParamsT<S> env{};                       //!< Earth constants (μ, J2, R_E)
  //! The same parameters in another scalar (each value rounded once; validated by the model).
  template <class T>
  Se3SpacecraftParamsT<T> cast() const noexcept {
    return Se3SpacecraftParamsT<T>{scalar_cast<T>(J_B), narrow_scalar<T>(m), env.template cast<T>()};
  }
};
using Se3SpacecraftParams = Se3SpacecraftParamsT<double>;

//! Continuous-time SE(3) plant of spec §A.2.2 for one spacecraft. Stateless after construction
//! (J⁻¹ precomputed), so one object serves the chaser truth, the nominal controller model or the
//! target. Se3SpacecraftT<float> is the nominal model of a float law (issue 19).
template <class S = double>
class Se3SpacecraftT {
 public:
  using State = Se3SpacecraftStateT<S>;
  using Rates = Se3SpacecraftRatesT<S>;
  using Params = Se3SpacecraftParamsT<S>;
  using M3 = Mat<3, 3, S>;
  using V3 = Vec<3, S>;
  using V6 = Vec<6, S>;

  //! Validates the parameters: J symmetric positive definite, m > 0, valid environment.
  //! status() says the outcome (the failure hook is called on error).
  explicit Se3SpacecraftT(const Params& p) noexcept : p_(p) {
    const Eigen::LDLT<M3> ldlt(p_.J_B);
    // Relative asymmetry accepted: 1e-12 in double (as before), ~100 ulp in float.
    const S sym_tol = std::is_same_v<S, float> ? S(1e-5) : S(1e-12);
    const bool symmetric = (p_.J_B - p_.J_B.transpose()).norm() <= sym_tol * p_.J_B.norm();
    const bool ok = all_finite(p_.J_B) && symmetric && ldlt.info() == Eigen::Success &&
                    ldlt.isPositive() && (ldlt.vectorD().array() > S(0)).all() &&
                    std::isfinite(p_.m) && p_.m > S(0) && orbit_environment_valid(p_.env);
    // Column-wise vector solves: a matrix right-hand side would pull in Eigen's blocked
    // triangular solver and its (never taken, but linked) heap fallback.
    if (ok) {
      for (int i = 0; i < 3; ++i) J_inv_.col(i) = ldlt.solve(V3::Unit(i));
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
  const M3& J_inv() const noexcept { return J_inv_; }

  //! Ξ = diag(J, m I3) [kg m², kg].
  Mat<6, 6, S> inertia() const noexcept {
    Mat<6, 6, S> Xi = Mat<6, 6, S>::Zero();
    Xi.template topLeftCorner<3, 3>() = p_.J_B;
    Xi.template bottomRightCorner<3, 3>() = p_.m * M3::Identity();
    return Xi;
  }

  //! Gravity-related wrench M_g = [τ_gg; f_g + f_J2] [N m; N], body components. Precondition
  //! ‖R_N‖ ≥ kOrbitMinRadius (derivative() checks it).   spec §A.2.2, seed 003 eq. (5)
  V6 gravity_wrench(const State& x) const noexcept {
    const V3 R_B = x.C_NB.transpose() * x.R_N;  // R_b = Cᵀ R
    return stack3(gravity_gradient_torque_B(p_.J_B, R_B, p_.env.mu),
                  point_mass_gravity_force(p_.m, R_B, p_.env.mu) + j2_force_B(p_.m, x.C_NB, x.R_N, p_.env));
  }

  //! (Ṙ, ω̇, v̇) at state x under the control wrench tau_c = [M_c; F_c] and the disturbance
  //! tau_d = [M_d; F_d] (both [N m; N], body components).   seed 003 eqs. (1)–(5), spec §A.2.2
  //! Returns invalid_parameter if construction failed, non_finite_input for NaN/Inf inputs,
  //! out_of_range when ‖R_N‖ < kOrbitMinRadius or the result overflows; `out` is untouched on
  //! any non-ok status.
  [[nodiscard]] Status derivative(const State& x, const V6& tau_c, const V6& tau_d,
                                  Rates& out) const noexcept {
    if (status_ != Status::ok) return status_;
    if (!all_finite(x.C_NB) || !all_finite(x.R_N) || !all_finite(x.omega_BN_B) ||
        !all_finite(x.v_B) || !all_finite(tau_c) || !all_finite(tau_d)) {
      return Status::non_finite_input;
    }
    if (!(x.R_N.norm() >= S(kOrbitMinRadius))) return Status::out_of_range;
    const V3& w = x.omega_BN_B;
    const V3& v = x.v_B;
    const V6 M_g = gravity_wrench(x);
    const V6 tau = M_g + tau_c + tau_d;
    Rates r;
    r.R_dot_N.noalias() = x.C_NB * v;                                                      // Ṙ = C v
    r.omega_dot_B.noalias() = J_inv_ * (tau.template head<3>() - w.cross(p_.J_B * w));    // J ω̇ = −ω×Jω + …
    r.v_dot_B = tau.template tail<3>() / p_.m - w.cross(v);                                // m v̇ = −m ω×v + …
    if (!all_finite(r.R_dot_N) || !all_finite(r.omega_dot_B) || !all_finite(r.v_dot_B)) {
      return Status::out_of_range;
    }
    out = r;
    return Status::ok;
  }

 private:
  Params p_;
  M3 J_inv_ = M3::Identity();
  Status status_ = Status::ok;
};
using Se3Spacecraft = Se3SpacecraftT<double>;

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
template <class S = double>
struct Se3DesiredStateT {
  Mat<3, 3, S> C_ND = Mat<3, 3, S>::Identity();    //!< [-] C_d = C_o C_χ, desired body → ECI
  Vec<3, S> R_N = Vec<3, S>::Zero();               //!< [m] R_d = R_o + C_o r_χ, ECI
  Vec<3, S> omega_DN_D = Vec<3, S>::Zero();        //!< [rad/s] ω_d = C_χᵀ ω_o
  Vec<3, S> v_D = Vec<3, S>::Zero();               //!< [m/s] v_d = C_χᵀ (v_o + ω_o × r_χ)
  Vec<3, S> omega_dot_D = Vec<3, S>::Zero();       //!< [rad/s²] ω̇_d = C_χᵀ ω̇_o
  Vec<3, S> v_dot_D = Vec<3, S>::Zero();           //!< [m/s²] v̇_d = C_χᵀ (v̇_o + ω̇_o × r_χ)

  //! ξ_d = [ω_d; v_d].
  Vec<6, S> xi() const noexcept {
    return stack3(omega_DN_D, v_D);
  }
  //! ξ̇_d = [ω̇_d; v̇_d].
  Vec<6, S> xi_dot() const noexcept {
    return stack3(omega_dot_D, v_dot_D);
  }
  //! The same desired state in another scalar (each value rounded once; beyond T's range: ±Inf).
  template <class T>
  Se3DesiredStateT<T> cast() const noexcept {
    return Se3DesiredStateT<T>{scalar_cast<T>(C_ND),       scalar_cast<T>(R_N),         scalar_cast<T>(omega_DN_D),
                               scalar_cast<T>(v_D),        scalar_cast<T>(omega_dot_D), scalar_cast<T>(v_dot_D)};
  }
};
using Se3DesiredState = Se3DesiredStateT<double>;

//! Desired configuration from the target state and its rates, for a CONSTANT relative pose
//! χ_d = (C_χ, r_χ) (C_χ: desired chaser body → target body; r_χ [m] in target body):
//!   C_d = C_o C_χ,  R_d = R_o + C_o r_χ,  ξ_d = Ad_{χ_d⁻¹} ξ_o,  ξ̇_d = Ad_{χ_d⁻¹} ξ̇_o
//! with Ad_{χ⁻¹} = [[C_χᵀ, 0], [−C_χᵀ r_χ×, C_χᵀ]] (ξ̇_d has no Ȧd term because χ_d is
//! constant).   spec §A.2.3
template <class S>
inline Se3DesiredStateT<S> se3_desired_state(const Se3SpacecraftStateT<S>& target,
                                             const Se3SpacecraftRatesT<S>& target_rates,
                                             const Mat<3, 3, S>& C_chi, const Vec<3, S>& r_chi) noexcept {
  Se3DesiredStateT<S> d;
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
// Relative poses (the paper's scenario data, Se3ScenarioParams and the initial poses, live with
// the scenarios: src/scenarios/seed003_data.hpp)

//! C_rel = Rz(ψ) Ry(ϑ) Rx(φ) with ACTIVE elementary rotations, zyx = [ψ, ϑ, φ] [rad]: the
//! intrinsic z-y-x sequence, chaser body → target body (spec §A.8 [A]). Equal to the transpose of
//! the passive 3-2-1 DCM R1(φ) R2(ϑ) R3(ψ) of math/euler.hpp.
inline Mat3 euler_zyx_active_dcm(const Vec3& zyx) noexcept {
  return euler321_to_dcm(zyx).transpose();
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

}  // namespace adcs
