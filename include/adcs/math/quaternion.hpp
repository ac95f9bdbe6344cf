#pragma once
// Unit quaternion (Euler parameters) q_BN, stored scalar-first [w, x, y, z]. Built only through
// named factories: Eigen's Quaternion(w,x,y,z) constructor stores x,y,z,w, a classic trap, so
// this type never takes a bare coefficient list.
//
// Convention (Schaub & Junkins): the DCM from N to B is
//   C_BN = (w^2 - v^T v) I3 + 2 v v^T - 2 w [v]x,   v = [x y z]^T,
// consistent with C(sigma) of seed 001 eq. (6) and sigma = v / (1 + w).
#include "adcs/core/types.hpp"
#include "adcs/math/so3.hpp"

namespace adcs {

class QuaternionSF {
 public:
  //! Identity attitude.
  static QuaternionSF identity() noexcept { return QuaternionSF(Vec4(1.0, 0.0, 0.0, 0.0)); }
  static QuaternionSF from_scalar_first(double w, double x, double y, double z) noexcept {
    return QuaternionSF(Vec4(w, x, y, z));
  }
  static QuaternionSF from_scalar_first(const Vec4& wxyz) noexcept { return QuaternionSF(wxyz); }
  static QuaternionSF from_scalar_last(double x, double y, double z, double w) noexcept {
    return QuaternionSF(Vec4(w, x, y, z));
  }
  //! Rotation of `angle_rad` about unit axis `axis` (principal rotation).
  static QuaternionSF from_axis_angle(const Vec3& axis, double angle_rad) noexcept {
    const double h = 0.5 * angle_rad;
    const Vec3 v = axis * std::sin(h);
    return QuaternionSF(Vec4(std::cos(h), v(0), v(1), v(2)));
  }

  double w() const noexcept { return q_(0); }
  Vec3 vec() const noexcept { return q_.tail<3>(); }
  //! Coefficients in [w, x, y, z] order.
  const Vec4& scalar_first() const noexcept { return q_; }
  double norm() const noexcept { return q_.norm(); }
  QuaternionSF normalized() const noexcept { return QuaternionSF(q_ / q_.norm()); }
  QuaternionSF conjugate() const noexcept {
    return QuaternionSF(Vec4(q_(0), -q_(1), -q_(2), -q_(3)));
  }
  //! Same attitude with w >= 0 (the short-rotation representative).
  QuaternionSF canonical() const noexcept { return q_(0) < 0.0 ? QuaternionSF(-q_) : *this; }

 private:
  explicit QuaternionSF(const Vec4& wxyz) noexcept : q_(wxyz) {}
  Vec4 q_;
};

//! Successive rotation: q_FN = compose(q_FB, q_BN), so that C(q_FN) = C(q_FB) C(q_BN).
inline QuaternionSF compose(const QuaternionSF& q_FB, const QuaternionSF& q_BN) noexcept {
  const Vec4& a = q_FB.scalar_first();
  const Vec4& b = q_BN.scalar_first();
  Mat<4, 4> m;  // Schaub & Junkins eq. (3.101)
  m << a(0), -a(1), -a(2), -a(3),  //
      a(1), a(0), a(3), -a(2),     //
      a(2), -a(3), a(0), a(1),     //
      a(3), a(2), -a(1), a(0);
  return QuaternionSF::from_scalar_first(m * b);
}

//! DCM C_BN of a unit quaternion q_BN.
inline Mat3 quat_to_dcm(const QuaternionSF& q) noexcept {
  const double w = q.w();
  const Vec3 v = q.vec();
  return (w * w - v.squaredNorm()) * Mat3::Identity() + 2.0 * v * v.transpose() - 2.0 * w * skew(v);
}

//! Quaternion of a proper orthonormal DCM by Shepperd's method (always picks the largest
//! component to divide by, so it is accurate for every attitude). Result has w >= 0.
inline QuaternionSF dcm_to_quat(const Mat3& C) noexcept {
  const double tr = C.trace();
  const Vec4 sq(1.0 + tr, 1.0 + 2.0 * C(0, 0) - tr, 1.0 + 2.0 * C(1, 1) - tr,
                1.0 + 2.0 * C(2, 2) - tr);  // 4 w^2, 4 x^2, 4 y^2, 4 z^2
  Eigen::Index k = 0;
  sq.maxCoeff(&k);
  Vec4 q;
  const double d = 0.5 * std::sqrt(sq(k));  // the largest |component|
  const double f = 0.25 / d;
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
  return QuaternionSF::from_scalar_first(q).canonical();
}

}  // namespace adcs
