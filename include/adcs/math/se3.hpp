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
#include <cmath>
#include <limits>

#include "adcs/core/types.hpp"
#include "adcs/math/quaternion.hpp"
#include "adcs/math/so3.hpp"

namespace adcs {

// =============================================================================================
// Scalar coefficients. Each is an even function of φ: a closed form, and a Taylor series below a
// switch where the closed form loses digits by cancellation.

//! Switch between Taylor series (|φ| < 0.05) and closed form for α, (1−cosφ)/φ², (φ−sinφ)/φ³
//! and γ. spec §A.2.1, §A.2.3
inline constexpr double kExpCoordSeriesSwitch = 0.05;  //!< [rad]

//! (1 − cos φ)/φ². spec §A.2.1. The closed form is evaluated as ½(sin(φ/2)/(φ/2))², equal in
//! exact arithmetic but free of the 1 − cos φ cancellation. The series carries the φ⁶ term, one
//! more than the spec lists, whose omission would leave 8e-13 relative at the switch.
inline double so3_coeff_one_minus_cos(double phi) noexcept {
  const double p2 = phi * phi;
  if (std::abs(phi) < kExpCoordSeriesSwitch) {
    return 0.5 + p2 * (-1.0 / 24.0 + p2 * (1.0 / 720.0 - p2 / 40320.0));
  }
  const double s = std::sin(0.5 * phi) / (0.5 * phi);
  return 0.5 * s * s;
}

//! (φ − sin φ)/φ³. spec §A.2.1. Series with the φ⁶ term added (spec truncation: 3e-13 at the
//! switch). The closed form loses ≈ 6ε/φ² relative (≈ 3e-13 at the switch).
inline double so3_coeff_phi_minus_sin(double phi) noexcept {
  const double p2 = phi * phi;
  if (std::abs(phi) < kExpCoordSeriesSwitch) {
    return 1.0 / 6.0 + p2 * (-1.0 / 120.0 + p2 * (1.0 / 5040.0 - p2 / 362880.0));
  }
  return (phi - std::sin(phi)) / (p2 * phi);
}

//! α(φ) = (1/φ²)(1 − (φ/2) cot(φ/2)), the (θ×)² coefficient of V⁻¹ and A. spec §A.2.1.
//! Series = Σ |B₂ₙ|/(2n)! φ²ⁿ⁻² (Bernoulli numbers), as listed in the spec.
inline double se3_alpha(double phi) noexcept {
  const double p2 = phi * phi;
  if (std::abs(phi) < kExpCoordSeriesSwitch) {
    return 1.0 / 12.0 + p2 * (1.0 / 720.0 + p2 * (1.0 / 30240.0 + p2 / 1209600.0));
  }
  const double h = 0.5 * phi;
  return (1.0 - h / std::tan(h)) / p2;
}

//! γ(φ) = α'(φ)/φ = −2/φ⁴ + cot(φ/2)/(2φ³) + 1/(4φ² sin²(φ/2)). spec §A.2.3.
//! Series with the φ⁶ term added (spec truncation: 9e-13 at the switch).
//! Accuracy: the closed form cancels three O(1/φ⁴) terms to O(1); its relative error is
//! ≈ 1e3 ε/φ⁴: 1e-9 to 2e-8 just above the switch (measured against 50-digit values; the test
//! bounds it by 3600 ε/φ⁴ = 1.3e-7) and 1e-14 at φ = 1. Rearranging the closed form does not
//! help (the cancellation is intrinsic). The spec fixes the switch at 0.05 anyway, and the error
//! is harmless where γ is used: in T it multiplies (θᵀβ)(θ×)², of size ≤ φ³‖β‖, so its absolute
//! effect on T is ≲ 3 ε ‖β‖/φ ≈ 1e-14 ‖β‖ at the switch.
inline double se3_gamma(double phi) noexcept {
  const double p2 = phi * phi;
  if (std::abs(phi) < kExpCoordSeriesSwitch) {
    return 1.0 / 360.0 + p2 * (1.0 / 7560.0 + p2 * (1.0 / 201600.0 + p2 / 5987520.0));
  }
  const double h = 0.5 * phi;
  const double s = std::sin(h);
  return -2.0 / (p2 * p2) + 1.0 / (2.0 * std::tan(h) * p2 * phi) + 1.0 / (4.0 * p2 * s * s);
}

//! Switch for se3_gamma_rate(): its closed form cancels O(1/φ⁶) terms (relative error
//! ≈ 5e4 ε/φ⁶: 1e-4 at φ = 0.05, 5e-13 at φ = 1), so the series is used up to φ = 1.
//! Not in the spec (which has no closed form for Ṫ); chosen here.
inline constexpr double kGammaRateSeriesSwitch = 1.0;  //!< [rad]

//! γ'(φ)/φ, needed for Ṫ (the time derivative of γ(φ) is this times θᵀθ̇).
//! Closed form, with w = (φ/2)/sin(φ/2) and k = (φ/2)cot(φ/2):
//!   γ'(φ)/φ = (8 − 3w² − 3k − 2w²k)/φ⁶.
//! Series Σ_{n≥3} (2n−2)(2n−4)|B₂ₙ|/(2n)! φ²ⁿ⁻⁶ through φ²⁰ (truncation < 2e-16 relative at 1).
inline double se3_gamma_rate(double phi) noexcept {
  const double p2 = phi * phi;
  if (std::abs(phi) < kGammaRateSeriesSwitch) {
    // Coefficients from the Bernoulli numbers B₆ … B₂₆ (exact rationals, rounded once).
    constexpr double c[] = {1.0 / 3780.0,
                            1.0 / 50400.0,
                            1.0 / 997920.0,
                            691.0 / 16345929600.0,
                            1.0 / 622702080.0,
                            3617.0 / 63515612160000.0,
                            43867.0 / 22808456326656000.0,
                            174611.0 / 2787700217702400000.0,
                            77683.0 / 39169722331643904000.0,
                            236364091.0 / 3849600310753962885120000.0,
                            657931.0 / 352527500984795136000000.0};
    double acc = c[10];
    for (int i = 9; i >= 0; --i) acc = c[i] + p2 * acc;  // Horner in φ²
    return acc;
  }
  const double h = 0.5 * phi;
  const double s = std::sin(h);
  const double w2 = (h * h) / (s * s);
  const double k = h / std::tan(h);
  return (8.0 - 3.0 * w2 - 3.0 * k - 2.0 * w2 * k) / (p2 * p2 * p2);
}

//! Every φ-dependent coefficient above at one φ, from one sin/cos pair of φ/2 and one sin φ
//! instead of the ~15 sin/tan calls the separate functions make when a control step needs G, G⁻¹,
//! Ġ ξ and log together (each newlib sin/tan is hundreds of Cortex-M7 instructions; issue 7
//! budget). Same formulas and switches as the single functions: the series branches are the
//! very same expressions; the closed forms write tan(φ/2) as sin/cos, which moves α and γ by a
//! few ulp × their own cancellation factor (α ≲ 24ε/φ², γ ≲ 1e3ε/φ⁴ relative, see se3_gamma),
//! tested against the single functions in tests/math/test_se3.cpp.
struct Se3ExpCoordCoefficients {
  double phi = 0.0;                   //!< φ = ‖θ‖ [rad]
  double one_minus_cos = 0.5;         //!< (1 − cos φ)/φ²
  double phi_minus_sin = 1.0 / 6.0;   //!< (φ − sin φ)/φ³
  double alpha = 1.0 / 12.0;          //!< α(φ)
  double gamma = 1.0 / 360.0;         //!< γ(φ)
  double gamma_rate = 1.0 / 3780.0;   //!< γ'(φ)/φ
};

inline Se3ExpCoordCoefficients se3_exp_coord_coefficients(double phi) noexcept {
  Se3ExpCoordCoefficients k;
  k.phi = phi;
  if (std::abs(phi) < kExpCoordSeriesSwitch) {  // series only: no trig at all
    k.gamma_rate = se3_gamma_rate(phi);
    k.one_minus_cos = so3_coeff_one_minus_cos(phi);
    k.phi_minus_sin = so3_coeff_phi_minus_sin(phi);
    k.alpha = se3_alpha(phi);
    k.gamma = se3_gamma(phi);
    return k;
  }
  const double p2 = phi * phi;
  const double h = 0.5 * phi;
  const double s = std::sin(h);
  const double c = std::cos(h);
  const double sinc_h = s / h;                                 // sin(φ/2)/(φ/2)
  const double h_cot_h = h * c / s;                            // (φ/2) cot(φ/2)
  k.one_minus_cos = 0.5 * sinc_h * sinc_h;                     // as so3_coeff_one_minus_cos
  k.phi_minus_sin = (phi - std::sin(phi)) / (p2 * phi);        // as so3_coeff_phi_minus_sin
  k.alpha = (1.0 - h_cot_h) / p2;                              // as se3_alpha
  k.gamma = -2.0 / (p2 * p2) + c / (2.0 * s * p2 * phi) + 1.0 / (4.0 * p2 * s * s);  // as se3_gamma
  if (std::abs(phi) < kGammaRateSeriesSwitch) {                // as se3_gamma_rate
    k.gamma_rate = se3_gamma_rate(phi);                        // its series: no trig
  } else {
    const double w2 = 1.0 / (sinc_h * sinc_h);
    k.gamma_rate = (8.0 - 3.0 * w2 - 3.0 * h_cot_h - 2.0 * w2 * h_cot_h) / (p2 * p2 * p2);
  }
  return k;
}

// =============================================================================================
// The group SE(3) and its algebra. spec §A.2.1

//! g = (C, R): homogeneous [[C, R], [0, 1]].
struct Se3 {
  Mat3 C;  //!< [-] active rotation, body -> inertial
  Vec3 R;  //!< [m] position in inertial components

