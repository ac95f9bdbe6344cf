#pragma once
// Euler angles. Two sequences:
//  - x-y-z (1-2-3) of seed 002 eq. (3): angles theta = [phi (roll), theta (pitch), psi (yaw)],
//    C_BN = R3(psi) R2(theta) R1(phi), theta_dot = F(theta) omega, omega = G(theta) theta_dot.
//  - 3-2-1 (yaw-pitch-roll): angles ypr = [psi (yaw), theta (pitch), phi (roll)] in rotation
//    order, C_BN = R1(phi) R2(theta) R3(psi), ypr_dot = B321(ypr) omega.
// Both are singular at pitch = +-90 deg; the functions that divide by cos(pitch) return a status.
#include <algorithm>
#include <cmath>

#include <type_traits>

#include "adcs/core/status.hpp"
#include "adcs/core/types.hpp"
#include "adcs/math/so3.hpp"

namespace adcs {

//! Smallest |cos(pitch)| accepted by the kinematic inverses (about 1e-6 deg from gimbal lock).
inline constexpr double kEulerSingularCos = 1e-8;
//! The same in the scalar S. In float the angle nearest 90° is 4.4e-8 rad from it (spacing 1.2e-7),
//! so 1e-8 would never trip and sec θ would reach 2e7: 1e-6 (~8 spacings, ~6e-5 deg) instead.
//! Ours (issue 19).
template <class S>
inline constexpr S euler_singular_cos_v = std::is_same_v<S, double> ? S(kEulerSingularCos) : S(1e-6);

// ---------------------------------------------------------------------------------------------
// x-y-z sequence, seed 002 eq. (3)

//! C_BN = R3(psi) R2(theta) R1(phi).   seed 002 eq. (3)
template <class S>
inline Mat<3, 3, S> euler123_to_dcm(const Vec<3, S>& angles) noexcept {
  return frame_rotation_3(angles(2)) * frame_rotation_2(angles(1)) * frame_rotation_1(angles(0));
}

//! Angles of a DCM, pitch in [-pi/2, pi/2]. At gimbal lock phi + psi is split arbitrarily.
template <class S>
inline Vec<3, S> dcm_to_euler123(const Mat<3, 3, S>& C) noexcept {
  const S s_theta = std::clamp(C(2, 0), S(-1), S(1));
  return Vec<3, S>(std::atan2(-C(2, 1), C(2, 2)), std::asin(s_theta), std::atan2(-C(1, 0), C(0, 0)));
}

//! omega = G(theta) theta_dot with G = F^-1; never singular.   seed 002 eq. (3)
template <class S>
inline Mat<3, 3, S> euler123_G(const Vec<3, S>& angles) noexcept {
  const S ct = std::cos(angles(1)), st = std::sin(angles(1));
  const S cp = std::cos(angles(2)), sp = std::sin(angles(2));
  Mat<3, 3, S> G;
  G << ct * cp, sp, S(0),  //
      -ct * sp, cp, S(0),  //
      st, S(0), S(1);
  return G;
}

//! theta_dot = F(theta) omega. Returns Status::singular (F untouched) at |cos(theta)| <
//! euler_singular_cos_v<S>, non_finite_input (F untouched) for NaN/Inf angles.   seed 002 eq. (3)
template <class S>
inline Status euler123_F(const identity_t<Vec<3, S>>& angles, Mat<3, 3, S>& F) noexcept {
  if (!all_finite(angles)) return Status::non_finite_input;
  const S ct = std::cos(angles(1)), st = std::sin(angles(1));
  if (!(std::abs(ct) >= euler_singular_cos_v<S>)) return Status::singular;
  const S cp = std::cos(angles(2)), sp = std::sin(angles(2));
  const S sec = S(1) / ct, tn = st / ct;
  F << cp * sec, -sp * sec, S(0),  //
      sp, cp, S(0),                //
      -cp * tn, sp * tn, S(1);
  return Status::ok;
}

//! d/dt G(theta) along theta_dot.   seed 002 §B.2
template <class S>
inline Mat<3, 3, S> euler123_G_dot(const Vec<3, S>& angles, const Vec<3, S>& angles_dot) noexcept {
  const S ct = std::cos(angles(1)), st = std::sin(angles(1));
  const S cp = std::cos(angles(2)), sp = std::sin(angles(2));
  const S td = angles_dot(1), pd = angles_dot(2);
  Mat<3, 3, S> Gd;
  Gd << -st * cp * td - ct * sp * pd, cp * pd, S(0),  //
      st * sp * td - ct * cp * pd, -sp * pd, S(0),    //
      ct * td, S(0), S(0);
  return Gd;
}

// ---------------------------------------------------------------------------------------------
// 3-2-1 sequence (yaw psi, pitch theta, roll phi)

//! C_BN = R1(phi) R2(theta) R3(psi), ypr = [psi, theta, phi].
template <class S>
inline Mat<3, 3, S> euler321_to_dcm(const Vec<3, S>& ypr) noexcept {
  return frame_rotation_1(ypr(2)) * frame_rotation_2(ypr(1)) * frame_rotation_3(ypr(0));
}

//! [psi, theta, phi] of a DCM, pitch in [-pi/2, pi/2].
template <class S>
inline Vec<3, S> dcm_to_euler321(const Mat<3, 3, S>& C) noexcept {
  const S s_theta = std::clamp(S(-C(0, 2)), S(-1), S(1));
  return Vec<3, S>(std::atan2(C(0, 1), C(0, 0)), std::asin(s_theta), std::atan2(C(1, 2), C(2, 2)));
}

//! omega = G321(ypr) ypr_dot; never singular.
template <class S>
inline Mat<3, 3, S> euler321_G(const Vec<3, S>& ypr) noexcept {
  const S ct = std::cos(ypr(1)), st = std::sin(ypr(1));
  const S cf = std::cos(ypr(2)), sf = std::sin(ypr(2));
  Mat<3, 3, S> G;
  G << -st, S(0), S(1),  //
      sf * ct, cf, S(0),  //
      cf * ct, -sf, S(0);
  return G;
}

//! ypr_dot = F321(ypr) omega (Schaub's B matrix). Status::singular at gimbal lock,
//! non_finite_input for NaN/Inf angles (F untouched in both cases).
template <class S>
inline Status euler321_F(const identity_t<Vec<3, S>>& ypr, Mat<3, 3, S>& F) noexcept {
  if (!all_finite(ypr)) return Status::non_finite_input;
  const S ct = std::cos(ypr(1)), st = std::sin(ypr(1));
  if (!(std::abs(ct) >= euler_singular_cos_v<S>)) return Status::singular;
  const S cf = std::cos(ypr(2)), sf = std::sin(ypr(2));
  F << S(0), sf, cf,  //
      S(0), cf * ct, -sf * ct,  //
      ct, sf * st, cf * st;
  F /= ct;
  return Status::ok;
}

// Expression arguments (core/types.hpp).
ADCS_ACCEPT_EXPRESSIONS_1(euler123_to_dcm)
ADCS_ACCEPT_EXPRESSIONS_1(dcm_to_euler123)
ADCS_ACCEPT_EXPRESSIONS_1(euler123_G)
ADCS_ACCEPT_EXPRESSIONS_1(euler321_to_dcm)
ADCS_ACCEPT_EXPRESSIONS_1(dcm_to_euler321)
ADCS_ACCEPT_EXPRESSIONS_1(euler321_G)
ADCS_ACCEPT_EXPRESSIONS_2(euler123_G_dot)

}  // namespace adcs
