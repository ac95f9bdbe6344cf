// SE(3) primitives and exponential-coordinate kinematics (seed 003, spec §A.2.1, §A.2.3, §A.5),
// checked as spec §A.11 items 1-4 ask: round trips, Ad/ad identities, G(η) against central
// finite differences of s ↦ log(g exp(sξ^)), Ġ against finite differences of G, det A, and the
// continuity of every series/closed-form switch. Truth comes from independent routes: matrix
// exponentials in homogeneous form, commutators, typed-in rotation matrices, finite differences.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

#include "adcs/math/se3.hpp"

namespace ADCS_UNITY_ID {

using adcs::Mat3;
using adcs::Mat6;
using adcs::Se3;
using adcs::Vec3;
using adcs::Vec6;
using Mat4 = adcs::Mat<4, 4>;

constexpr double kPi = 3.14159265358979323846;
constexpr double kEps = std::numeric_limits<double>::epsilon();
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kSwitch = adcs::kExpCoordSeriesSwitch;

// Fixed seed: every run sees the same samples.
class Rng {
 public:
  explicit Rng(std::uint64_t seed) : gen_(seed) {}
  double uniform(double lo, double hi) {
    return std::uniform_real_distribution<double>(lo, hi)(gen_);
  }
  Vec3 vec3(double r) { return Vec3(uniform(-r, r), uniform(-r, r), uniform(-r, r)); }
  Vec6 vec6(double r) {
    Vec6 x;
    x << vec3(r), vec3(r);
    return x;
  }
  Vec3 unit3() {
    Vec3 v = vec3(1.0);
    while (v.norm() < 1e-3) v = vec3(1.0);
    return v.normalized();
  }
  //! η = [θ; β] with ‖θ‖ = phi and β uniform in [−b, b]³ (b = 50 m: spec §A.2.3 prototype range).
  Vec6 eta(double phi, double b = 50.0) {
    Vec6 e;
    e << unit3() * phi, vec3(b);
    return e;
  }

