#pragma once
// Rotation-group basics shared by every attitude parameterisation.
#include "adcs/core/types.hpp"

namespace adcs {

//! Skew (cross-product) matrix: skew(v) * w == v.cross(w).
inline Mat3 skew(const Vec3& v) noexcept {
  Mat3 m;  // element by element: Eigen's comma initialiser is 9 out-of-line calls on the M7 (-O2)
  m(0, 0) = 0.0;
  m(1, 0) = v(2);
  m(2, 0) = -v(1);
  m(0, 1) = -v(2);
  m(1, 1) = 0.0;
  m(2, 1) = v(0);
  m(0, 2) = v(1);
  m(1, 2) = -v(0);
  m(2, 2) = 0.0;
  return m;
}

//! Inverse of skew() for a skew-symmetric matrix (the skew part is taken if it is not).
inline Vec3 vee(const Mat3& m) noexcept {
  return Vec3(m(2, 1) - m(1, 2), m(0, 2) - m(2, 0), m(1, 0) - m(0, 1)) * 0.5;
}

//! Rotation matrix exp([φ]x) of a rotation vector φ [rad] (Rodrigues), active: it rotates a
//! vector by |φ| about φ. Series for |φ| < 1e-4 so the small-angle case keeps full precision.
inline Mat3 so3_exp(const Vec3& phi) noexcept {
  const double a2 = phi.squaredNorm();
  const Mat3 K = skew(phi);
  double s, c;  // sin(a)/a and (1 - cos a)/a²
  if (a2 < 1e-8) {
    s = 1.0 - a2 / 6.0;
    c = 0.5 - a2 / 24.0;
  } else {
    const double a = std::sqrt(a2);
    s = std::sin(a) / a;
    c = (1.0 - std::cos(a)) / a2;
  }
  return Mat3::Identity() + s * K + c * K * K;
}

//! Elementary frame rotations (passive, "frame rotates by angle"), as used by 3-2-1 and
//! x-y-z Euler sequences: R1 about x, R2 about y, R3 about z. seed 002 eq. (3).
inline Mat3 frame_rotation_1(double a) noexcept {
  const double c = std::cos(a), s = std::sin(a);
  Mat3 m;
  m << 1, 0, 0, 0, c, s, 0, -s, c;
  return m;
}
inline Mat3 frame_rotation_2(double a) noexcept {
  const double c = std::cos(a), s = std::sin(a);
  Mat3 m;
  m << c, 0, -s, 0, 1, 0, s, 0, c;
  return m;
}
inline Mat3 frame_rotation_3(double a) noexcept {
  const double c = std::cos(a), s = std::sin(a);
  Mat3 m;
  m << c, s, 0, -s, c, 0, 0, 0, 1;
  return m;
}

}  // namespace adcs
