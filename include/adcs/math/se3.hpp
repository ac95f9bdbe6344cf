#pragma once
// SE(3) primitives and the exponential-coordinate error kinematics of seed 003 (spec §A.2.1 and
// §A.2.3, seed 003 eqs. (6)-(9)): the group g = (C, R), hat/vee, Ad, ad, ad*, the SO(3)/SE(3)
// exponential and logarithm, the left Jacobian V(θ), and the blocks A(θ), T(θ,β), G(η), G⁻¹(η)
// of η̇ = G(η) ξ_e together with their time derivatives (Ȧ, Ġ of spec §A.5).
//
// Conventions (spec §A.2.1):
// - Ordering is always [rotational; translational]: a twist is ξ = [ω; v], exponential
//   coordinates are η = [θ; β] (θ rotation part [rad], β translation part [m]).
// - C is ACTIVE, body -> inertial: Ċ = C ω×, Ṙ = C v. This is the transpose of the passive
//   C_BN used by quaternion.hpp / mrp.hpp, so so3_log() hands Cᵀ to dcm_to_quat().
// - φ = ‖θ‖ throughout.
//
// Non-finite input: these are pure math helpers without a Status. NaN/Inf in the input give a
// non-finite output (tested for every entry), so a caller that checks all_finite() on its result
// catches them. so3_log() needs an explicit check for that: Shepperd's method maps an infinite
// diagonal entry to q = (Inf, 0, 0, 0), i.e. a finite θ = 0.
//
// Scalar (issue 19): every function and type takes the scalar S (deduced from the arguments;
// `Se3T<S>`, `Se3GBlocksT<S>`, … with the double names kept). The series/closed-form switches
// depend on S (exp_coord_series_switch_v, gamma_rate_series_switch_v): the closed forms cancel
// O(1/φ²) to O(1/φ⁶) terms, which float's ε = 6e-8 cannot afford at double's switches (γ's closed
// form at φ = 0.05 would carry 1e3 ε/φ⁴ ≈ 10 relative error in float); in double the switches
// and every expression are the ones before, bit for bit.
#include <cmath>
#include <type_traits>
#include <limits>

#include "adcs/core/types.hpp"
#include "adcs/math/quaternion.hpp"
#include "adcs/math/so3.hpp"

