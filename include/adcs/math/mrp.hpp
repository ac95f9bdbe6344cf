#pragma once
// Modified Rodrigues parameters sigma_BN (B relative to N). seed 001 eq. (6) and §A.2.5.
// Invariant after mrp_shadow_switch(): |sigma| <= 1 (the short-rotation set).
#include <cmath>

#include "adcs/core/status.hpp"
#include "adcs/core/types.hpp"
#include "adcs/math/quaternion.hpp"
#include "adcs/math/so3.hpp"

namespace adcs {

//! C(sigma): DCM from N to B, h_B = C(sigma) H_N.   seed 001 §A.2.5
template <class S>
inline Mat<3, 3, S> mrp_to_dcm(const Vec<3, S>& sigma) noexcept {
  const S s2 = sigma.squaredNorm();
  const S d = S(1) + s2;
  const Mat<3, 3, S> K = skew(sigma);
  return Mat<3, 3, S>::Identity() - (S(4) * (S(1) - s2) / (d * d)) * K + (S(8) / (d * d)) * (K * K);
}

//! sigma = v / (1 + w) for a unit quaternion; pass a canonical (w >= 0) one for |sigma| <= 1.
template <class S>
inline Vec<3, S> quat_to_mrp(const QuaternionSFT<S>& q) noexcept {
  return q.vec() / (S(1) + q.w());
}

//! Unit quaternion of an MRP: w = (1 - s^2)/(1 + s^2), v = 2 sigma/(1 + s^2).
template <class S>
inline QuaternionSFT<S> mrp_to_quat(const Vec<3, S>& sigma) noexcept {
  const S s2 = sigma.squaredNorm();
  const S d = S(1) + s2;
  const Vec<3, S> v = S(2) * sigma / d;
  return QuaternionSFT<S>::from_scalar_first((S(1) - s2) / d, v(0), v(1), v(2));
}

//! MRP (|sigma| <= 1) of a proper orthonormal DCM.
template <class S>
inline Vec<3, S> dcm_to_mrp(const Mat<3, 3, S>& C) noexcept {
  return quat_to_mrp(dcm_to_quat(C));
}

//! G(sigma) = 1/4 [(1 - s^2) I3 + 2[sigma]x + 2 sigma sigma^T]; sigma_dot = G omega.
//! seed 001 eq. (6)
template <class S>
inline Mat<3, 3, S> mrp_G(const Vec<3, S>& sigma) noexcept {
  const S s2 = sigma.squaredNorm();
  return S(0.25) *
         ((S(1) - s2) * Mat<3, 3, S>::Identity() + S(2) * skew(sigma) + S(2) * sigma * sigma.transpose());
}

//! Closed-form inverse G^-1 = 16 G^T / (1 + s^2)^2 (G^T G = ((1 + s^2)/4)^2 I3, so G is never
//! singular).   seed 001 §A.2.5
template <class S>
inline Mat<3, 3, S> mrp_G_inv(const Vec<3, S>& sigma) noexcept {
  const S d = S(1) + sigma.squaredNorm();
  return (S(16) / (d * d)) * mrp_G(sigma).transpose();
}

//! d/dt G(sigma) = 1/2 ([sigma_dot]x + sigma_dot sigma^T + sigma sigma_dot^T - (sigma_dot^T sigma) I3).
//! seed 001 §A.2.5
template <class S>
inline Mat<3, 3, S> mrp_G_dot(const Vec<3, S>& sigma, const Vec<3, S>& sigma_dot) noexcept {
  return S(0.5) * (skew(sigma_dot) + sigma_dot * sigma.transpose() + sigma * sigma_dot.transpose() -
                   sigma_dot.dot(sigma) * Mat<3, 3, S>::Identity());
}

//! sigma_dot = G(sigma) omega.
template <class S>
inline Vec<3, S> mrp_rate(const Vec<3, S>& sigma, const Vec<3, S>& omega) noexcept {
  return mrp_G(sigma) * omega;
}

//! Shadow set sigma^S = -sigma / |sigma|^2 (same attitude, the other rotation sense).
//! The zero MRP has no shadow: returns out_of_range and leaves `shadow` untouched.
template <class S>
inline Status mrp_shadow(const identity_t<Vec<3, S>>& sigma, Vec<3, S>& shadow) noexcept {
  if (!all_finite(sigma)) return Status::non_finite_input;
  const S s2 = sigma.squaredNorm();
  if (!(s2 > S(0))) return Status::out_of_range;
  shadow = -sigma / s2;
  return Status::ok;
}

//! Rate of the shadow set: d/dt(-sigma/s^2) = -sigma_dot/s^2 + 2 (sigma^T sigma_dot) sigma / s^4.
//! Precondition: sigma != 0.
template <class S>
inline Vec<3, S> mrp_shadow_rate(const Vec<3, S>& sigma, const Vec<3, S>& sigma_dot) noexcept {
  const S s2 = sigma.squaredNorm();
  return -sigma_dot / s2 + (S(2) * sigma.dot(sigma_dot) / (s2 * s2)) * sigma;
}

//! Switches sigma to its shadow set when |sigma| > threshold (threshold >= 1; 1 keeps
//! |sigma| <= 1). Returns true if it switched.
template <class S>
inline bool mrp_shadow_switch(Vec<3, S>& sigma, identity_t<S> threshold = S(1)) noexcept {
  const S s2 = sigma.squaredNorm();
  if (s2 > threshold * threshold) {
    sigma = -sigma / s2;
    return true;
  }
  return false;
}

//! Relative attitude sigma_BR from sigma_BN and sigma_RN (C_BR = C_BN C_RN^T), short set.
template <class S>
inline Vec<3, S> mrp_subtract(const Vec<3, S>& sigma_BN, const Vec<3, S>& sigma_RN) noexcept {
  return quat_to_mrp(compose(mrp_to_quat(sigma_BN), mrp_to_quat(sigma_RN).conjugate()).canonical());
}

//! Principal rotation angle [rad] of an MRP: phi = 4 atan(|sigma|), in [0, pi] for |sigma| <= 1.
template <class S>
inline S mrp_principal_angle(const Vec<3, S>& sigma) noexcept {
  return S(4) * std::atan(sigma.norm());
}

// Expression arguments (core/types.hpp).
ADCS_ACCEPT_EXPRESSIONS_1(mrp_to_dcm)
ADCS_ACCEPT_EXPRESSIONS_1(mrp_to_quat)
ADCS_ACCEPT_EXPRESSIONS_1(dcm_to_mrp)
ADCS_ACCEPT_EXPRESSIONS_1(mrp_G)
ADCS_ACCEPT_EXPRESSIONS_1(mrp_G_inv)
ADCS_ACCEPT_EXPRESSIONS_1(mrp_principal_angle)
ADCS_ACCEPT_EXPRESSIONS_2(mrp_G_dot)
ADCS_ACCEPT_EXPRESSIONS_2(mrp_rate)
ADCS_ACCEPT_EXPRESSIONS_2(mrp_shadow_rate)
ADCS_ACCEPT_EXPRESSIONS_2(mrp_subtract)

}  // namespace adcs
