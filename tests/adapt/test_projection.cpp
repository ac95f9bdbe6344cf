// Smooth projection, seed 001 spec §A.7 S13 (i)-(vi), plus bad input.
#include <gtest/gtest.h>

#include <limits>
#include <random>

#include "adcs/adapt/projection.hpp"

namespace ADCS_UNITY_ID {
using adcs::ProjectionParams;
using adcs::Status;
using V6 = adcs::Vec<6>;

const ProjectionParams kP{1e3, 0.05, 0.1};  // seed 001: α_G = 1e3, β = 0.05, δ = 0.1

V6 proj(const V6& th, const V6& phi, bool* active = nullptr, const ProjectionParams& p = kP) {
  V6 out;
  EXPECT_EQ(adcs::smooth_projection<6>(th, phi, p, out, active), Status::ok);
  return out;
}

V6 random_vec(std::mt19937_64& rng, double norm) {
  std::normal_distribution<double> n(0.0, 1.0);
  V6 v;
  for (int i = 0; i < 6; ++i) v(i) = n(rng);
  return v.normalized() * norm;
}

TEST(Projection, InsideTheBallIsTheUnprojectedLaw) {  // S13 (i)
  std::mt19937_64 rng(1);
  for (int k = 0; k < 100; ++k) {
    const V6 th = random_vec(rng, std::sqrt(0.049));
    const V6 phi = random_vec(rng, 2.0);
    bool active = true;
    EXPECT_LT((proj(th, phi, &active) - kP.alpha * phi).norm(), 1e-12);
    EXPECT_FALSE(active);
  }
}

TEST(Projection, InwardDirectionIsNeverCorrected) {  // S13 (ii)
  std::mt19937_64 rng(2);
  for (int k = 0; k < 100; ++k) {
    const V6 th = random_vec(rng, std::sqrt(0.14));
    V6 phi = random_vec(rng, 1.0);
    if (th.dot(phi) > 0) phi = -phi;
    bool active = true;
    EXPECT_LT((proj(th, phi, &active) - kP.alpha * phi).norm(), 1e-12);
    EXPECT_FALSE(active);
  }
}

TEST(Projection, ContinuousAtTheBallBoundary) {  // S13 (iii)
  std::mt19937_64 rng(3);
  for (int k = 0; k < 100; ++k) {
    const V6 dir = random_vec(rng, 1.0);
    V6 phi = random_vec(rng, 1.0);
    if (dir.dot(phi) < 0) phi = -phi;
    const V6 below = proj(dir * std::sqrt(kP.beta - 1e-12), phi);
    const V6 above = proj(dir * std::sqrt(kP.beta + 1e-12), phi);
    EXPECT_LT((below - above).norm(), 1e-6 * kP.alpha);
  }
}

TEST(Projection, TangentOnTheOuterBoundary) {  // S13 (iv)
  std::mt19937_64 rng(4);
  for (int k = 0; k < 100; ++k) {
    const V6 th = random_vec(rng, std::sqrt(kP.beta + kP.delta));
    V6 phi = random_vec(rng, 3.0);
    if (th.dot(phi) < 0) phi = -phi;
    bool active = false;
    const V6 d = proj(th, phi, &active);
    EXPECT_TRUE(active);
    EXPECT_NEAR(th.dot(d), 0.0, 1e-12 * kP.alpha * phi.norm());
  }
}

TEST(Projection, ContinuousLawStaysInTheInvariantBall) {  // S13 (v)
  // Constant outward Φ from θ(0) = 0, RK4 with a small step: ‖θ‖² → β + δ, never above.
  const ProjectionParams p{1.0, 0.05, 0.1};
  const V6 phi = (V6() << 1, -2, 0.5, 0.3, 1, -1).finished();
  V6 th = V6::Zero();
  const double h = 1e-3;
  double max_n2 = 0.0;
  for (int k = 0; k < 20000; ++k) {
    const V6 k1 = proj(th, phi, nullptr, p);
    const V6 k2 = proj(V6(th + 0.5 * h * k1), phi, nullptr, p);
    const V6 k3 = proj(V6(th + 0.5 * h * k2), phi, nullptr, p);
    const V6 k4 = proj(V6(th + h * k3), phi, nullptr, p);
    th += h / 6.0 * (k1 + 2 * k2 + 2 * k3 + k4);
    max_n2 = std::max(max_n2, th.squaredNorm());
  }
  EXPECT_LE(max_n2, p.beta + p.delta + 1e-12);
  EXPECT_NEAR(th.squaredNorm(), p.beta + p.delta, 1e-6);
}

TEST(Projection, LyapunovPropertyForAnyAdmissibleTruth) {  // S13 (vi)
  std::mt19937_64 rng(6);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int k = 0; k < 2000; ++k) {
    const V6 th = random_vec(rng, std::sqrt((kP.beta + kP.delta) * u(rng)));
    const V6 th_star = random_vec(rng, std::sqrt(kP.beta * u(rng)));
    const V6 phi = random_vec(rng, 5.0 * u(rng));
    const double lhs = (th_star - th).dot(kP.alpha * phi - proj(th, phi));
    EXPECT_LE(lhs, 1e-9) << k;
  }
}

TEST(Projection, BadInputLeavesOutputUntouched) {
  const V6 th = V6::Constant(0.1), phi = V6::Constant(1.0);
  V6 out = V6::Constant(42.0);
  V6 bad = phi;
  bad(3) = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(adcs::smooth_projection<6>(th, bad, kP, out), Status::non_finite_input);
  bad = th;
  bad(0) = std::numeric_limits<double>::infinity();
  EXPECT_EQ(adcs::smooth_projection<6>(bad, phi, kP, out), Status::non_finite_input);
  EXPECT_EQ(adcs::smooth_projection<6>(th, phi, ProjectionParams{1.0, 0.0, 0.1}, out),
            Status::invalid_parameter);
  EXPECT_EQ(adcs::smooth_projection<6>(th, phi, ProjectionParams{1.0, 0.05, 0.0}, out),
            Status::invalid_parameter);
  EXPECT_EQ(out, V6::Constant(42.0));
  // Zero-norm θ and zero Φ: no division, plain law.
  V6 zero_out;
  EXPECT_EQ(adcs::smooth_projection<6>(V6::Zero(), V6::Zero(), kP, zero_out), Status::ok);
  EXPECT_EQ(zero_out, V6::Zero());
}

TEST(Projection, RadialSafeguardRescalesOnlyOutside) {
  adcs::Vec<3> th(0.3, 0.3, 0.3);  // ‖θ‖² = 0.27 > 0.15
  EXPECT_TRUE(adcs::radial_safeguard<3>(th, 0.15));
  EXPECT_NEAR(th.squaredNorm(), 0.15, 1e-15);
  EXPECT_NEAR(th(0), th(2), 0.0);
  EXPECT_FALSE(adcs::radial_safeguard<3>(th, 0.15 + 1e-12));
}
}  // namespace

using namespace ADCS_UNITY_ID;  // as an anonymous namespace would (CMakeLists.txt, adcs_unity)
