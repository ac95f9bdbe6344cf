#pragma once
// Rotation-group basics shared by every attitude parameterisation.
#include <cmath>

#include "adcs/core/types.hpp"

namespace adcs {

//! Skew (cross-product) matrix: skew(v) * w == v.cross(w).
template <class S>
inline Mat<3, 3, S> skew(const Vec<3, S>& v) noexcept {
  Mat<3, 3, S> m;  // element by element: Eigen's comma initialiser is 9 out-of-line calls on the M7 (-O2)
  m(0, 0) = S(0);
  m(1, 0) = v(2);
  m(2, 0) = -v(1);
  m(0, 1) = -v(2);
  m(1, 1) = S(0);
  m(2, 1) = v(0);
  m(0, 2) = v(1);
  m(1, 2) = -v(0);
  m(2, 2) = S(0);
  return m;
}

//! Inverse of skew() for a skew-symmetric matrix (the skew part is taken if it is not).
template <class S>
inline Vec<3, S> vee(const Mat<3, 3, S>& m) noexcept {
  return Vec<3, S>(m(2, 1) - m(1, 2), m(0, 2) - m(2, 0), m(1, 0) - m(0, 1)) * S(0.5);
}

//! Rotation matrix exp([φ]x) of a rotation vector φ [rad] (Rodrigues), active: it rotates a
//! vector by |φ| about φ. Series for |φ| < 1e-4 so the small-angle case keeps full precision.
template <class S>
inline Mat<3, 3, S> so3_exp(const Vec<3, S>& phi) noexcept {
  const S a2 = phi.squaredNorm();
  const Mat<3, 3, S> K = skew(phi);
  S s, c;  // sin(a)/a and (1 - cos a)/a²
  if (a2 < S(1e-8)) {
    s = S(1) - a2 / S(6);
    c = S(0.5) - a2 / S(24);
  } else {
    const S a = std::sqrt(a2);
    s = std::sin(a) / a;
    c = (S(1) - std::cos(a)) / a2;
  }
  return Mat<3, 3, S>::Identity() + s * K + c * K * K;
}

//! Elementary frame rotations (passive, "frame rotates by angle"), as used by 3-2-1 and
//! x-y-z Euler sequences: R1 about x, R2 about y, R3 about z. seed 002 eq. (3).
template <class S>
inline Mat<3, 3, S> frame_rotation_1(S a) noexcept {
  const S c = std::cos(a), s = std::sin(a);
  Mat<3, 3, S> m;
  m << S(1), S(0), S(0), S(0), c, s, S(0), -s, c;
  return m;
}
template <class S>
inline Mat<3, 3, S> frame_rotation_2(S a) noexcept {
  const S c = std::cos(a), s = std::sin(a);
  Mat<3, 3, S> m;
  m << c, S(0), -s, S(0), S(1), S(0), s, S(0), c;
  return m;
}
template <class S>
inline Mat<3, 3, S> frame_rotation_3(S a) noexcept {
  const S c = std::cos(a), s = std::sin(a);
  Mat<3, 3, S> m;
  m << c, s, S(0), -s, c, S(0), S(0), S(0), S(1);
  return m;
}

// Expression arguments (core/types.hpp).
ADCS_ACCEPT_EXPRESSIONS_1(skew)
ADCS_ACCEPT_EXPRESSIONS_1(vee)
ADCS_ACCEPT_EXPRESSIONS_1(so3_exp)

}  // namespace adcs
