#pragma once
// Small fixed-size aliases used across the library. All quantities are SI (rad, s, m, N m,
// kg m^2, N m s) unless a name or comment says otherwise. Frames follow the Basilisk naming:
// `sigma_BN` is the MRP of body B relative to inertial N, `omega_BN_B` that rate in B components.
#include <Eigen/Core>
#include <Eigen/Geometry>  // cross products
#include <cmath>

namespace adcs {

using Scalar = double;

//! π [rad], for angle conversions and geometry builders (M_PI is not standard C++).
inline constexpr double kPiRad = 3.14159265358979323846;
template <int Rows, int Cols>
using Mat = Eigen::Matrix<double, Rows, Cols, (Cols == 1 && Rows != 1) ? Eigen::ColMajor
                                              : (Rows == 1 && Cols != 1) ? Eigen::RowMajor
                                                                         : Eigen::ColMajor>;
template <int N>
using Vec = Eigen::Matrix<double, N, 1>;
using Vec3 = Vec<3>;
using Vec4 = Vec<4>;
using Vec6 = Vec<6>;
using Mat3 = Mat<3, 3>;
using Mat6 = Mat<6, 6>;

//! [a; b] for two 3-vectors (twists, wrenches, [θ; β]). Written as head/tail assignments:
//! Eigen's comma initialiser is not inlined by arm-none-eabi-g++ -O2 (two out-of-line calls,
//! ~45 Cortex-M7 instructions per use), this is ~12 loads and stores.
template <class A, class B>
inline Vec6 stack3(const Eigen::MatrixBase<A>& a, const Eigen::MatrixBase<B>& b) noexcept {
  Vec6 x;
  x.template head<3>() = a;
  x.template tail<3>() = b;
  return x;
}

//! True when every coefficient is finite (no NaN, no Inf). Works on any Eigen expression.
//! x·0 is ±0 for every finite x and NaN for NaN or ±Inf, so one vectorised sum decides (IEEE
//! arithmetic; the library is not built with -ffast-math, which would void every such check).
template <class Derived>
inline bool all_finite(const Eigen::DenseBase<Derived>& x) noexcept {
  return (x.derived().array() * typename Derived::Scalar(0)).sum() == typename Derived::Scalar(0);
}

inline bool all_finite(double x) noexcept { return std::isfinite(x); }

}  // namespace adcs
