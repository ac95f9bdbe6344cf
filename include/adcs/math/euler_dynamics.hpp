#pragma once
// Rigid-body attitude dynamics in x-y-z Euler angles, ϑ̈ = A + B u + D̄ (seed 002 eqs. (3)-(4),
// spec §B.2): what the Euler-angle tracking laws (control/euler_tracking_common.hpp) and the
// flexible plant's tests share. Kept apart from the plant so a law never includes a plant.
#include "adcs/core/status.hpp"
#include "adcs/core/types.hpp"
#include "adcs/math/euler.hpp"
#include "adcs/math/so3.hpp"

namespace adcs {

//! ϑ̈ = A + B u + D̄ in closed form at one (ϑ, ω) (spec §B.2), shared by plant tests and
//! controllers. F, G, ϑ̇ = F ω are returned too so a controller computes them once.
template <class S = double>
struct EulerAffineT {
  Mat<3, 3, S> F = Mat<3, 3, S>::Identity();      //!< [-] ϑ̇ = F ω
  Mat<3, 3, S> G = Mat<3, 3, S>::Identity();      //!< [-] ω = G ϑ̇
  Vec<3, S> angles_dot = Vec<3, S>::Zero();       //!< [rad/s] ϑ̇
  Vec<3, S> A = Vec<3, S>::Zero();                //!< [rad/s²] drift −F Ġ ϑ̇ − F J⁻¹ (ω × J ω)
  Mat<3, 3, S> B = Mat<3, 3, S>::Identity();      //!< [rad/(s² N m)] F J⁻¹
  Mat<3, 3, S> B_inv = Mat<3, 3, S>::Identity();  //!< [N m s²/rad] J G
};
using EulerAffine = EulerAffineT<double>;

//! Fills `out` for x-y-z Euler angles ϑ [rad] and body rate ω [rad/s] (J⁻¹ precomputed by the
//! caller). Returns singular at gimbal lock (|cos θ| < kEulerSingularCos) and non_finite_input for
//! NaN/Inf, leaving `out` untouched in both cases.   seed 002 eqs. (3)-(4), spec §B.2
template <class S>
inline Status euler_affine(const Mat<3, 3, S>& J, const Mat<3, 3, S>& J_inv, const Vec<3, S>& angles,
                           const Vec<3, S>& omega, EulerAffineT<S>& out) noexcept {
  if (!all_finite(angles) || !all_finite(omega)) return Status::non_finite_input;
  Mat<3, 3, S> F;
  const Status s = euler123_F<S>(angles, F);
  if (s != Status::ok) return s;
  out.F = F;
  out.G = euler123_G(angles);
  out.angles_dot = F * omega;
  const Mat<3, 3, S> FJinv = F * J_inv;
  out.A = -F * (euler123_G_dot(angles, out.angles_dot) * out.angles_dot) - FJinv * omega.cross(J * omega);
  out.B = FJinv;
  out.B_inv = J * out.G;
  return Status::ok;
}

//! Euler–Lagrange inertia J* = Gᵀ J G and Coriolis matrix C = Gᵀ J Ġ − Gᵀ (J G ϑ̇)× G
//! (seed 002 eq. (4), repaired B.4 #3). Not used by the controllers (euler_affine is cheaper);
//! kept for the B-S2/B-S3 checks and for users who want the EL form.
inline void euler_lagrange_terms(const Mat3& J, const Vec3& angles, const Vec3& angles_dot,
                                 Mat3& J_star, Mat3& C) noexcept {
  const Mat3 G = euler123_G(angles);
  const Mat3 G_dot = euler123_G_dot(angles, angles_dot);
  J_star = G.transpose() * J * G;
  C = G.transpose() * J * G_dot - G.transpose() * skew(J * G * angles_dot) * G;
}

}  // namespace adcs