 private:
  std::mt19937_64 gen_;
};

template <class M>
double max_abs(const M& m) {
  return m.cwiseAbs().maxCoeff();
}

// Angles the spec names (A.11 item 1), both sides of the series switch, and near π.
const double kSpecialPhi[] = {0.0,     1e-9, 1e-4, std::nextafter(kSwitch, 0.0),
                              kSwitch, 1.0,  kPi - 1e-6};

//! Exponential of a 4×4 twist by scaling and squaring of its Taylor series: an independent
//! route to exp(η^) (no V(θ), no Rodrigues).
Mat4 expm4(const Mat4& X) {
  int squarings = 0;
  double n = X.cwiseAbs().rowwise().sum().maxCoeff();
  while (n > 0.25) {
    n *= 0.5;
    ++squarings;
  }
  const Mat4 Y = X / std::ldexp(1.0, squarings);
  Mat4 E = Mat4::Identity(), term = Mat4::Identity();
  for (int k = 1; k <= 20; ++k) {
    term = term * Y / k;
    E += term;
  }
  for (int i = 0; i < squarings; ++i) E = E * E;
  return E;
}

// =============================================================================================
// A.11 item 1: exp/log round trips

TEST(Se3, So3LogOfTypedInActiveRotationAboutZ) {
  // Active rotation by +0.3 rad about z (Ċ = C ω×, body -> inertial): log must be +0.3 ẑ, which
  // pins the transpose handed to the passive-DCM dcm_to_quat().
  const double a = 0.3;
  Mat3 C;
  C << std::cos(a), -std::sin(a), 0, std::sin(a), std::cos(a), 0, 0, 0, 1;
  EXPECT_LE((adcs::so3_log(C) - Vec3(0, 0, a)).norm(), 2 * kEps);
}

TEST(Se3, LogOfExpIsIdentityOnTheChart) {
  Rng rng(0x5e3001);
  double worst = 0.0;
  auto check = [&](const Vec6& eta) {
    const double err = (adcs::se3_log(adcs::se3_exp(eta)) - eta).norm() / std::max(1.0, eta.norm());
    worst = std::max(worst, err);
  };
  for (double phi : kSpecialPhi)
    for (int k = 0; k < 20; ++k) check(rng.eta(phi));
  for (int k = 0; k < 1000; ++k) check(rng.eta(rng.uniform(0.0, kPi - 1e-6)));
  EXPECT_LE(worst, 1e-12);  // relative to max(1, ‖η‖); measured 7.8e-16
}

TEST(Se3, ExpOfLogIsIdentityOnTheGroup) {
  Rng rng(0x5e3002);
  double worst_C = 0.0, worst_R = 0.0;
  auto check = [&](const Se3& g) {
    const Se3 h = adcs::se3_exp(adcs::se3_log(g));
    worst_C = std::max(worst_C, max_abs(h.C - g.C));
    worst_R = std::max(worst_R, (h.R - g.R).norm() / std::max(1.0, g.R.norm()));
  };
  for (double phi : {0.0, 1e-9, 1e-4, kSwitch, 1.0, kPi - 1e-6, kPi})
    for (int k = 0; k < 20; ++k) check(Se3{adcs::so3_exp(rng.unit3() * phi), rng.vec3(100.0)});
  for (int k = 0; k < 1000; ++k)
    check(Se3{adcs::so3_exp(rng.unit3() * rng.uniform(0.0, kPi)), rng.vec3(100.0)});
  EXPECT_LE(worst_C, 1e-12);  // measured 8.9e-16
  EXPECT_LE(worst_R, 1e-12);  // relative to max(1, ‖R‖); measured 5.5e-16
}

TEST(Se3, ExpMatchesTheMatrixExponentialOfTheTwist) {
  Rng rng(0x5e3009);
  double worst = 0.0;
  for (int k = 0; k < 200; ++k) {
    const Vec6 eta = rng.eta(k < 7 ? kSpecialPhi[k] : rng.uniform(0.0, kPi));
    const Mat4 E = expm4(adcs::se3_hat(eta));
    worst = std::max(worst, max_abs(adcs::se3_matrix(adcs::se3_exp(eta)) - E) /
                                std::max(1.0, eta.norm()));
  }
  EXPECT_LE(worst, 1e-12);  // measured 1.5e-14, limited by the squarings in expm4
}

TEST(Se3, So3LogAtAndNearPiStaysOnTheChart) {
  Rng rng(0x5e3003);
  for (int k = 0; k < 50; ++k) {
    const Vec3 n = rng.unit3();
    // Exactly φ = π: C = 2nnᵀ − I, typed in (θ and −θ are both valid logs).
    const Mat3 C_pi = 2.0 * n * n.transpose() - Mat3::Identity();
    // Just beyond π the short rotation is about −n: ‖θ‖ = 2π − φ.
    for (double phi : {kPi - 1e-6, kPi - 1e-9, kPi + 1e-9, kPi + 1e-6}) {
      const Mat3 C = adcs::so3_exp(n * phi);
      const Vec3 theta = adcs::so3_log(C);
      // ‖θ‖ ≤ π up to the rounding of 2·atan2 and of a unit-vector norm.
      EXPECT_LE(theta.norm(), kPi * (1.0 + 4.0 * kEps));
      EXPECT_GE(theta.norm(), std::min(phi, 2.0 * kPi - phi) - 1e-12);
      EXPECT_LE(max_abs(adcs::so3_exp(theta) - C), 1e-12);
    }
    const Vec3 theta = adcs::so3_log(C_pi);
    EXPECT_NEAR(theta.norm(), kPi, 4.0 * kPi * kEps);
    EXPECT_LE(max_abs(adcs::so3_exp(theta) - C_pi), 1e-12);
  }
}

TEST(Se3, NonFiniteInputPropagatesToTheOutput) {
  // Documented behaviour: no branch launders NaN/Inf into a finite number.
  for (double bad : {kNaN, kInf, -kInf}) {
    for (int i = 0; i < 9; ++i) {
      Se3 g = adcs::se3_exp(Rng(i).eta(1.0));
      g.C(i / 3, i % 3) = bad;
      EXPECT_FALSE(adcs::all_finite(adcs::se3_log(g)))
          << "C(" << i / 3 << "," << i % 3 << ") = " << bad;
    }
    Se3 g = Se3::identity();
    g.R(1) = bad;
    EXPECT_FALSE(adcs::all_finite(adcs::se3_log(g)));
    Vec6 eta = Vec6::Constant(0.1);
    eta(0) = bad;
    EXPECT_FALSE(adcs::all_finite(adcs::se3_G(eta)));
    EXPECT_FALSE(adcs::all_finite(adcs::se3_exp(eta).C));
  }
}

// =============================================================================================
// A.11 item 2: Ad / ad identities

TEST(Se3, AdjointAndCoadjointIdentities) {
  Rng rng(0x5e3004);
  for (int k = 0; k < 200; ++k) {
    const Se3 g1 = adcs::se3_exp(rng.eta(rng.uniform(0, kPi), 100.0));
    const Se3 g2 = adcs::se3_exp(rng.eta(rng.uniform(0, kPi), 100.0));
    const Vec6 xi = rng.vec6(2.0), zeta = rng.vec6(2.0);
    const double scale = 1.0 + g1.R.norm() + g2.R.norm();

    // Group helpers against homogeneous matrices.
    const Mat4 G1 = adcs::se3_matrix(g1), G2 = adcs::se3_matrix(g2);
    EXPECT_LE(max_abs(adcs::se3_matrix(adcs::se3_compose(g1, g2)) - G1 * G2), 1e-13 * scale);
    EXPECT_LE(max_abs(adcs::se3_matrix(adcs::se3_inverse(g1)) * G1 - Mat4::Identity()),
              1e-13 * scale);
    EXPECT_EQ(adcs::se3_vee(adcs::se3_hat(xi)), xi);

    // Ad_{g1 g2} = Ad_{g1} Ad_{g2}; Ad_{g⁻¹} = (Ad_g)⁻¹.
    const Mat6 Ad1 = adcs::se3_Ad(g1);
    EXPECT_LE(max_abs(adcs::se3_Ad(adcs::se3_compose(g1, g2)) - Ad1 * adcs::se3_Ad(g2)),
              1e-12 * scale);
    EXPECT_LE(max_abs(adcs::se3_Ad_inv(g1) * Ad1 - Mat6::Identity()), 1e-12 * scale);
    EXPECT_LE(max_abs(adcs::se3_Ad_inv(g1) - adcs::se3_Ad(adcs::se3_inverse(g1))),
              1e-13 * scale);

    // (Ad_g ξ)^ = g ξ^ g⁻¹ in 4×4 homogeneous form.
    EXPECT_LE(max_abs(adcs::se3_hat(Ad1 * xi) - G1 * adcs::se3_hat(xi) * G1.inverse()),
              1e-12 * scale);

    // ad_ξ is the commutator: (ad_ξ ζ)^ = ξ^ζ^ − ζ^ξ^; ad* is its transpose.
    const Mat4 X = adcs::se3_hat(xi), Z = adcs::se3_hat(zeta);
    EXPECT_LE(max_abs(adcs::se3_hat(adcs::se3_ad(xi) * zeta) - (X * Z - Z * X)), 1e-14);
    EXPECT_EQ(adcs::se3_ad_star(xi), adcs::se3_ad(xi).transpose());

    // ad*_ξ Ξ ξ = [−ω×Jω; −m ω×v] for Ξ = diag(J, m I3). spec §A.2.2
    const Vec3 d = rng.vec3(1.0).cwiseAbs() + Vec3::Constant(0.5);
    const Mat3 Rj = adcs::so3_exp(rng.vec3(kPi));
    const Mat3 J = 100.0 * Rj * d.asDiagonal() * Rj.transpose();  // SPD, kg m²
    const double m = rng.uniform(50.0, 200.0);                      // kg
    Mat6 Xi = Mat6::Zero();
    Xi.topLeftCorner<3, 3>() = J;
    Xi.bottomRightCorner<3, 3>() = m * Mat3::Identity();
    const Vec3 w = xi.head<3>(), v = xi.tail<3>();
    Vec6 expected;
    expected << -w.cross(J * w), -m * w.cross(v);
    EXPECT_LE((adcs::se3_ad_star(xi) * (Xi * xi) - expected).norm(),
              1e-12 * (1.0 + expected.norm()));
  }
}

// =============================================================================================
// A.11 item 3: G(η), G⁻¹, det A, Ġ

TEST(Se3, GMatchesFiniteDifferenceOfLogAlongATwist) {
  // η̇ = G(η) ξ for ġ = g ξ^, so G(η) ξ = d/ds log(exp(η) exp(s ξ^))|₀.
  Rng rng(0x5e3005);
  constexpr double h = 1e-6;
  double worst = 0.0;
  for (int k = 0; k < 500; ++k) {
    // Mostly uniform φ up to 0.999π, plus every special angle below that.
    const double phi = k < 60 ? kSpecialPhi[k % 6] : rng.uniform(0.0, 0.999 * kPi);
    const Vec6 eta = rng.eta(phi);
    const Vec6 xi = rng.vec6(1.0);
    const Se3 g = adcs::se3_exp(eta);
    const Vec6 fd = (adcs::se3_log(adcs::se3_compose(g, adcs::se3_exp(h * xi))) -
                     adcs::se3_log(adcs::se3_compose(g, adcs::se3_exp(-h * xi)))) / (2.0 * h);
    const Vec6 an = adcs::se3_G(eta) * xi;
    worst = std::max(worst, (fd - an).norm() / an.norm());
  }
  EXPECT_LT(worst, 1e-5);  // measured 4.7e-9 (finite-difference limited)
}

TEST(Se3, GAtZeroInverseAndDeterminant) {
  EXPECT_EQ(adcs::se3_G(Vec6::Zero()), Mat6::Identity());

  Rng rng(0x5e3006);
  double worst_inv = 0.0, worst_V = 0.0;
  for (int k = 0; k < 300; ++k) {
    const Vec6 eta = rng.eta(k < 7 ? kSpecialPhi[k] : rng.uniform(0.0, 0.999 * kPi));
    worst_inv = std::max(worst_inv,
                         max_abs(adcs::se3_G_inv(eta) * adcs::se3_G(eta) - Mat6::Identity()));
    // V (coefficients (1−cosφ)/φ², (φ−sinφ)/φ³) and V⁻¹ (coefficient α) are independent formulas.
    const Vec3 theta = eta.head<3>();
    const Mat3 VVi = adcs::so3_left_jacobian(theta) * adcs::so3_left_jacobian_inv(theta);
    worst_V = std::max(worst_V, max_abs(VVi - Mat3::Identity()));
  }
  EXPECT_LE(worst_inv, 1e-10);  // measured 1.5e-14 with ‖β‖ up to 87 m
  EXPECT_LE(worst_V, 1e-14);    // measured 4.4e-16

  // det A(θ) = ((φ/2)/sin(φ/2))²: the complex eigenvalue pair has modulus (φ/2)/sin(φ/2).
  for (int k = 0; k < 200; ++k) {
    const double phi = k < 7 ? kSpecialPhi[k] : rng.uniform(0.0, kPi);
    const double r = phi == 0.0 ? 1.0 : (0.5 * phi) / std::sin(0.5 * phi);
    EXPECT_NEAR(adcs::se3_A(rng.unit3() * phi).determinant(), r * r, 1e-14 * r * r)
        << "phi = " << phi;
  }
}

TEST(Se3, GDotMatchesFiniteDifferenceOfG) {
  // Ġ(η, η̇) ξ = d/ds G(η + s η̇) ξ|₀; step as spec §A.5 prescribes for its own central difference.
  Rng rng(0x5e3007);
  const double phis[] = {0.0, 1e-4, 0.04, 0.06, 0.9, 1.1, 2.0, 0.999 * kPi};
  double worst = 0.0, worst_Adot = 0.0;
  for (int k = 0; k < 400; ++k) {
    const Vec6 eta = rng.eta(k < 80 ? phis[k % 8] : rng.uniform(0.0, 0.999 * kPi));
    const Vec6 eta_dot = rng.vec6(1.0), xi = rng.vec6(1.0);
    const double h = 1e-6 * std::max(1.0, eta.norm()) / eta_dot.norm();
    const Vec6 fd =
        (adcs::se3_G(eta + h * eta_dot) * xi - adcs::se3_G(eta - h * eta_dot) * xi) / (2.0 * h);
    const Vec6 an = adcs::se3_G_dot_xi(eta, eta_dot, xi);
    worst = std::max(worst, (fd - an).norm() / an.norm());
    // Ȧ in the spec §A.5 closed form, typed in independently of se3_A_dot().
    const Vec3 th = eta.head<3>(), thd = eta_dot.head<3>();
    const Mat3 T = adcs::skew(th), Td = adcs::skew(thd);
    const double phi = th.norm();
    const Mat3 Adot = 0.5 * Td + adcs::se3_alpha(phi) * (Td * T + T * Td) +
                      adcs::se3_gamma(phi) * th.dot(thd) * T * T;
    worst_Adot = std::max(worst_Adot, max_abs(adcs::se3_A_dot(th, thd) - Adot));
  }
  EXPECT_LT(worst, 1e-6);        // measured 1.6e-9 (finite-difference limited)
  EXPECT_LE(worst_Adot, 1e-15);  // measured 0 (same arithmetic)

  // ‖η̇‖ = 0 gives Ġ = 0 exactly.
  EXPECT_EQ(adcs::se3_G_dot_xi(rng.eta(1.0), Vec6::Zero(), rng.vec6(1.0)), Vec6::Zero());
}

// =============================================================================================
// A.11 item 4: series / closed-form switches

double rel_jump(double (*f)(double), double at) {
  const double above = f(at);
  return std::abs(f(std::nextafter(at, 0.0)) - above) / std::abs(above);
}

TEST(Se3, SeriesAndClosedFormAgreeAtTheSwitch) {
  EXPECT_LT(rel_jump(adcs::se3_alpha, kSwitch), 1e-12);               // measured 2.9e-13
  EXPECT_LT(rel_jump(adcs::so3_coeff_one_minus_cos, kSwitch), 1e-12);  // measured 1.1e-16
  EXPECT_LT(rel_jump(adcs::so3_coeff_phi_minus_sin, kSwitch), 1e-12);  // measured 3.6e-14

  // γ: 1e-12 is out of reach at φ = 0.05. The closed form sums three terms of size ≤ 2/φ⁴ to
  // γ ≈ 1/360; with a few ulps each the absolute error is ≲ 20 (ε/2)/φ⁴, i.e. a relative bound
  // of 3600 ε/φ⁴ = 1.3e-7 at the switch. Measured 1.1e-9 (glibc).
  EXPECT_LT(rel_jump(adcs::se3_gamma, kSwitch), 3600.0 * kEps / std::pow(kSwitch, 4));
  // …and that error does not reach G: γ is weighted by ≈ φ³/180 relative to T's ½β×, so its
  // share of T's jump is ~1e-15. The jump of T is dominated by α's (≈ 3e-13 × α's weight φ/3).
  Rng rng(0x5e3008);
  double worst_T = 0.0;
  for (int k = 0; k < 100; ++k) {
    const Vec3 n = rng.unit3(), beta = rng.vec3(50.0);
    const Mat3 T_above = adcs::se3_T(n * kSwitch, beta);
    const Mat3 T_below = adcs::se3_T(n * std::nextafter(kSwitch, 0.0), beta);
    worst_T = std::max(worst_T, (T_above - T_below).norm() / T_above.norm());
  }
  EXPECT_LT(worst_T, 1e-13);  // measured 5.5e-15

  // γ'/φ (used by Ṫ) switches at φ = 1, where both branches are accurate.
  EXPECT_LT(rel_jump(adcs::se3_gamma_rate, adcs::kGammaRateSeriesSwitch), 1e-12);  // meas. 5.6e-13
}

TEST(Se3, CoefficientsSatisfyTheirDefiningRelations) {
  // α = (½(1−cosφ)/φ² − (φ−sinφ)/φ³)/(sinφ/φ) follows from V V⁻¹ = I; γ = α'/φ and
  // γ'/φ are checked by central differences where the differenced function is accurate.
  for (double phi : {0.0, 1e-6, 0.01, 0.049, 0.05, 0.3, 1.0, 2.0, 3.0, kPi - 1e-6}) {
    const double s = phi == 0.0 ? 1.0 : std::sin(phi) / phi;
    const double alpha = adcs::se3_alpha(phi);
    const double rhs = 0.5 * adcs::so3_coeff_one_minus_cos(phi) - adcs::so3_coeff_phi_minus_sin(phi);
    EXPECT_NEAR(alpha * s, rhs, 1e-12 * alpha) << "phi = " << phi;  // 2e-13 rel. at 0.05
  }
  constexpr double h = 1e-3;
  for (double phi : {0.5, 1.0, 1.5, 2.5}) {
    const double g_fd = (adcs::se3_alpha(phi + h) - adcs::se3_alpha(phi - h)) / (2.0 * h * phi);
    EXPECT_NEAR(adcs::se3_gamma(phi), g_fd, 1e-6 * adcs::se3_gamma(phi)) << "phi = " << phi;
    const double r_fd = (adcs::se3_gamma(phi + h) - adcs::se3_gamma(phi - h)) / (2.0 * h * phi);
    EXPECT_NEAR(adcs::se3_gamma_rate(phi), r_fd, 1e-6 * adcs::se3_gamma_rate(phi))
        << "phi = " << phi;
  }
  // Values at φ = 0 are the series' leading terms.
  EXPECT_EQ(adcs::se3_alpha(0.0), 1.0 / 12.0);
  EXPECT_EQ(adcs::se3_gamma(0.0), 1.0 / 360.0);
  EXPECT_EQ(adcs::se3_gamma_rate(0.0), 1.0 / 3780.0);
}

// =============================================================================================
// The one-pass error kinematics (se3_error_kinematics, the seed 003 laws' path) against the
// single functions above, which the finite-difference tests check.

TEST(Se3, SharedCoefficientsMatchTheSingleFunctions) {
  const auto rel = [](double a, double b) { return std::fabs(a - b) / std::fabs(b); };
  Rng rng(0x5e300a);
  for (int k = 0; k < 2000; ++k) {
    const double phi = k < 7 ? kSpecialPhi[k] : k < 14 ? -kSpecialPhi[k - 7] : rng.uniform(0.0, kPi);
    const double a = std::max(std::fabs(phi), kSwitch);
    const adcs::Se3ExpCoordCoefficients c = adcs::se3_exp_coord_coefficients(phi);
    EXPECT_EQ(c.phi, phi);
    EXPECT_EQ(c.one_minus_cos, adcs::so3_coeff_one_minus_cos(phi));  // same expression
    EXPECT_EQ(c.phi_minus_sin, adcs::so3_coeff_phi_minus_sin(phi));  // same expression
    // Both routes of each closed form cancel to O(1): α by 12/φ² (measured errors against
    // long double: 9 ε/φ² with tan, 16 ε/φ² with sin/cos), γ by ≈ 1e3/φ⁴ (se3_gamma), γ'/φ
    // by ≈ 5e4/φ⁶ above its switch at 1 rad (se3_gamma_rate). Below the switches: one series.
    EXPECT_LE(rel(c.alpha, adcs::se3_alpha(phi)), 40.0 * kEps / (a * a)) << "phi = " << phi;
    EXPECT_LE(rel(c.gamma, adcs::se3_gamma(phi)), 3600.0 * kEps / std::pow(a, 4)) << "phi = " << phi;
    EXPECT_LE(rel(c.gamma_rate, adcs::se3_gamma_rate(phi)), 1e5 * kEps) << "phi = " << phi;
    if (std::fabs(phi) < kSwitch) {
      EXPECT_EQ(c.alpha, adcs::se3_alpha(phi));
      EXPECT_EQ(c.gamma, adcs::se3_gamma(phi));
    }
  }
  // Below the switch both are the series: identical.
  const adcs::Se3ExpCoordCoefficients c0 = adcs::se3_exp_coord_coefficients(0.0);
  EXPECT_EQ(c0.alpha, 1.0 / 12.0);
  EXPECT_EQ(c0.gamma, 1.0 / 360.0);
  EXPECT_EQ(c0.gamma_rate, 1.0 / 3780.0);
}

TEST(Se3, OnePassErrorKinematicsMatchesTheSingleFunctions) {
  Rng rng(0x5e300b);
  const double phis[] = {0.0, 1e-9, 1e-4, 0.049, 0.051, 0.9, 1.1, 2.0, 0.999 * kPi};
  double worst = 0.0;
  for (int k = 0; k < 600; ++k) {
    const Vec6 eta = rng.eta(k < 90 ? phis[k % 9] : rng.uniform(0.0, 0.999 * kPi));
    const Se3 g = adcs::se3_exp(eta);
    const Vec6 xi = rng.vec6(k % 2 == 0 ? 1.0 : 0.05);
    const adcs::Se3ErrorKinematics e = adcs::se3_error_kinematics(g, xi);
    const Vec6 eta_ref = adcs::se3_log(g);
    const Mat6 G = adcs::se3_G(eta_ref);
    const Vec6 eta_dot = G * xi;
    const double s = 1.0 + eta_ref.norm();
    const Vec6 y = rng.vec6(1.0);
    worst = std::max({worst, (e.G.times(y) - G * y).norm() / s,
                      (e.G.transpose_times(y) - G.transpose() * y).norm() / s,
                      (e.G.inverse_times(y) - adcs::se3_G_inv(eta_ref) * y).norm() / (s * s)});
    worst = std::max({worst, (e.eta - eta_ref).norm() / s, max_abs(e.G.matrix() - G) / s,
                      max_abs(e.G.inverse_matrix() - adcs::se3_G_inv(eta_ref)) / (s * s),
                      (e.eta_dot - eta_dot).norm() / (s * (1.0 + xi.norm())),
                      (e.G_dot_xi - adcs::se3_G_dot_xi(eta_ref, eta_dot, xi)).norm() /
                          (s * (1.0 + xi.norm()) * (1.0 + xi.norm()))});
  }
  EXPECT_LE(worst, 1e-12);
  // The zero-twist and identity cases are exact; Se3GBlocks::identity() is G(0).
  EXPECT_EQ(adcs::Se3GBlocks::identity().matrix(), Mat6::Identity());
  EXPECT_EQ(adcs::Se3GBlocks::identity().inverse_matrix(), Mat6::Identity());
  const adcs::Se3ErrorKinematics id = adcs::se3_error_kinematics(Se3::identity(), Vec6::Zero());
  EXPECT_EQ(id.eta, Vec6::Zero());
  EXPECT_EQ(id.G.matrix(), Mat6::Identity());
  EXPECT_EQ(id.G.inverse_matrix(), Mat6::Identity());
  EXPECT_EQ(id.G_dot_xi, Vec6::Zero());
  // Non-finite input propagates (se3_tracking_error checks its result with all_finite()).
  Se3 bad = Se3::identity();
  bad.R(2) = kNaN;
  EXPECT_FALSE(adcs::all_finite(adcs::se3_error_kinematics(bad, Vec6::Zero()).eta));
  bad = Se3::identity();
  bad.C(0, 1) = kInf;
  EXPECT_FALSE(adcs::all_finite(adcs::se3_error_kinematics(bad, Vec6::Zero()).G.matrix()));
}

TEST(Se3, MatrixFreeAdjointProductsMatchTheMatrices) {
  Rng rng(0x5e300c);
  for (int k = 0; k < 200; ++k) {
    const Se3 g = adcs::se3_exp(rng.eta(rng.uniform(0, kPi), 100.0));
    const Vec6 xi = rng.vec6(2.0), x = rng.vec6(2.0);
    EXPECT_LE((adcs::se3_Ad_inv_times(g, x) - adcs::se3_Ad_inv(g) * x).norm(), 1e-13 * (1.0 + g.R.norm()));
    EXPECT_LE((adcs::se3_ad_times(xi, x) - adcs::se3_ad(xi) * x).norm(), 1e-14);
  }
}

}  // namespace

using namespace ADCS_UNITY_ID;  // as an anonymous namespace would (CMakeLists.txt, adcs_unity)
