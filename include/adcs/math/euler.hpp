#pragma once
// Euler angles. Two sequences:
//  - x-y-z (1-2-3) of seed 002 eq. (3): angles theta = [phi (roll), theta (pitch), psi (yaw)],
//    C_BN = R3(psi) R2(theta) R1(phi), theta_dot = F(theta) omega, omega = G(theta) theta_dot.
//  - 3-2-1 (yaw-pitch-roll): angles ypr = [psi (yaw), theta (pitch), phi (roll)] in rotation
//    order, C_BN = R1(phi) R2(theta) R3(psi), ypr_dot = B321(ypr) omega.
// Both are singular at pitch = +-90 deg; the functions that divide by cos(pitch) return a status.
#include <algorithm>

#include "adcs/core/status.hpp"
#include "adcs/core/types.hpp"
#include "adcs/math/so3.hpp"

namespace adcs {

//! Smallest |cos(pitch)| accepted by the kinematic inverses (about 1e-6 deg from gimbal lock).
inline constexpr double kEulerSingularCos = 1e-8;

// ---------------------------------------------------------------------------------------------
// x-y-z sequence, seed 002 eq. (3)

//! C_BN = R3(psi) R2(theta) R1(phi).   seed 002 eq. (3)
inline Mat3 euler123_to_dcm(const Vec3& angles) noexcept {
  return frame_rotation_3(angles(2)) * frame_rotation_2(angles(1)) * frame_rotation_1(angles(0));
}

//! Angles of a DCM, pitch in [-pi/2, pi/2]. At gimbal lock phi + psi is split arbitrarily.
inline Vec3 dcm_to_euler123(const Mat3& C) noexcept {
  const double s_theta = std::clamp(C(2, 0), -1.0, 1.0);
  return Vec3(std::atan2(-C(2, 1), C(2, 2)), std::asin(s_theta), std::atan2(-C(1, 0), C(0, 0)));
}

//! omega = G(theta) theta_dot with G = F^-1; never singular.   seed 002 eq. (3)
inline Mat3 euler123_G(const Vec3& angles) noexcept {
  const double ct = std::cos(angles(1)), st = std::sin(angles(1));
  const double cp = std::cos(angles(2)), sp = std::sin(angles(2));
  Mat3 G;
  G << ct * cp, sp, 0.0,  //
      -ct * sp, cp, 0.0,  //
      st, 0.0, 1.0;
  return G;
}

//! theta_dot = F(theta) omega. Returns Status::singular (F untouched) at |cos(theta)| <
//! kEulerSingularCos, non_finite_input (F untouched) for NaN/Inf angles.   seed 002 eq. (3)
inline Status euler123_F(const Vec3& angles, Mat3& F) noexcept {
  if (!all_finite(angles)) return Status::non_finite_input;
  const double ct = std::cos(angles(1)), st = std::sin(angles(1));
  if (!(std::abs(ct) >= kEulerSingularCos)) return Status::singular;
  const double cp = std::cos(angles(2)), sp = std::sin(angles(2));
  const double sec = 1.0 / ct, tn = st / ct;
  F << cp * sec, -sp * sec, 0.0,  //
      sp, cp, 0.0,                //
      -cp * tn, sp * tn, 1.0;
  return Status::ok;
}

//! d/dt G(theta) along theta_dot.   seed 002 §B.2
inline Mat3 euler123_G_dot(const Vec3& angles, const Vec3& angles_dot) noexcept {
  const double ct = std::cos(angles(1)), st = std::sin(angles(1));
  const double cp = std::cos(angles(2)), sp = std::sin(angles(2));
  const double td = angles_dot(1), pd = angles_dot(2);
  Mat3 Gd;
  Gd << -st * cp * td - ct * sp * pd, cp * pd, 0.0,  //
      st * sp * td - ct * cp * pd, -sp * pd, 0.0,    //
      ct * td, 0.0, 0.0;
  return Gd;
}

// ---------------------------------------------------------------------------------------------
// 3-2-1 sequence (yaw psi, pitch theta, roll phi)

//! C_BN = R1(phi) R2(theta) R3(psi), ypr = [psi, theta, phi].
inline Mat3 euler321_to_dcm(const Vec3& ypr) noexcept {
  return frame_rotation_1(ypr(2)) * frame_rotation_2(ypr(1)) * frame_rotation_3(ypr(0));
}

//! [psi, theta, phi] of a DCM, pitch in [-pi/2, pi/2].
inline Vec3 dcm_to_euler321(const Mat3& C) noexcept {
  const double s_theta = std::clamp(-C(0, 2), -1.0, 1.0);
  return Vec3(std::atan2(C(0, 1), C(0, 0)), std::asin(s_theta), std::atan2(C(1, 2), C(2, 2)));
}

//! omega = G321(ypr) ypr_dot; never singular.
inline Mat3 euler321_G(const Vec3& ypr) noexcept {
  const double ct = std::cos(ypr(1)), st = std::sin(ypr(1));
  const double cf = std::cos(ypr(2)), sf = std::sin(ypr(2));
  Mat3 G;
  G << -st, 0.0, 1.0,  //
      sf * ct, cf, 0.0,  //
      cf * ct, -sf, 0.0;
  return G;
}

//! ypr_dot = F321(ypr) omega (Schaub's B matrix). Status::singular at gimbal lock,
//! non_finite_input for NaN/Inf angles (F untouched in both cases).
inline Status euler321_F(const Vec3& ypr, Mat3& F) noexcept {
  if (!all_finite(ypr)) return Status::non_finite_input;
  const double ct = std::cos(ypr(1)), st = std::sin(ypr(1));
  if (!(std::abs(ct) >= kEulerSingularCos)) return Status::singular;
  const double cf = std::cos(ypr(2)), sf = std::sin(ypr(2));
  F << 0.0, sf, cf,  //
      0.0, cf * ct, -sf * ct,  //
      ct, sf * st, cf * st;
  F /= ct;
  return Status::ok;
}

}  // namespace adcs
