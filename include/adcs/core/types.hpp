#pragma once
// Small fixed-size aliases used across the library. All quantities are SI (rad, s, m, N m,
// kg m^2, N m s) unless a name or comment says otherwise. Frames follow the Basilisk naming:
// `sigma_BN` is the MRP of body B relative to inertial N, `omega_BN_B` that rate in B components.
#include <Eigen/Core>
#include <Eigen/Geometry>  // cross products
#include <cmath>
#include <limits>

namespace adcs {

//! The default scalar of every template (issue 19): each flight template takes its scalar type
//! as its last template parameter, defaulting to double (`MrpPd<4, float>`, `Vec<3, float>`);
//! a class that had no template parameter became `NameT<S = double>` and kept its name for the
//! double instance (`using PpcNeural = PpcNeuralT<double>`). Constants in generic code are
//! written `S(0.25)` so that no float computation is promoted to double (checked with
//! -Wdouble-promotion -Wfloat-conversion -Werror on the float instantiations).
using Scalar = double;

//! π [rad], for angle conversions and geometry builders (M_PI is not standard C++).
inline constexpr double kPiRad = 3.14159265358979323846;
//! π [rad] in the scalar S, rounded once at compile time (C++20's std::numbers::pi_v).
template <class S>
inline constexpr S pi_v = static_cast<S>(3.14159265358979323846L);

template <int Rows, int Cols, class S = double>
using Mat = Eigen::Matrix<S, Rows, Cols, (Cols == 1 && Rows != 1) ? Eigen::ColMajor
                                         : (Rows == 1 && Cols != 1) ? Eigen::RowMajor
                                                                    : Eigen::ColMajor>;
template <int N, class S = double>
using Vec = Eigen::Matrix<S, N, 1>;
using Vec3 = Vec<3>;
using Vec4 = Vec<4>;
using Vec6 = Vec<6>;
using Mat3 = Mat<3, 3>;
using Mat6 = Mat<6, 6>;

//! [a; b] for two 3-vectors (twists, wrenches, [θ; β]). Written as head/tail assignments:
//! Eigen's comma initialiser is not inlined by arm-none-eabi-g++ -O2 (two out-of-line calls,
//! ~45 Cortex-M7 instructions per use), this is ~12 loads and stores.
template <class A, class B>
inline Vec<6, typename A::Scalar> stack3(const Eigen::MatrixBase<A>& a, const Eigen::MatrixBase<B>& b) noexcept {
  Vec<6, typename A::Scalar> x;
  x.template head<3>() = a;
  x.template tail<3>() = b;
  return x;
}

//! C++20's std::type_identity_t: a parameter of this type takes no part in template argument
//! deduction, so `f(const Vec<3, S>& x, identity_t<S> k)` deduces S from x and converts k.
template <class T>
struct identity {
  using type = T;
};
template <class T>
using identity_t = typename identity<T>::type;

//! Lets math functions written for plain fixed-size operands (`f(const Vec<3, S>&)`: one body per
//! scalar) also take any Eigen expression (`f(x.head<3>())`, `f(a + b)`): the expression is
//! evaluated once into the library's plain type of that size (column-major, as Mat<> gives it:
//! a transpose's own plain type is row-major) and the plain overload is called. An exact `Vec<3, S>`
//! argument binds to the plain overload itself (an exact match beats the derived-to-base
//! conversion to MatrixBase), so the forwarders add no code to the usual call.
#define ADCS_ACCEPT_EXPRESSIONS_1(fn)                                          \
  template <class A>                                                           \
  inline auto fn(const Eigen::MatrixBase<A>& a) noexcept {                     \
    return fn(::adcs::Mat<A::RowsAtCompileTime, A::ColsAtCompileTime, typename A::Scalar>(a)); \
  }
#define ADCS_ACCEPT_EXPRESSIONS_2(fn)                                                              \
  template <class A, class B>                                                                      \
  inline auto fn(const Eigen::MatrixBase<A>& a, const Eigen::MatrixBase<B>& b) noexcept {          \
    return fn(::adcs::Mat<A::RowsAtCompileTime, A::ColsAtCompileTime, typename A::Scalar>(a),       \
              ::adcs::Mat<B::RowsAtCompileTime, B::ColsAtCompileTime, typename B::Scalar>(b));      \
  }

//! v in the scalar T. Narrowing (double → float) maps a value beyond T's range to ±Inf, as IEEE
//! rounding would; a plain conversion is undefined behaviour there (C++ [conv.double]). NaN stays
//! NaN, so a controller fed the result refuses it as it refuses any non-finite input.
template <class T, class S>
constexpr T narrow_scalar(S v) noexcept {
  // Compared in long double: a float-double comparison would promote (-Wdouble-promotion).
  if constexpr (static_cast<long double>(std::numeric_limits<T>::max()) >=
                static_cast<long double>(std::numeric_limits<S>::max())) {
    return static_cast<T>(v);
  } else {
    if (v > static_cast<S>(std::numeric_limits<T>::max())) return std::numeric_limits<T>::infinity();
    if (v < -static_cast<S>(std::numeric_limits<T>::max())) return -std::numeric_limits<T>::infinity();
    return static_cast<T>(v);
  }
}

//! x with every coefficient converted by narrow_scalar<T> (the parameter and signal casts use this,
//! never Eigen's plain cast, so a double beyond float's range becomes ±Inf, not undefined).
template <class T, class Derived>
inline auto scalar_cast(const Eigen::MatrixBase<Derived>& x) noexcept {
  using S = typename Derived::Scalar;
  return x.derived().unaryExpr([](S v) { return narrow_scalar<T, S>(v); });
}

//! True when every coefficient is finite (no NaN, no Inf). Works on any Eigen expression.
//! x·0 is ±0 for every finite x and NaN for NaN or ±Inf, so one vectorised sum decides (IEEE
//! arithmetic; the library is not built with -ffast-math, which would void every such check).
template <class Derived>
inline bool all_finite(const Eigen::DenseBase<Derived>& x) noexcept {
  return (x.derived().array() * typename Derived::Scalar(0)).sum() == typename Derived::Scalar(0);
}

inline bool all_finite(double x) noexcept { return std::isfinite(x); }
inline bool all_finite(float x) noexcept { return std::isfinite(x); }

}  // namespace adcs