namespace adcs {

// =============================================================================================
// Scalar coefficients. Each is an even function of φ: a closed form, and a Taylor series below a
// switch where the closed form loses digits by cancellation.

//! Switch between Taylor series (|φ| < 0.05) and closed form for α, (1−cosφ)/φ², (φ−sinφ)/φ³
//! and γ in double. spec §A.2.1, §A.2.3
inline constexpr double kExpCoordSeriesSwitch = 0.05;  //!< [rad]

//! The switch in scalar S. Float: 1 rad, where each series (truncated after its φ⁶ term) is
//! still more accurate than the closed form in float: truncation at φ = 1 is 2.5e-7 (α),
//! 5.5e-7 ((1−cosφ)/φ²), 1.5e-7 ((φ−sinφ)/φ³), 1.9e-6 (γ) relative, against the closed forms'
//! 24 ε/φ² = 1.4e-6 (α) and 1e3 ε/φ⁴ = 6e-5 (γ) there (ε = 6e-8); at double's 0.05 the float
//! closed form of γ would be off by ~10 relative.
template <class S>
inline constexpr S exp_coord_series_switch_v = std::is_same_v<S, float> ? S(1) : S(kExpCoordSeriesSwitch);

//! (1 − cos φ)/φ². spec §A.2.1. The closed form is evaluated as ½(sin(φ/2)/(φ/2))², equal in
//! exact arithmetic but free of the 1 − cos φ cancellation. The series carries the φ⁶ term, one
//! more than the spec lists, whose omission would leave 8e-13 relative at the switch.
template <class S>
inline S so3_coeff_one_minus_cos(S phi) noexcept {
  const S p2 = phi * phi;
  if (std::abs(phi) < exp_coord_series_switch_v<S>) {
    return S(0.5) + p2 * (S(-1.0 / 24.0) + p2 * (S(1.0 / 720.0) - p2 / S(40320.0)));
  }
  const S s = std::sin(S(0.5) * phi) / (S(0.5) * phi);
  return S(0.5) * s * s;
}

//! (φ − sin φ)/φ³. spec §A.2.1. Series with the φ⁶ term added (spec truncation: 3e-13 at the
//! switch). The closed form loses ≈ 6ε/φ² relative (≈ 3e-13 at the switch).
template <class S>
inline S so3_coeff_phi_minus_sin(S phi) noexcept {
  const S p2 = phi * phi;
  if (std::abs(phi) < exp_coord_series_switch_v<S>) {
    return S(1.0 / 6.0) + p2 * (S(-1.0 / 120.0) + p2 * (S(1.0 / 5040.0) - p2 / S(362880.0)));
  }
  return (phi - std::sin(phi)) / (p2 * phi);
}

//! α(φ) = (1/φ²)(1 − (φ/2) cot(φ/2)), the (θ×)² coefficient of V⁻¹ and A. spec §A.2.1.
//! Series = Σ |B₂ₙ|/(2n)! φ²ⁿ⁻² (Bernoulli numbers), as listed in the spec.
template <class S>
inline S se3_alpha(S phi) noexcept {
  const S p2 = phi * phi;
  if (std::abs(phi) < exp_coord_series_switch_v<S>) {
    return S(1.0 / 12.0) + p2 * (S(1.0 / 720.0) + p2 * (S(1.0 / 30240.0) + p2 / S(1209600.0)));
  }
  const S h = S(0.5) * phi;
  return (S(1) - h / std::tan(h)) / p2;
}

//! γ(φ) = α'(φ)/φ = −2/φ⁴ + cot(φ/2)/(2φ³) + 1/(4φ² sin²(φ/2)). spec §A.2.3.
//! Series with the φ⁶ term added (spec truncation: 9e-13 at the switch).
//! Accuracy: the closed form cancels three O(1/φ⁴) terms to O(1); its relative error is
//! ≈ 1e3 ε/φ⁴: 1e-9 to 2e-8 just above the switch (measured against 50-digit values; the test
//! bounds it by 3600 ε/φ⁴ = 1.3e-7) and 1e-14 at φ = 1. Rearranging the closed form does not
//! help (the cancellation is intrinsic). The spec fixes the switch at 0.05 anyway, and the error
//! is harmless where γ is used: in T it multiplies (θᵀβ)(θ×)², of size ≤ φ³‖β‖, so its absolute
//! effect on T is ≲ 3 ε ‖β‖/φ ≈ 1e-14 ‖β‖ at the switch.
//! γ's series in float up to gamma_float_series_switch (below): ten terms, through φ¹⁸, from
//! the Bernoulli numbers B₄ … B₂₂ (c_n = (2n−2)|B₂ₙ|/(2n)!, exact rationals rounded once);
//! truncation 1e-9 relative at φ = 2.
inline constexpr float kGammaFloatSeriesSwitch = 2.0f;  //!< [rad]
namespace detail {
inline float se3_gamma_series_float(float p2) noexcept {
  constexpr float c[] = {float(1.0 / 360.0),
                         float(1.0 / 7560.0),
                         float(1.0 / 201600.0),
                         float(1.0 / 5987520.0),
                         float(691.0 / 130767436800.0),
                         float(1.0 / 6227020800.0),
                         float(3617.0 / 762187345920000.0),
                         float(43867.0 / 319318388573184000.0),
                         float(174611.0 / 44603203483238400000.0),
                         float(77683.0 / 705055001969590272000.0)};
  float acc = c[9];
  for (int i = 8; i >= 0; --i) acc = c[i] + p2 * acc;  // Horner in φ²
  return acc;
}
}  // namespace detail

template <class S>
inline S se3_gamma(S phi) noexcept {
  const S p2 = phi * phi;
  // Float: the closed form's 1e3 ε/φ⁴ is 6e-5 at φ = 1 and 4e-6 at 2 (ε = 6e-8), so float
  // takes the long series below φ = 2. Double keeps its switch and four-term series.
  if constexpr (std::is_same_v<S, float>) {
    if (std::abs(phi) < kGammaFloatSeriesSwitch) return detail::se3_gamma_series_float(p2);
  }
  if (std::abs(phi) < exp_coord_series_switch_v<S>) {
    return S(1.0 / 360.0) + p2 * (S(1.0 / 7560.0) + p2 * (S(1.0 / 201600.0) + p2 / S(5987520.0)));
  }
  const S h = S(0.5) * phi;
  const S s = std::sin(h);
  return S(-2) / (p2 * p2) + S(1) / (S(2) * std::tan(h) * p2 * phi) + S(1) / (S(4) * p2 * s * s);
}

//! Switch for se3_gamma_rate(): its closed form cancels O(1/φ⁶) terms (relative error
//! ≈ 5e4 ε/φ⁶: 1e-4 at φ = 0.05, 5e-13 at φ = 1), so the series is used up to φ = 1.
//! Not in the spec (which has no closed form for Ṫ); chosen here.
inline constexpr double kGammaRateSeriesSwitch = 1.0;  //!< [rad]

//! The switch in scalar S. Float: 3 rad (the log chart ends at π): the closed form's 5e4 ε/φ⁶
//! is 3e-3 at 1 rad and 4e-6 at 3 rad in float, the 11-term series' truncation (φ/2π)²² is
//! 9e-8 at 3 rad.
template <class S>
inline constexpr S gamma_rate_series_switch_v = std::is_same_v<S, float> ? S(3) : S(kGammaRateSeriesSwitch);

//! γ'(φ)/φ, needed for Ṫ (the time derivative of γ(φ) is this times θᵀθ̇).
//! Closed form, with w = (φ/2)/sin(φ/2) and k = (φ/2)cot(φ/2):
//!   γ'(φ)/φ = (8 − 3w² − 3k − 2w²k)/φ⁶.
//! Series Σ_{n≥3} (2n−2)(2n−4)|B₂ₙ|/(2n)! φ²ⁿ⁻⁶ through φ²⁰ (truncation < 2e-16 relative at 1).
template <class S>
inline S se3_gamma_rate(S phi) noexcept {
  const S p2 = phi * phi;
  if (std::abs(phi) < gamma_rate_series_switch_v<S>) {
    // Coefficients from the Bernoulli numbers B₆ … B₂₆ (exact rationals, rounded once).
    constexpr S c[] = {S(1.0 / 3780.0),
                       S(1.0 / 50400.0),
                       S(1.0 / 997920.0),
                       S(691.0 / 16345929600.0),
                       S(1.0 / 622702080.0),
                       S(3617.0 / 63515612160000.0),
                       S(43867.0 / 22808456326656000.0),
                       S(174611.0 / 2787700217702400000.0),
                       S(77683.0 / 39169722331643904000.0),
                       S(236364091.0 / 3849600310753962885120000.0),
                       S(657931.0 / 352527500984795136000000.0)};
    S acc = c[10];
    for (int i = 9; i >= 0; --i) acc = c[i] + p2 * acc;  // Horner in φ²
    return acc;
  }
  const S h = S(0.5) * phi;
  const S s = std::sin(h);
  const S w2 = (h * h) / (s * s);
  const S k = h / std::tan(h);
  return (S(8) - S(3) * w2 - S(3) * k - S(2) * w2 * k) / (p2 * p2 * p2);
}

//! Every φ-dependent coefficient above at one φ, from one sin/cos pair of φ/2 and one sin φ
//! instead of the ~15 sin/tan calls the separate functions make when a control step needs G, G⁻¹,
//! Ġ ξ and log together (each newlib sin/tan is hundreds of Cortex-M7 instructions; issue 7
//! budget). Same formulas and switches as the single functions: the series branches are the
//! very same expressions; the closed forms write tan(φ/2) as sin/cos, which moves α and γ by a
//! few ulp × their own cancellation factor (α ≲ 24ε/φ², γ ≲ 1e3ε/φ⁴ relative, see se3_gamma),
//! tested against the single functions in tests/math/test_se3.cpp.
template <class S = double>
struct Se3ExpCoordCoefficientsT {
  S phi = S(0);                       //!< φ = ‖θ‖ [rad]
  S one_minus_cos = S(0.5);           //!< (1 − cos φ)/φ²
  S phi_minus_sin = S(1.0 / 6.0);     //!< (φ − sin φ)/φ³
  S alpha = S(1.0 / 12.0);            //!< α(φ)
  S gamma = S(1.0 / 360.0);           //!< γ(φ)
  S gamma_rate = S(1.0 / 3780.0);     //!< γ'(φ)/φ
};
using Se3ExpCoordCoefficients = Se3ExpCoordCoefficientsT<double>;

template <class S>
inline Se3ExpCoordCoefficientsT<S> se3_exp_coord_coefficients(S phi) noexcept {
  Se3ExpCoordCoefficientsT<S> k;
  k.phi = phi;
  if (std::abs(phi) < exp_coord_series_switch_v<S>) {  // series only: no trig at all
    k.gamma_rate = se3_gamma_rate(phi);
    k.one_minus_cos = so3_coeff_one_minus_cos(phi);
    k.phi_minus_sin = so3_coeff_phi_minus_sin(phi);
    k.alpha = se3_alpha(phi);
    k.gamma = se3_gamma(phi);
    return k;
  }
  const S p2 = phi * phi;
  const S h = S(0.5) * phi;
  const S s = std::sin(h);
  const S c = std::cos(h);
  const S sinc_h = s / h;                                      // sin(φ/2)/(φ/2)
  const S h_cot_h = h * c / s;                                 // (φ/2) cot(φ/2)
  k.one_minus_cos = S(0.5) * sinc_h * sinc_h;                  // as so3_coeff_one_minus_cos
  k.phi_minus_sin = (phi - std::sin(phi)) / (p2 * phi);        // as so3_coeff_phi_minus_sin
  k.alpha = (S(1) - h_cot_h) / p2;                             // as se3_alpha
  if constexpr (std::is_same_v<S, float>) {                    // as se3_gamma in float
    k.gamma = std::abs(phi) < kGammaFloatSeriesSwitch ? detail::se3_gamma_series_float(p2)
                                                      : S(-2) / (p2 * p2) + c / (S(2) * s * p2 * phi) +
                                                            S(1) / (S(4) * p2 * s * s);
  } else {
    k.gamma = S(-2) / (p2 * p2) + c / (S(2) * s * p2 * phi) + S(1) / (S(4) * p2 * s * s);  // as se3_gamma
  }
  if (std::abs(phi) < gamma_rate_series_switch_v<S>) {         // as se3_gamma_rate
    k.gamma_rate = se3_gamma_rate(phi);                        // its series: no trig
  } else {
    const S w2 = S(1) / (sinc_h * sinc_h);
    k.gamma_rate = (S(8) - S(3) * w2 - S(3) * h_cot_h - S(2) * w2 * h_cot_h) / (p2 * p2 * p2);
  }
  return k;
}

// =============================================================================================
// The group SE(3) and its algebra. spec §A.2.1

//! g = (C, R): homogeneous [[C, R], [0, 1]].
template <class S = double>
struct Se3T {
  Mat<3, 3, S> C;  //!< [-] active rotation, body -> inertial
  Vec<3, S> R;     //!< [m] position in inertial components