  static Se3 identity() noexcept { return Se3{Mat3::Identity(), Vec3::Zero()}; }
};

//! g1 g2 = (C1 C2, R1 + C1 R2).
inline Se3 se3_compose(const Se3& g1, const Se3& g2) noexcept {
  return Se3{g1.C * g2.C, g1.R + g1.C * g2.R};
}

//! g⁻¹ = (Cᵀ, −Cᵀ R). spec §A.2.1
inline Se3 se3_inverse(const Se3& g) noexcept {
  return Se3{g.C.transpose(), -(g.C.transpose() * g.R)};
}

//! Homogeneous 4×4 matrix [[C, R], [0, 1]].
inline Mat<4, 4> se3_matrix(const Se3& g) noexcept {
  Mat<4, 4> m = Mat<4, 4>::Identity();
  m.topLeftCorner<3, 3>() = g.C;
  m.topRightCorner<3, 1>() = g.R;
  return m;
}

//! ξ^ = [[ω×, v], [0, 0]] for ξ = [ω; v]. spec §A.2.1
inline Mat<4, 4> se3_hat(const Vec6& xi) noexcept {
  Mat<4, 4> m = Mat<4, 4>::Zero();
  m.topLeftCorner<3, 3>() = skew(xi.head<3>());
  m.topRightCorner<3, 1>() = xi.tail<3>();
  return m;
}

//! Inverse of se3_hat() (the skew part of the upper-left block is taken if it is not skew).
inline Vec6 se3_vee(const Mat<4, 4>& m) noexcept {
  Vec6 xi;
  xi << vee(m.topLeftCorner<3, 3>()), m.topRightCorner<3, 1>();
  return xi;
}

//! Ad_g = [[C, 0], [R×C, C]]. spec §A.2.1
inline Mat6 se3_Ad(const Se3& g) noexcept {
  Mat6 m;
  m << g.C, Mat3::Zero(), skew(g.R) * g.C, g.C;
  return m;
}

//! Ad_{g⁻¹} = [[Cᵀ, 0], [−Cᵀ R×, Cᵀ]], without forming g⁻¹. spec §A.2.1
inline Mat6 se3_Ad_inv(const Se3& g) noexcept {
  const Mat3 Ct = g.C.transpose();
  Mat6 m;
  m << Ct, Mat3::Zero(), -(Ct * skew(g.R)), Ct;
  return m;
}

//! Ad_{g⁻¹} x = [Cᵀ x_ω; Cᵀ (x_v − R × x_ω)], the product without the 6×6 matrix.
inline Vec6 se3_Ad_inv_times(const Se3& g, const Vec6& x) noexcept {
  const Vec3 xw = x.head<3>();
  return stack3(g.C.transpose() * xw, g.C.transpose() * (x.tail<3>() - g.R.cross(xw)));
}

//! ad_ξ x = [ω × x_ω; v × x_ω + ω × x_v], the product without the 6×6 matrix.
inline Vec6 se3_ad_times(const Vec6& xi, const Vec6& x) noexcept {
  const Vec3 w = xi.head<3>();
  const Vec3 xw = x.head<3>();
  return stack3(w.cross(xw), xi.tail<3>().cross(xw) + w.cross(x.tail<3>()));
}

//! ad_ξ = [[ω×, 0], [v×, ω×]]. spec §A.2.1
inline Mat6 se3_ad(const Vec6& xi) noexcept {
  const Mat3 W = skew(xi.head<3>());
  Mat6 m;
  m << W, Mat3::Zero(), skew(xi.tail<3>()), W;
  return m;
}

//! ad*_ξ := (ad_ξ)ᵀ = [[−ω×, −v×], [0, −ω×]]; Ξ ξ̇ = ad*_ξ Ξ ξ + … is the rigid-body equation.
//! spec §A.2.1, §A.2.2
inline Mat6 se3_ad_star(const Vec6& xi) noexcept { return se3_ad(xi).transpose(); }

// =============================================================================================
// Exponential and logarithm. spec §A.2.1

//! log of an active rotation matrix: θ with exp(θ×) = C and ‖θ‖ ∈ [0, π] (up to rounding).
//! Robust form of the spec: unit quaternion by Shepperd's method with q0 ≥ 0 (dcm_to_quat(),
//! which takes the passive C_BN = Cᵀ), then θ = 2 atan2(‖q_v‖, q0) q_v/‖q_v‖, or 2 q_v/q0 when
//! ‖q_v‖ < 1e-12. Accurate to a few ε for every angle, including 0 and π (where θ and −θ are
//! both valid and either may be returned). The arccos/trace form is deliberately not used.
//! Any NaN/Inf entry in C gives θ = NaN (see the file comment).
inline Vec3 so3_log(const Mat3& C) noexcept {
  if (!all_finite(C)) return Vec3::Constant(std::numeric_limits<double>::quiet_NaN());
  const QuaternionSF q = dcm_to_quat(C.transpose());
  const double q0 = q.w();
  const Vec3 qv = q.vec();
  const double n = qv.norm();
  if (n < 1e-12) return (2.0 / q0) * qv;  // atan2(n, q0)/n = 1/q0 to O(n²) = O(1e-24)
  return (2.0 * std::atan2(n, q0) / n) * qv;
}

//! Left Jacobian V(θ) = I + ((1−cosφ)/φ²) θ× + ((φ−sinφ)/φ³)(θ×)². spec §A.2.1
inline Mat3 so3_left_jacobian(const Vec3& theta) noexcept {
  const double phi = theta.norm();
  const Mat3 Th = skew(theta);
  return Mat3::Identity() + so3_coeff_one_minus_cos(phi) * Th +
         so3_coeff_phi_minus_sin(phi) * (Th * Th);
}

//! V(θ)⁻¹ = I − ½θ× + α(φ)(θ×)². spec §A.2.1. Exists for φ < 2π.
inline Mat3 so3_left_jacobian_inv(const Vec3& theta) noexcept {
  const Mat3 Th = skew(theta);
  return Mat3::Identity() - 0.5 * Th + se3_alpha(theta.norm()) * (Th * Th);
}

//! exp(η^) = (exp(θ×), V(θ) β) for η = [θ; β]. spec §A.2.1
inline Se3 se3_exp(const Vec6& eta) noexcept {
  const Vec3 theta = eta.head<3>();
  return Se3{so3_exp(theta), so3_left_jacobian(theta) * eta.tail<3>()};
}

//! log(g)^∨ = [θ; V(θ)⁻¹ R], θ = so3_log(C), ‖θ‖ ≤ π. spec §A.2.1, §A.2.3, seed 003 eq. (7)
inline Vec6 se3_log(const Se3& g) noexcept {
  const Vec3 theta = so3_log(g.C);
  Vec6 eta;
  eta << theta, so3_left_jacobian_inv(theta) * g.R;
  return eta;
}

// =============================================================================================
// Error kinematics η̇ = G(η) ξ_e. spec §A.2.3, seed 003 eq. (8)
//
// G(η) = Σ B_n/n! (−ad_η)ⁿ (inverse right Jacobian of SE(3)). −ad_η is block lower-triangular
// with equal diagonal blocks −θ×, so G = [[A, 0], [T, A]] with T(θ,β) = d/ds A(θ + sβ)|₀.
// The same identity gives Ȧ = T(θ, θ̇) (spec §A.5).

namespace detail {

//! T from precomputed pieces: Th = θ×, B = β×, tb = θᵀβ, a = α(φ), g = γ(φ). spec §A.2.3
inline Mat3 se3_T_from(const Mat3& Th, const Mat3& B, double tb, double a, double g) noexcept {
  return 0.5 * B + a * (Th * B + B * Th) + (g * tb) * (Th * Th);
}

}  // namespace detail

//! A(θ) = I + ½θ× + α(φ)(θ×)². spec §A.2.3
inline Mat3 se3_A(const Vec3& theta) noexcept {
  const Mat3 Th = skew(theta);
  return Mat3::Identity() + 0.5 * Th + se3_alpha(theta.norm()) * (Th * Th);
}

//! A(θ)⁻¹ = I − ((1−cosφ)/φ²) θ× + ((φ−sinφ)/φ³)(θ×)² = V(θ)ᵀ. spec §A.2.3. Exists for φ < 2π.
inline Mat3 se3_A_inv(const Vec3& theta) noexcept { return so3_left_jacobian(theta).transpose(); }

//! T(θ,β) = ½β× + α(φ)(θ×β× + β×θ×) + γ(φ)(θᵀβ)(θ×)². spec §A.2.3
inline Mat3 se3_T(const Vec3& theta, const Vec3& beta) noexcept {
  const double phi = theta.norm();
  return detail::se3_T_from(skew(theta), skew(beta), theta.dot(beta), se3_alpha(phi),
                            se3_gamma(phi));
}

//! G(η) = [[A(θ), 0], [T(θ,β), A(θ)]], the matrix of η̇ = G(η) ξ_e. spec §A.2.3, seed 003 eq. (9)
inline Mat6 se3_G(const Vec6& eta) noexcept {
  const Vec3 theta = eta.head<3>();
  const Vec3 beta = eta.tail<3>();
  const double phi = theta.norm();
  const double a = se3_alpha(phi);
  const Mat3 Th = skew(theta);
  const Mat3 Th2 = Th * Th;
  const Mat3 A = Mat3::Identity() + 0.5 * Th + a * Th2;
  Mat6 G;
  G << A, Mat3::Zero(), detail::se3_T_from(Th, skew(beta), theta.dot(beta), a, se3_gamma(phi)), A;
  return G;
}

//! G(η)⁻¹ = [[A⁻¹, 0], [−A⁻¹ T A⁻¹, A⁻¹]] in closed form; exists for ‖θ‖ < 2π, hence on the
//! whole log chart (det A = ((φ/2)/sin(φ/2))² ≥ 1). spec §A.2.3, paper Proposition 1
inline Mat6 se3_G_inv(const Vec6& eta) noexcept {
  const Vec3 theta = eta.head<3>();
  const Mat3 Ai = se3_A_inv(theta);
  Mat6 Gi;
  Gi << Ai, Mat3::Zero(), -(Ai * se3_T(theta, eta.tail<3>()) * Ai), Ai;
  return Gi;
}

//! Ȧ = ½θ̇× + α(θ̇×θ× + θ×θ̇×) + γ(θᵀθ̇)(θ×)², i.e. T(θ, θ̇). spec §A.5
inline Mat3 se3_A_dot(const Vec3& theta, const Vec3& theta_dot) noexcept {
  return se3_T(theta, theta_dot);
}

//! Ṫ = d/dt T(θ,β) along (θ̇, β̇), closed form (differentiating spec §A.2.3 term by term, with
//! α̇ = γ θᵀθ̇ and γ̇ = (γ'/φ) θᵀθ̇):
//!   Ṫ = ½β̇× + α(θ̇×β× + θ×β̇× + β̇×θ× + β×θ̇×) + γ(θᵀθ̇)(θ×β× + β×θ×)
//!     + [(γ'/φ)(θᵀθ̇)(θᵀβ) + γ(θ̇ᵀβ + θᵀβ̇)](θ×)² + γ(θᵀβ)(θ̇×θ× + θ×θ̇×).
inline Mat3 se3_T_dot(const Vec3& theta, const Vec3& beta, const Vec3& theta_dot,
                      const Vec3& beta_dot) noexcept {
  const double phi = theta.norm();
  const double a = se3_alpha(phi);
  const double g = se3_gamma(phi);
  const double tb = theta.dot(beta);
  const double ttd = theta.dot(theta_dot);
  const Mat3 Th = skew(theta), B = skew(beta), Thd = skew(theta_dot);
  // The terms linear in β̇ are T(θ, β̇); the rest come from differentiating in θ.
  return detail::se3_T_from(Th, skew(beta_dot), theta.dot(beta_dot), a, g) +
         a * (Thd * B + B * Thd) + (g * ttd) * (Th * B + B * Th) +
         (se3_gamma_rate(phi) * ttd * tb + g * theta_dot.dot(beta)) * (Th * Th) +
         (g * tb) * (Thd * Th + Th * Thd);
}

//! Ġ(η, η̇) = [[Ȧ, 0], [Ṫ, Ȧ]], the derivative of G along η̇. spec §A.5
inline Mat6 se3_G_dot(const Vec6& eta, const Vec6& eta_dot) noexcept {
  const Vec3 theta = eta.head<3>();
  const Vec3 theta_dot = eta_dot.head<3>();
  const Mat3 Ad = se3_A_dot(theta, theta_dot);
  Mat6 Gd;
  Gd << Ad, Mat3::Zero(), se3_T_dot(theta, eta.tail<3>(), theta_dot, eta_dot.tail<3>()), Ad;
  return Gd;
}

//! Ġ ξ: directional derivative of η ↦ G(η) ξ along η̇ (used with η̇ = G ξ_e in the
//! controller's ż₂, spec §A.5). Closed form, no finite difference.
inline Vec6 se3_G_dot_xi(const Vec6& eta, const Vec6& eta_dot, const Vec6& xi) noexcept {
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
inline Vec3 se3_T_times(const Vec3& theta, const Vec3& b, const Vec3& x, double a, double g) noexcept {
  const Vec3 tx = theta.cross(x);
  const Vec3 bx = b.cross(x);
  return 0.5 * bx + a * (theta.cross(bx) + b.cross(tx)) + (g * theta.dot(b)) * theta.cross(tx);
}

//! Ṫ x along (θ̇, β̇), the se3_T_dot() formula applied to x term by term.
inline Vec3 se3_T_dot_times(const Vec3& theta, const Vec3& beta, const Vec3& theta_dot, const Vec3& beta_dot,
                            const Vec3& x, const Se3ExpCoordCoefficients& k) noexcept {
  const double a = k.alpha, g = k.gamma;
  const double tb = theta.dot(beta), ttd = theta.dot(theta_dot);
  const Vec3 tx = theta.cross(x), bx = beta.cross(x), tdx = theta_dot.cross(x);
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
struct Se3GBlocks {
  Mat3 A;      //!< A(θ), both diagonal blocks
  Mat3 T;      //!< T(θ, β), the lower-left block
  Mat3 A_inv;  //!< A(θ)⁻¹ = V(θ)ᵀ

  static Se3GBlocks identity() noexcept { return Se3GBlocks{Mat3::Identity(), Mat3::Zero(), Mat3::Identity()}; }

  //! G x = [A x_ω; T x_ω + A x_v].
  Vec6 times(const Vec6& x) const noexcept {
    const Vec3 xw = x.head<3>();
    return stack3(A * xw, T * xw + A * x.tail<3>());
  }
  //! Gᵀ x = [Aᵀ x_ω + Tᵀ x_v; Aᵀ x_v].
  Vec6 transpose_times(const Vec6& x) const noexcept {
    const Vec3 xv = x.tail<3>();
    return stack3(A.transpose() * x.head<3>() + T.transpose() * xv, A.transpose() * xv);
  }
  //! G⁻¹ y by block forward substitution: x_ω = A⁻¹ y_ω, x_v = A⁻¹ (y_v − T x_ω).
  Vec6 inverse_times(const Vec6& y) const noexcept {
    const Vec3 xw = A_inv * y.head<3>();
    return stack3(xw, A_inv * (y.tail<3>() - T * xw));
  }
  //! G as a dense 6×6 matrix (logging, tests).
  Mat6 matrix() const noexcept {
    Mat6 G;
    G << A, Mat3::Zero(), T, A;
    return G;
  }
  //! G⁻¹ = [[A⁻¹, 0], [−A⁻¹ T A⁻¹, A⁻¹]] as a dense 6×6 matrix (logging, tests).
  Mat6 inverse_matrix() const noexcept {
    Mat6 Gi;
    Gi << A_inv, Mat3::Zero(), -(A_inv * T * A_inv), A_inv;
    return Gi;
  }
  bool finite() const noexcept { return all_finite(A) && all_finite(T) && all_finite(A_inv); }
};

//! log(g_e) and everything a seed 003 law needs at that η (spec §A.2.3, §A.5, paper (8)).
//! Only se3_error_kinematics() makes one and it writes every member, so the members have no
//! default initialisers (see Se3GBlocks).
struct Se3ErrorKinematics {
  Vec6 eta;          //!< η = log(g)^∨ = [θ; β] [rad; m]
  Se3GBlocks G;      //!< G(η) and G(η)⁻¹
  Vec6 eta_dot;      //!< η̇ = G(η) ξ
  Vec6 G_dot_xi;     //!< Ġ(η, η̇) ξ
};

//! se3_log(g), se3_G, se3_G_inv, G ξ and se3_G_dot_xi(η, G ξ, ξ) in one pass.
inline Se3ErrorKinematics se3_error_kinematics(const Se3& g, const Vec6& xi) noexcept {
  Se3ErrorKinematics out;
  const Vec3 theta = so3_log(g.C);
  const Se3ExpCoordCoefficients k = se3_exp_coord_coefficients(theta.norm());
  const Vec3 tR = theta.cross(g.R);
  const Vec3 beta = g.R - 0.5 * tR + k.alpha * theta.cross(tR);  // V(θ)⁻¹ R, spec §A.2.1
  out.eta = stack3(theta, beta);

  const Mat3 I = Mat3::Identity();
  const double tb = theta.dot(beta);
  const Mat3 Th = skew(theta);
  const Mat3 Th2 = theta * theta.transpose() - theta.squaredNorm() * I;    // (θ×)²
  const Mat3 ThB_BTh = beta * theta.transpose() + theta * beta.transpose() - 2.0 * tb * I;  // θ×β× + β×θ×
  out.G.A = I + 0.5 * Th + k.alpha * Th2;                                   // spec §A.2.3
  out.G.T = 0.5 * skew(beta) + k.alpha * ThB_BTh + (k.gamma * tb) * Th2;
  out.G.A_inv = I - k.one_minus_cos * Th + k.phi_minus_sin * Th2;          // A⁻¹ = V(θ)ᵀ

  const Vec3 w = xi.head<3>(), v = xi.tail<3>();
  const Vec3 theta_dot = out.G.A * w;
  const Vec3 beta_dot = out.G.T * w + out.G.A * v;
  out.eta_dot = stack3(theta_dot, beta_dot);                                // seed 003 eq. (8)
  // Ġ ξ = [Ȧ ω; Ṫ ω + Ȧ v] with Ȧ = T(θ, θ̇), spec §A.5.
  out.G_dot_xi = stack3(detail::se3_T_times(theta, theta_dot, w, k.alpha, k.gamma),
                        detail::se3_T_dot_times(theta, beta, theta_dot, beta_dot, w, k) +
                            detail::se3_T_times(theta, theta_dot, v, k.alpha, k.gamma));
  return out;
}

}  // namespace adcs
