#pragma once
// Seed 003's scenario data (spec §A.8): the target orbit and mass properties, the chaser's
// nominal and true mass properties, the disturbance, the actuator limits, the four initial poses
// and the quantizer channels. Paper data, not flight code: it lives with the scenarios (issue 17)
// and is included by the se3-* scenarios, their tests, the benchmarks, the fuzzers and the
// Cortex-M7 replays of the paper's controller. Header-only and heap-free like the flight headers,
// so the target builds can use it.
#include <array>
#include <cmath>

#include "adcs/actuator/quantizer.hpp"
#include "adcs/core/failure_hook.hpp"
#include "adcs/core/status.hpp"
#include "adcs/core/types.hpp"
#include "adcs/plant/orbit_environment.hpp"
#include "adcs/plant/se3_spacecraft.hpp"

namespace adcs {

//! Seed 003 channels (3 torques [N m], then 3 forces [N]), spec §A.8 "Proposed Table 1" [A]:
//! torque ρ 0.3, u_min 1e-3, u_s 0.2, σ 0.1; force ρ 0.5, u_min 1e-3, u_s 2, σ 1.0. With the
//! actuator limits 0.5 N m / 5 N [P] the limits are exact uniform levels (5σ).
inline CompositeQuantizerParams<6> seed003_quantizer_params() noexcept {
  CompositeQuantizerParams<6> p;
  const QuantizerChannelParams torque{0.3, 1e-3, 0.2, 0.1};
  const QuantizerChannelParams force{0.5, 1e-3, 2.0, 1.0};
  for (int i = 0; i < 3; ++i) {
    p.channel[i] = torque;
    p.channel[i + 3] = force;
  }
  return p;
}

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

//! C_rel of a table row (degrees converted to rad).
inline Mat3 se3_relative_attitude(const Se3InitialPose& pose) noexcept {
  return euler_zyx_active_dcm(
      Vec3(pose.euler_zyx_deg[0], pose.euler_zyx_deg[1], pose.euler_zyx_deg[2]) * kSe3RadPerDeg);
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

//! The laws' input at one of the paper's initial poses (state = 0..3 of kSe3InitialPoses), the
//! chaser's twist offset by (d_omega_B, d_v_B) from the target-attached one (so that every term of
//! the laws is active), and the desired state from the target model. Out-of-range state or a
//! rejected target: ok is false and `out` untouched.
[[nodiscard]] inline bool se3_paper_tracking_input(const Se3ScenarioParams& p, int state, const Vec3& d_omega_B,
                                                   const Vec3& d_v_B, Se3SpacecraftState& chaser,
                                                   Se3DesiredState& desired) noexcept {
  if (state < 0 || state >= static_cast<int>(kSe3InitialPoses.size())) return false;
  Se3SpacecraftState t;
  if (se3_target_initial_state(p, t) != Status::ok) return false;
  Se3SpacecraftState c = se3_chaser_initial_state(t, kSe3InitialPoses[static_cast<std::size_t>(state)]);
  c.omega_BN_B += d_omega_B;
  c.v_B += d_v_B;
  Se3DesiredState d;
  if (se3_desired_state(Se3Spacecraft(se3_target_params(p)), t, p, d) != Status::ok) return false;
  chaser = c;
  desired = d;
  return true;
}

}  // namespace adcs