  static Se3T identity() noexcept { return Se3T{Mat<3, 3, S>::Identity(), Vec<3, S>::Zero()}; }
};
using Se3 = Se3T<double>;

//! g1 g2 = (C1 C2, R1 + C1 R2).
template <class S>
inline Se3T<S> se3_compose(const Se3T<S>& g1, const Se3T<S>& g2) noexcept {
  return Se3T<S>{g1.C * g2.C, g1.R + g1.C * g2.R};
}

//! g⁻¹ = (Cᵀ, −Cᵀ R). spec §A.2.1
template <class S>
inline Se3T<S> se3_inverse(const Se3T<S>& g) noexcept {
  return Se3T<S>{g.C.transpose(), -(g.C.transpose() * g.R)};
}

//! Homogeneous 4×4 matrix [[C, R], [0, 1]].
template <class S>
inline Mat<4, 4, S> se3_matrix(const Se3T<S>& g) noexcept {
  Mat<4, 4, S> m = Mat<4, 4, S>::Identity();
  m.template topLeftCorner<3, 3>() = g.C;
  m.template topRightCorner<3, 1>() = g.R;
  return m;
}

//! ξ^ = [[ω×, v], [0, 0]] for ξ = [ω; v]. spec §A.2.1
template <class S>
inline Mat<4, 4, S> se3_hat(const Vec<6, S>& xi) noexcept {
  Mat<4, 4, S> m = Mat<4, 4, S>::Zero();
  m.template topLeftCorner<3, 3>() = skew(xi.template head<3>());
  m.template topRightCorner<3, 1>() = xi.template tail<3>();
  return m;
}

//! Inverse of se3_hat() (the skew part of the upper-left block is taken if it is not skew).
template <class S>
inline Vec<6, S> se3_vee(const Mat<4, 4, S>& m) noexcept {
  return stack3(vee(m.template topLeftCorner<3, 3>()), m.template topRightCorner<3, 1>());
}

//! Ad_g = [[C, 0], [R×C, C]]. spec §A.2.1
template <class S>
inline Mat<6, 6, S> se3_Ad(const Se3T<S>& g) noexcept {
  Mat<6, 6, S> m;
  m << g.C, Mat<3, 3, S>::Zero(), skew(g.R) * g.C, g.C;
  return m;
}

//! Ad_{g⁻¹} = [[Cᵀ, 0], [−Cᵀ R×, Cᵀ]], without forming g⁻¹. spec §A.2.1
template <class S>
inline Mat<6, 6, S> se3_Ad_inv(const Se3T<S>& g) noexcept {
  const Mat<3, 3, S> Ct = g.C.transpose();
  Mat<6, 6, S> m;
  m << Ct, Mat<3, 3, S>::Zero(), -(Ct * skew(g.R)), Ct;
  return m;
}

//! Ad_{g⁻¹} x = [Cᵀ x_ω; Cᵀ (x_v − R × x_ω)], the product without the 6×6 matrix.
template <class S>
inline Vec<6, S> se3_Ad_inv_times(const Se3T<S>& g, const Vec<6, S>& x) noexcept {
  const Vec<3, S> xw = x.template head<3>();
  return stack3(g.C.transpose() * xw, g.C.transpose() * (x.template tail<3>() - g.R.cross(xw)));
}

//! ad_ξ x = [ω × x_ω; v × x_ω + ω × x_v], the product without the 6×6 matrix.
template <class S>
inline Vec<6, S> se3_ad_times(const Vec<6, S>& xi, const Vec<6, S>& x) noexcept {
  const Vec<3, S> w = xi.template head<3>();
  const Vec<3, S> xw = x.template head<3>();
  return stack3(w.cross(xw), xi.template tail<3>().cross(xw) + w.cross(x.template tail<3>()));
}

//! ad_ξ = [[ω×, 0], [v×, ω×]]. spec §A.2.1
template <class S>
inline Mat<6, 6, S> se3_ad(const Vec<6, S>& xi) noexcept {
  const Mat<3, 3, S> W = skew(xi.template head<3>());
  Mat<6, 6, S> m;
  m << W, Mat<3, 3, S>::Zero(), skew(xi.template tail<3>()), W;
  return m;
}

//! ad*_ξ := (ad_ξ)ᵀ = [[−ω×, −v×], [0, −ω×]]; Ξ ξ̇ = ad*_ξ Ξ ξ + … is the rigid-body equation.
//! spec §A.2.1, §A.2.2
template <class S>
inline Mat<6, 6, S> se3_ad_star(const Vec<6, S>& xi) noexcept { return se3_ad(xi).transpose(); }

// =============================================================================================
// Exponential and logarithm. spec §A.2.1

//! log of an active rotation matrix: θ with exp(θ×) = C and ‖θ‖ ∈ [0, π] (up to rounding).
//! Robust form of the spec: unit quaternion by Shepperd's method with q0 ≥ 0 (dcm_to_quat(),
//! which takes the passive C_BN = Cᵀ), then θ = 2 atan2(‖q_v‖, q0) q_v/‖q_v‖, or 2 q_v/q0 when
//! ‖q_v‖ < 1e-12. Accurate to a few ε for every angle, including 0 and π (where θ and −θ are
//! both valid and either may be returned). The arccos/trace form is deliberately not used.
//! Any NaN/Inf entry in C gives θ = NaN (see the file comment).
template <class S>
inline Vec<3, S> so3_log(const Mat<3, 3, S>& C) noexcept {
  if (!all_finite(C)) return Vec<3, S>::Constant(std::numeric_limits<S>::quiet_NaN());
  const QuaternionSFT<S> q = dcm_to_quat(Mat<3, 3, S>(C.transpose()));
  const S q0 = q.w();
  const Vec<3, S> qv = q.vec();
  const S n = qv.norm();
  if (n < S(1e-12)) return (S(2) / q0) * qv;  // atan2(n, q0)/n = 1/q0 to O(n²) = O(1e-24)
  return (S(2) * std::atan2(n, q0) / n) * qv;
}

//! Left Jacobian V(θ) = I + ((1−cosφ)/φ²) θ× + ((φ−sinφ)/φ³)(θ×)². spec §A.2.1
template <class S>
inline Mat<3, 3, S> so3_left_jacobian(const Vec<3, S>& theta) noexcept {
  const S phi = theta.norm();
  const Mat<3, 3, S> Th = skew(theta);
  return Mat<3, 3, S>::Identity() + so3_coeff_one_minus_cos(phi) * Th +
         so3_coeff_phi_minus_sin(phi) * (Th * Th);
}

//! V(θ)⁻¹ = I − ½θ× + α(φ)(θ×)². spec §A.2.1. Exists for φ < 2π.
template <class S>
inline Mat<3, 3, S> so3_left_jacobian_inv(const Vec<3, S>& theta) noexcept {
  const Mat<3, 3, S> Th = skew(theta);
  return Mat<3, 3, S>::Identity() - S(0.5) * Th + se3_alpha(theta.norm()) * (Th * Th);
}

//! exp(η^) = (exp(θ×), V(θ) β) for η = [θ; β]. spec §A.2.1
template <class S>
inline Se3T<S> se3_exp(const Vec<6, S>& eta) noexcept {
  const Vec<3, S> theta = eta.template head<3>();
  return Se3T<S>{so3_exp(theta), so3_left_jacobian(theta) * eta.template tail<3>()};
}

//! log(g)^∨ = [θ; V(θ)⁻¹ R], θ = so3_log(C), ‖θ‖ ≤ π. spec §A.2.1, §A.2.3, seed 003 eq. (7)
template <class S>
inline Vec<6, S> se3_log(const Se3T<S>& g) noexcept {
  const Vec<3, S> theta = so3_log(g.C);
  return stack3(theta, so3_left_jacobian_inv(theta) * g.R);
}

// =============================================================================================
// Error kinematics η̇ = G(η) ξ_e. spec §A.2.3, seed 003 eq. (8)
//
// G(η) = Σ B_n/n! (−ad_η)ⁿ (inverse right Jacobian of SE(3)). −ad_η is block lower-triangular
// with equal diagonal blocks −θ×, so G = [[A, 0], [T, A]] with T(θ,β) = d/ds A(θ + sβ)|₀.
// The same identity gives Ȧ = T(θ, θ̇) (spec §A.5).

namespace detail {

//! T from precomputed pieces: Th = θ×, B = β×, tb = θᵀβ, a = α(φ), g = γ(φ). spec §A.2.3
template <class S>
inline Mat<3, 3, S> se3_T_from(const Mat<3, 3, S>& Th, const Mat<3, 3, S>& B, S tb, S a, S g) noexcept {
  return S(0.5) * B + a * (Th * B + B * Th) + (g * tb) * (Th * Th);
}

}  // namespace detail

//! A(θ) = I + ½θ× + α(φ)(θ×)². spec §A.2.3
template <class S>
inline Mat<3, 3, S> se3_A(const Vec<3, S>& theta) noexcept {
  const Mat<3, 3, S> Th = skew(theta);
  return Mat<3, 3, S>::Identity() + S(0.5) * Th + se3_alpha(theta.norm()) * (Th * Th);
}

//! A(θ)⁻¹ = I − ((1−cosφ)/φ²) θ× + ((φ−sinφ)/φ³)(θ×)² = V(θ)ᵀ. spec §A.2.3. Exists for φ < 2π.
template <class S>
inline Mat<3, 3, S> se3_A_inv(const Vec<3, S>& theta) noexcept {
  return so3_left_jacobian(theta).transpose();
}

//! T(θ,β) = ½β× + α(φ)(θ×β× + β×θ×) + γ(φ)(θᵀβ)(θ×)². spec §A.2.3
template <class S>
inline Mat<3, 3, S> se3_T(const Vec<3, S>& theta, const Vec<3, S>& beta) noexcept {
  const S phi = theta.norm();
  return detail::se3_T_from(skew(theta), skew(beta), theta.dot(beta), se3_alpha(phi), se3_gamma(phi));
}

//! G(η) = [[A(θ), 0], [T(θ,β), A(θ)]], the matrix of η̇ = G(η) ξ_e. spec §A.2.3, seed 003 eq. (9)
template <class S>
inline Mat<6, 6, S> se3_G(const Vec<6, S>& eta) noexcept {
  const Vec<3, S> theta = eta.template head<3>();
  const Vec<3, S> beta = eta.template tail<3>();
  const S phi = theta.norm();
  const S a = se3_alpha(phi);
  const Mat<3, 3, S> Th = skew(theta);
  const Mat<3, 3, S> Th2 = Th * Th;
  const Mat<3, 3, S> A = Mat<3, 3, S>::Identity() + S(0.5) * Th + a * Th2;
  Mat<6, 6, S> G;
  G << A, Mat<3, 3, S>::Zero(), detail::se3_T_from(Th, skew(beta), theta.dot(beta), a, se3_gamma(phi)), A;
  return G;
}

//! G(η)⁻¹ = [[A⁻¹, 0], [−A⁻¹ T A⁻¹, A⁻¹]] in closed form; exists for ‖θ‖ < 2π, hence on the
//! whole log chart (det A = ((φ/2)/sin(φ/2))² ≥ 1). spec §A.2.3, paper Proposition 1
template <class S>
inline Mat<6, 6, S> se3_G_inv(const Vec<6, S>& eta) noexcept {
  const Vec<3, S> theta = eta.template head<3>();
  const Mat<3, 3, S> Ai = se3_A_inv(theta);
  Mat<6, 6, S> Gi;
  Gi << Ai, Mat<3, 3, S>::Zero(), -(Ai * se3_T(theta, Vec<3, S>(eta.template tail<3>())) * Ai), Ai;
  return Gi;
}

//! Ȧ = ½θ̇× + α(θ̇×θ× + θ×θ̇×) + γ(θᵀθ̇)(θ×)², i.e. T(θ, θ̇). spec §A.5
template <class S>
inline Mat<3, 3, S> se3_A_dot(const Vec<3, S>& theta, const Vec<3, S>& theta_dot) noexcept {
  return se3_T(theta, theta_dot);
}

//! Ṫ = d/dt T(θ,β) along (θ̇, β̇), closed form (differentiating spec §A.2.3 term by term, with
//! α̇ = γ θᵀθ̇ and γ̇ = (γ'/φ) θᵀθ̇):
//!   Ṫ = ½β̇× + α(θ̇×β× + θ×β̇× + β̇×θ× + β×θ̇×) + γ(θᵀθ̇)(θ×β× + β×θ×)
//!     + [(γ'/φ)(θᵀθ̇)(θᵀβ) + γ(θ̇ᵀβ + θᵀβ̇)](θ×)² + γ(θᵀβ)(θ̇×θ× + θ×θ̇×).
template <class S>
inline Mat<3, 3, S> se3_T_dot(const Vec<3, S>& theta, const Vec<3, S>& beta, const Vec<3, S>& theta_dot,
                              const Vec<3, S>& beta_dot) noexcept {
  const S phi = theta.norm();
  const S a = se3_alpha(phi);
  const S g = se3_gamma(phi);
  const S tb = theta.dot(beta);
  const S ttd = theta.dot(theta_dot);
  const Mat<3, 3, S> Th = skew(theta), B = skew(beta), Thd = skew(theta_dot);
  // The terms linear in β̇ are T(θ, β̇); the rest come from differentiating in θ.
  return detail::se3_T_from(Th, skew(beta_dot), theta.dot(beta_dot), a, g) +
         a * (Thd * B + B * Thd) + (g * ttd) * (Th * B + B * Th) +
         (se3_gamma_rate(phi) * ttd * tb + g * theta_dot.dot(beta)) * (Th * Th) +
         (g * tb) * (Thd * Th + Th * Thd);
}

//! Ġ(η, η̇) = [[Ȧ, 0], [Ṫ, Ȧ]], the derivative of G along η̇. spec §A.5
template <class S>
inline Mat<6, 6, S> se3_G_dot(const Vec<6, S>& eta, const Vec<6, S>& eta_dot) noexcept {
  const Vec<3, S> theta = eta.template head<3>();
  const Vec<3, S> theta_dot = eta_dot.template head<3>();
  const Mat<3, 3, S> Ad = se3_A_dot(theta, theta_dot);
  Mat<6, 6, S> Gd;
  Gd << Ad, Mat<3, 3, S>::Zero(),
      se3_T_dot(theta, Vec<3, S>(eta.template tail<3>()), theta_dot, Vec<3, S>(eta_dot.template tail<3>())), Ad;
  return Gd;
}

//! Ġ ξ: directional derivative of η ↦ G(η) ξ along η̇ (used with η̇ = G ξ_e in the
//! controller's ż₂, spec §A.5). Closed form, no finite difference.
template <class S>
inline Vec<6, S> se3_G_dot_xi(const Vec<6, S>& eta, const identity_t<Vec<6, S>>& eta_dot,
                              const identity_t<Vec<6, S>>& xi) noexcept {
  return se3_G_dot(eta, eta_dot) * xi;
}

// =============================================================================================
// The whole error kinematics of one control step, spec §A.2.3-§A.5, at the cost of a few cross
// products: a law needs log(g_e), G, G⁻¹, η̇ = G ξ_e and Ġ ξ_e at the same η. The functions
// above build every 3×3 block and multiply them (≈ 25 3×3 products and ~15 trig calls per step);
// here the coefficients are computed once and T(θ,b) x, Ṫ x are applied as cross products,
// using (a×)(b×) = b aᵀ − (aᵀb) I for the blocks G and G⁻¹ must hold as matrices.
// Agreement with se3_G, se3_G_inv, se3_G_dot_xi, se3_log: tests/math/test_se3.cpp.

namespace detail {

//! T(θ,b) x = ½ b×x + α(θ×(b×x) + b×(θ×x)) + γ(θᵀb) θ×(θ×x). spec §A.2.3
template <class S>
inline Vec<3, S> se3_T_times(const Vec<3, S>& theta, const Vec<3, S>& b, const Vec<3, S>& x, S a, S g) noexcept {
  const Vec<3, S> tx = theta.cross(x);
  const Vec<3, S> bx = b.cross(x);
  return S(0.5) * bx + a * (theta.cross(bx) + b.cross(tx)) + (g * theta.dot(b)) * theta.cross(tx);
}

//! Ṫ x along (θ̇, β̇), the se3_T_dot() formula applied to x term by term.
template <class S>
inline Vec<3, S> se3_T_dot_times(const Vec<3, S>& theta, const Vec<3, S>& beta, const Vec<3, S>& theta_dot,
                                 const Vec<3, S>& beta_dot, const Vec<3, S>& x,
                                 const Se3ExpCoordCoefficientsT<S>& k) noexcept {
  const S a = k.alpha, g = k.gamma;
  const S tb = theta.dot(beta), ttd = theta.dot(theta_dot);
  const Vec<3, S> tx = theta.cross(x), bx = beta.cross(x), tdx = theta_dot.cross(x);
  return se3_T_times(theta, beta_dot, x, a, g) + a * (theta_dot.cross(bx) + beta.cross(tdx)) +
         (g * ttd) * (theta.cross(bx) + beta.cross(tx)) +
         (k.gamma_rate * ttd * tb + g * theta_dot.dot(beta)) * theta.cross(tx) +
         (g * tb) * (theta_dot.cross(tx) + theta.cross(tdx));
}

}  // namespace detail

//! G(η) = [[A, 0], [T, A]] kept as its 3×3 blocks, with A⁻¹ (spec §A.2.3, seed 003 eq. (9)): a
//! law only multiplies vectors by G, Gᵀ and G⁻¹, and the block-triangular form does each in
//! 2-3 3×3 products instead of a dense 6×6 product or an explicit −A⁻¹TA⁻¹.
//! Like an Eigen matrix, a default-constructed one is uninitialised (identity() gives G(0) = I):
//! se3_error_kinematics() writes every block, and zeroing them first would cost memset calls
//! in every control step on the Cortex-M7 (issue 7 budget).
template <class S = double>
struct Se3GBlocksT {
  using M3 = Mat<3, 3, S>;
  using V3 = Vec<3, S>;
  using V6 = Vec<6, S>;
  M3 A;      //!< A(θ), both diagonal blocks
  M3 T;      //!< T(θ, β), the lower-left block
  M3 A_inv;  //!< A(θ)⁻¹ = V(θ)ᵀ

