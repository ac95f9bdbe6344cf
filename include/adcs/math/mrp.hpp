#pragma once
// Modified Rodrigues parameters sigma_BN (B relative to N). seed 001 eq. (6) and §A.2.5.
// Invariant after mrp_shadow_switch(): |sigma| <= 1 (the short-rotation set).
#include "adcs/core/status.hpp"
#include "adcs/core/types.hpp"
#include "adcs/math/quaternion.hpp"
#include "adcs/math/so3.hpp"

namespace adcs {

//! C(sigma): DCM from N to B, h_B = C(sigma) H_N.   seed 001 §A.2.5
inline Mat3 mrp_to_dcm(const Vec3& sigma) noexcept {
  const double s2 = sigma.squaredNorm();
  const double d = 1.0 + s2;
  const Mat3 S = skew(sigma);
  return Mat3::Identity() - (4.0 * (1.0 - s2) / (d * d)) * S + (8.0 / (d * d)) * (S * S);
}

//! sigma = v / (1 + w) for a unit quaternion; pass a canonical (w >= 0) one for |sigma| <= 1.
inline Vec3 quat_to_mrp(const QuaternionSF& q) noexcept { return q.vec() / (1.0 + q.w()); }

//! Unit quaternion of an MRP: w = (1 - s^2)/(1 + s^2), v = 2 sigma/(1 + s^2).
inline QuaternionSF mrp_to_quat(const Vec3& sigma) noexcept {
  const double s2 = sigma.squaredNorm();
  const double d = 1.0 + s2;
  const Vec3 v = 2.0 * sigma / d;
  return QuaternionSF::from_scalar_first((1.0 - s2) / d, v(0), v(1), v(2));
}

//! MRP (|sigma| <= 1) of a proper orthonormal DCM.
inline Vec3 dcm_to_mrp(const Mat3& C) noexcept { return quat_to_mrp(dcm_to_quat(C)); }

//! G(sigma) = 1/4 [(1 - s^2) I3 + 2[sigma]x + 2 sigma sigma^T]; sigma_dot = G omega.
//! seed 001 eq. (6)
inline Mat3 mrp_G(const Vec3& sigma) noexcept {
  const double s2 = sigma.squaredNorm();
  return 0.25 * ((1.0 - s2) * Mat3::Identity() + 2.0 * skew(sigma) + 2.0 * sigma * sigma.transpose());
}

//! Closed-form inverse G^-1 = 16 G^T / (1 + s^2)^2 (G^T G = ((1 + s^2)/4)^2 I3, so G is never
//! singular).   seed 001 §A.2.5
inline Mat3 mrp_G_inv(const Vec3& sigma) noexcept {
  const double d = 1.0 + sigma.squaredNorm();
  return (16.0 / (d * d)) * mrp_G(sigma).transpose();
}

//! d/dt G(sigma) = 1/2 ([sigma_dot]x + sigma_dot sigma^T + sigma sigma_dot^T - (sigma_dot^T sigma) I3).
//! seed 001 §A.2.5
inline Mat3 mrp_G_dot(const Vec3& sigma, const Vec3& sigma_dot) noexcept {
  return 0.5 * (skew(sigma_dot) + sigma_dot * sigma.transpose() + sigma * sigma_dot.transpose() -
                sigma_dot.dot(sigma) * Mat3::Identity());
}

//! sigma_dot = G(sigma) omega.
inline Vec3 mrp_rate(const Vec3& sigma, const Vec3& omega) noexcept { return mrp_G(sigma) * omega; }

//! Shadow set sigma^S = -sigma / |sigma|^2 (same attitude, the other rotation sense).
//! The zero MRP has no shadow: returns out_of_range and leaves `shadow` untouched.
inline Status mrp_shadow(const Vec3& sigma, Vec3& shadow) noexcept {
  if (!all_finite(sigma)) return Status::non_finite_input;
  const double s2 = sigma.squaredNorm();
  if (!(s2 > 0.0)) return Status::out_of_range;
  shadow = -sigma / s2;
  return Status::ok;
}

//! Rate of the shadow set: d/dt(-sigma/s^2) = -sigma_dot/s^2 + 2 (sigma^T sigma_dot) sigma / s^4.
//! Precondition: sigma != 0.
inline Vec3 mrp_shadow_rate(const Vec3& sigma, const Vec3& sigma_dot) noexcept {
  const double s2 = sigma.squaredNorm();
  return -sigma_dot / s2 + (2.0 * sigma.dot(sigma_dot) / (s2 * s2)) * sigma;
}

//! Switches sigma to its shadow set when |sigma| > threshold (threshold >= 1; 1 keeps
//! |sigma| <= 1). Returns true if it switched.
inline bool mrp_shadow_switch(Vec3& sigma, double threshold = 1.0) noexcept {
  const double s2 = sigma.squaredNorm();
  if (s2 > threshold * threshold) {
    sigma = -sigma / s2;
    return true;
  }
  return false;
}

//! Relative attitude sigma_BR from sigma_BN and sigma_RN (C_BR = C_BN C_RN^T), short set.
inline Vec3 mrp_subtract(const Vec3& sigma_BN, const Vec3& sigma_RN) noexcept {
  return quat_to_mrp(compose(mrp_to_quat(sigma_BN), mrp_to_quat(sigma_RN).conjugate()).canonical());
}

//! Principal rotation angle [rad] of an MRP: phi = 4 atan(|sigma|), in [0, pi] for |sigma| <= 1.
inline double mrp_principal_angle(const Vec3& sigma) noexcept { return 4.0 * std::atan(sigma.norm()); }

}  // namespace adcs
