#pragma once
// Unit quaternion (Euler parameters) q_BN, stored scalar-first [w, x, y, z]. Built only through
// named factories: Eigen's Quaternion(w,x,y,z) constructor stores x,y,z,w, a classic trap, so
// this type never takes a bare coefficient list.
//
// Convention (Schaub & Junkins): the DCM from N to B is
//   C_BN = (w^2 - v^T v) I3 + 2 v v^T - 2 w [v]x,   v = [x y z]^T,
// consistent with C(sigma) of seed 001 eq. (6) and sigma = v / (1 + w).
#include <cmath>

#include "adcs/core/types.hpp"
#include "adcs/math/so3.hpp"

namespace adcs {

template <class S = double>
class QuaternionSFT {
 public:
  using Scalar = S;
  using V3 = Vec<3, S>;
  using V4 = Vec<4, S>;
  //! Identity attitude.
  static QuaternionSFT identity() noexcept { return QuaternionSFT(V4(S(1), S(0), S(0), S(0))); }
  static QuaternionSFT from_scalar_first(S w, S x, S y, S z) noexcept { return QuaternionSFT(V4(w, x, y, z)); }
  static QuaternionSFT from_scalar_first(const V4& wxyz) noexcept { return QuaternionSFT(wxyz); }
  static QuaternionSFT from_scalar_last(S x, S y, S z, S w) noexcept { return QuaternionSFT(V4(w, x, y, z)); }
  //! Rotation of `angle_rad` about unit axis `axis` (principal rotation).
  static QuaternionSFT from_axis_angle(const V3& axis, S angle_rad) noexcept {
    const S h = S(0.5) * angle_rad;
    const V3 v = axis * std::sin(h);
    return QuaternionSFT(V4(std::cos(h), v(0), v(1), v(2)));
  }

  S w() const noexcept { return q_(0); }
  V3 vec() const noexcept { return q_.template tail<3>(); }
  //! Coefficients in [w, x, y, z] order.
  const V4& scalar_first() const noexcept { return q_; }
  S norm() const noexcept { return q_.norm(); }
  QuaternionSFT normalized() const noexcept { return QuaternionSFT(q_ / q_.norm()); }
  QuaternionSFT conjugate() const noexcept { return QuaternionSFT(V4(q_(0), -q_(1), -q_(2), -q_(3))); }
  //! Same attitude with w >= 0 (the short-rotation representative).
  QuaternionSFT canonical() const noexcept { return q_(0) < S(0) ? QuaternionSFT(-q_) : *this; }
  //! The same quaternion in another scalar (each coefficient rounded once).
  template <class T>
  QuaternionSFT<T> cast() const noexcept {
    return QuaternionSFT<T>::from_scalar_first(scalar_cast<T>(q_));
  }

 private:
  explicit QuaternionSFT(const V4& wxyz) noexcept : q_(wxyz) {}
  V4 q_;
};
using QuaternionSF = QuaternionSFT<double>;

//! Successive rotation: q_FN = compose(q_FB, q_BN), so that C(q_FN) = C(q_FB) C(q_BN).
template <class S>
inline QuaternionSFT<S> compose(const QuaternionSFT<S>& q_FB, const QuaternionSFT<S>& q_BN) noexcept {
  const Vec<4, S>& a = q_FB.scalar_first();
  const Vec<4, S>& b = q_BN.scalar_first();
  Mat<4, 4, S> m;  // Schaub & Junkins eq. (3.101)
  m << a(0), -a(1), -a(2), -a(3),  //
      a(1), a(0), a(3), -a(2),     //
      a(2), -a(3), a(0), a(1),     //
      a(3), a(2), -a(1), a(0);
  return QuaternionSFT<S>::from_scalar_first(m * b);
}

//! DCM C_BN of a unit quaternion q_BN.
template <class S>
inline Mat<3, 3, S> quat_to_dcm(const QuaternionSFT<S>& q) noexcept {
  const S w = q.w();
  const Vec<3, S> v = q.vec();
  return (w * w - v.squaredNorm()) * Mat<3, 3, S>::Identity() + S(2) * v * v.transpose() - S(2) * w * skew(v);
}

//! Quaternion of a proper orthonormal DCM by Shepperd's method (always picks the largest
//! component to divide by, so it is accurate for every attitude). Result has w >= 0.
template <class S>
inline QuaternionSFT<S> dcm_to_quat(const Mat<3, 3, S>& C) noexcept {
  const S tr = C.trace();
  const Vec<4, S> sq(S(1) + tr, S(1) + S(2) * C(0, 0) - tr, S(1) + S(2) * C(1, 1) - tr,
                     S(1) + S(2) * C(2, 2) - tr);  // 4 w^2, 4 x^2, 4 y^2, 4 z^2
  Eigen::Index k = 0;
  sq.maxCoeff(&k);
  Vec<4, S> q;
  const S d = S(0.5) * std::sqrt(sq(k));  // the largest |component|
  const S f = S(0.25) / d;
  switch (k) {
    case 0:
      q << d, (C(1, 2) - C(2, 1)) * f, (C(2, 0) - C(0, 2)) * f, (C(0, 1) - C(1, 0)) * f;
      break;
    case 1:
      q << (C(1, 2) - C(2, 1)) * f, d, (C(0, 1) + C(1, 0)) * f, (C(2, 0) + C(0, 2)) * f;
      break;
    case 2:
      q << (C(2, 0) - C(0, 2)) * f, (C(0, 1) + C(1, 0)) * f, d, (C(1, 2) + C(2, 1)) * f;
      break;
    default:
      q << (C(0, 1) - C(1, 0)) * f, (C(2, 0) + C(0, 2)) * f, (C(1, 2) + C(2, 1)) * f, d;
      break;
  }
  return QuaternionSFT<S>::from_scalar_first(q).canonical();
}

// Expression arguments (core/types.hpp).
ADCS_ACCEPT_EXPRESSIONS_1(dcm_to_quat)

}  // namespace adcs