  static Se3GBlocksT identity() noexcept { return Se3GBlocksT{M3::Identity(), M3::Zero(), M3::Identity()}; }

  //! G x = [A x_ω; T x_ω + A x_v].
  V6 times(const V6& x) const noexcept {
    const V3 xw = x.template head<3>();
    return stack3(A * xw, T * xw + A * x.template tail<3>());
  }
  //! Gᵀ x = [Aᵀ x_ω + Tᵀ x_v; Aᵀ x_v].
  V6 transpose_times(const V6& x) const noexcept {
    const V3 xv = x.template tail<3>();
    return stack3(A.transpose() * x.template head<3>() + T.transpose() * xv, A.transpose() * xv);
  }
  //! G⁻¹ y by block forward substitution: x_ω = A⁻¹ y_ω, x_v = A⁻¹ (y_v − T x_ω).
  V6 inverse_times(const V6& y) const noexcept {
    const V3 xw = A_inv * y.template head<3>();
    return stack3(xw, A_inv * (y.template tail<3>() - T * xw));
  }
  //! G as a dense 6×6 matrix (logging, tests).
  Mat<6, 6, S> matrix() const noexcept {
    Mat<6, 6, S> G;
    G << A, M3::Zero(), T, A;
    return G;
  }
  //! G⁻¹ = [[A⁻¹, 0], [−A⁻¹ T A⁻¹, A⁻¹]] as a dense 6×6 matrix (logging, tests).
  Mat<6, 6, S> inverse_matrix() const noexcept {
    Mat<6, 6, S> Gi;
    Gi << A_inv, M3::Zero(), -(A_inv * T * A_inv), A_inv;
    return Gi;
  }
  bool finite() const noexcept { return all_finite(A) && all_finite(T) && all_finite(A_inv); }
};
using Se3GBlocks = Se3GBlocksT<double>;

//! log(g_e) and everything a seed 003 law needs at that η (spec §A.2.3, §A.5, paper (8)).
//! Only se3_error_kinematics() makes one and it writes every member, so the members have no
//! default initialisers (see Se3GBlocks).
template <class S = double>
struct Se3ErrorKinematicsT {
  Vec<6, S> eta;          //!< η = log(g)^∨ = [θ; β] [rad; m]
  Se3GBlocksT<S> G;       //!< G(η) and G(η)⁻¹
  Vec<6, S> eta_dot;      //!< η̇ = G(η) ξ
  Vec<6, S> G_dot_xi;     //!< Ġ(η, η̇) ξ
};
using Se3ErrorKinematics = Se3ErrorKinematicsT<double>;

//! se3_log(g), se3_G, se3_G_inv, G ξ and se3_G_dot_xi(η, G ξ, ξ) in one pass.
template <class S>
inline Se3ErrorKinematicsT<S> se3_error_kinematics(const Se3T<S>& g, const identity_t<Vec<6, S>>& xi) noexcept {
  using M3 = Mat<3, 3, S>;
  using V3 = Vec<3, S>;
  Se3ErrorKinematicsT<S> out;
  const V3 theta = so3_log(g.C);
  const Se3ExpCoordCoefficientsT<S> k = se3_exp_coord_coefficients(theta.norm());
  const V3 tR = theta.cross(g.R);
  const V3 beta = g.R - S(0.5) * tR + k.alpha * theta.cross(tR);  // V(θ)⁻¹ R, spec §A.2.1
  out.eta = stack3(theta, beta);

  const M3 I = M3::Identity();
  const S tb = theta.dot(beta);
  const M3 Th = skew(theta);
  const M3 Th2 = theta * theta.transpose() - theta.squaredNorm() * I;    // (θ×)²
  const M3 ThB_BTh = beta * theta.transpose() + theta * beta.transpose() - S(2) * tb * I;  // θ×β× + β×θ×
  out.G.A = I + S(0.5) * Th + k.alpha * Th2;                                // spec §A.2.3
  out.G.T = S(0.5) * skew(beta) + k.alpha * ThB_BTh + (k.gamma * tb) * Th2;
  out.G.A_inv = I - k.one_minus_cos * Th + k.phi_minus_sin * Th2;          // A⁻¹ = V(θ)ᵀ

  const V3 w = xi.template head<3>(), v = xi.template tail<3>();
  const V3 theta_dot = out.G.A * w;
  const V3 beta_dot = out.G.T * w + out.G.A * v;
  out.eta_dot = stack3(theta_dot, beta_dot);                                // seed 003 eq. (8)
  // Ġ ξ = [Ȧ ω; Ṫ ω + Ȧ v] with Ȧ = T(θ, θ̇), spec §A.5.
  out.G_dot_xi = stack3(detail::se3_T_times(theta, theta_dot, w, k.alpha, k.gamma),
                        detail::se3_T_dot_times(theta, beta, theta_dot, beta_dot, w, k) +
                            detail::se3_T_times(theta, theta_dot, v, k.alpha, k.gamma));
  return out;
}

// Expression arguments (core/types.hpp), for the one- and two-vector entries.
ADCS_ACCEPT_EXPRESSIONS_1(so3_log)
ADCS_ACCEPT_EXPRESSIONS_1(so3_left_jacobian)
ADCS_ACCEPT_EXPRESSIONS_1(so3_left_jacobian_inv)
ADCS_ACCEPT_EXPRESSIONS_1(se3_exp)
ADCS_ACCEPT_EXPRESSIONS_1(se3_A)
ADCS_ACCEPT_EXPRESSIONS_1(se3_A_inv)
ADCS_ACCEPT_EXPRESSIONS_1(se3_G)
ADCS_ACCEPT_EXPRESSIONS_1(se3_G_inv)
ADCS_ACCEPT_EXPRESSIONS_1(se3_hat)
ADCS_ACCEPT_EXPRESSIONS_1(se3_ad)
ADCS_ACCEPT_EXPRESSIONS_1(se3_ad_star)
ADCS_ACCEPT_EXPRESSIONS_2(se3_T)
ADCS_ACCEPT_EXPRESSIONS_2(se3_A_dot)
ADCS_ACCEPT_EXPRESSIONS_2(se3_G_dot)
ADCS_ACCEPT_EXPRESSIONS_2(se3_ad_times)

}  // namespace adcs
