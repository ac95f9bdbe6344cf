// RBF network and the σ-modification adaptive laws of seed 002 (rbf_network.hpp,
// bound_estimator.hpp), spec §B.3 steps 11-14 and §B.7: B-S11 (h_j ∈ (0, 1], h_4(0) = 1 with the
// §B.5 centre matrix, Ŵ = 0 ⇒ D̂̄ = 0, invalid widths), the ZOH-exact weight step of eq. (13)
// (against RK4, O(T²) from Euler, β = 0), and B-S12 (μ̂ ≥ 0 under eq. (14), exact bound step,
// robust term of eq. (12) bounded by μ̂ and finite for s = 0).
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include "adcs/adapt/bound_estimator.hpp"
#include "adcs/adapt/rbf_network.hpp"

namespace ADCS_UNITY_ID {
using adcs::Status;
using Layer = adcs::RbfLayer<6, 7>;
using V3 = adcs::Vec<3>;
using V6 = adcs::Vec<6>;
using V7 = adcs::Vec<7>;
using W73 = adcs::Mat<7, 3>;

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// Spec §B.5 centre matrix (6 x 7; rows 1-3 ↔ e in deg, rows 4-6 ↔ ė in deg/s), row 6 entry 1
// repaired to −0.03 (B.4-#19).
adcs::Mat<6, 7> spec_centres() {
  adcs::Mat<6, 7> c;
  c << -0.25, -0.17, -0.08, 0, 0.08, 0.17, 0.25,  //
      -0.15, -0.10, -0.05, 0, 0.05, 0.10, 0.15,   //
      -0.20, -0.13, -0.07, 0, 0.07, 0.13, 0.20,   //
      -0.03, -0.02, -0.01, 0, 0.01, 0.02, 0.03,   //
      -0.15, -0.10, -0.05, 0, 0.05, 0.10, 0.15,   //
      -0.03, -0.02, -0.01, 0, 0.01, 0.02, 0.03;
  return c;
}

Layer::Params spec_layer() {
  Layer::Params p;
  p.centers = spec_centres();
  p.widths = V7::Constant(0.1);  // b_j = 0.1, spec §B.5
  return p;
}

// Spec §B.5 adaptation gains.
const V3 kTau = V3::Constant(0.5);
constexpr double kBeta = 0.01, kGamma = 0.01, kSigma = 0.01;

// RK4 of Ẇ_i = τ_i (s_i h − β W_i) with s, h held, n sub-steps over T.
W73 rk4_weights(W73 W, const V7& h, const V3& s, const V3& tau, double beta, double T, int n) {
  auto f = [&](const W73& w) {
    W73 d;
    for (int i = 0; i < 3; ++i) d.col(i) = tau(i) * (s(i) * h - beta * w.col(i));
    return d;
  };
  const double dt = T / n;
  for (int k = 0; k < n; ++k) {
    const W73 k1 = f(W), k2 = f(W + 0.5 * dt * k1), k3 = f(W + 0.5 * dt * k2), k4 = f(W + dt * k3);
    W += dt / 6.0 * (k1 + 2 * k2 + 2 * k3 + k4);
  }
  return W;
}

W73 euler_weights(const W73& W, const V7& h, const V3& s, const V3& tau, double beta, double T) {
  W73 next;
  for (int i = 0; i < 3; ++i) next.col(i) = W.col(i) + T * tau(i) * (s(i) * h - beta * W.col(i));
  return next;
}

// ---------------------------------------------------------------------------------- B-S11

TEST(RbfLayer, SpecCentresGivePeakAtOriginForNodeFour) {  // spec B-S11
  const Layer layer(spec_layer());
  ASSERT_EQ(layer.status(), Status::ok);
  const V7 h = layer.activations(V6::Zero());
  EXPECT_EQ(h(3), 1.0);  // c_4 = 0
  for (int j = 0; j < 7; ++j) {
    if (j == 3) continue;
    EXPECT_GT(h(j), 0.0);
    EXPECT_LT(h(j), 1.0);
  }
  // Symmetric grid: h_j(0) = h_{8−j}(0).
  for (int j = 0; j < 3; ++j) EXPECT_DOUBLE_EQ(h(j), h(6 - j));
}

TEST(RbfLayer, ActivationsFollowTheGaussianFormulaAndLieInUnitInterval) {  // spec B-S11, step 11
  Layer::Params p = spec_layer();
  p.widths << 0.1, 0.2, 0.05, 0.1, 0.3, 0.15, 0.08;  // per-node widths are honoured
  const Layer layer(p);
  ASSERT_EQ(layer.status(), Status::ok);
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u(-0.4, 0.4);
  for (int k = 0; k < 500; ++k) {
    V6 x;
    for (int i = 0; i < 6; ++i) x(i) = u(rng);
    const V7 h = layer.activations(x);
    for (int j = 0; j < 7; ++j) {
      const double expected =
          std::exp(-(x - p.centers.col(j)).squaredNorm() / (2.0 * p.widths(j) * p.widths(j)));
      EXPECT_NEAR(h(j), expected, 1e-15);
      EXPECT_GT(h(j), 0.0);
      EXPECT_LE(h(j), 1.0);
    }
  }
  // h_j = 1 exactly at its own centre, < 1 elsewhere.
  for (int j = 0; j < 7; ++j) {
    EXPECT_EQ(layer.activations(p.centers.col(j))(j), 1.0);
    EXPECT_LT(layer.activations(V6(p.centers.col(j)) + V6::Constant(1e-3))(j), 1.0);
  }
  // Scenario input x = (180/π)[e(0); ė(0)] in degrees (§B.5): e.g. node 7 at c_7 + small offset.
  const V6 x0(0.25, 0.15, -0.20, -0.03, -0.09, 0.03);
  const V7 h0 = layer.activations(x0);
  EXPECT_NEAR(h0(6), std::exp(-(x0 - p.centers.col(6)).squaredNorm() / (2 * 0.08 * 0.08)), 1e-15);
}

TEST(RbfLayer, ZeroWeightsGiveZeroEstimate) {  // spec B-S11, step 12 (D̂̄ = Ŵᵀ h)
  const Layer layer(spec_layer());
  const V7 h = layer.activations(V6(0.25, 0.15, -0.20, -0.03, -0.09, 0.03));
  const W73 W = W73::Zero();
  EXPECT_EQ(V3(W.transpose() * h), V3::Zero());
  // And Ŵ stays 0 under eq. (13) while s = 0.
  const W73 next = adcs::rbf_weight_step<7, 3>(W, h, V3::Zero(), kTau, kBeta, 1e-4);
  EXPECT_EQ(next, W73::Zero());
}

TEST(RbfLayer, NonPositiveOrNonFiniteParametersAreInvalid) {  // spec B-S11 (b_j > 0)
  for (double bad : {0.0, -0.1, -1e-300, kNaN, std::numeric_limits<double>::infinity()}) {
    Layer::Params p = spec_layer();
    p.widths(4) = bad;
    EXPECT_EQ(Layer(p).status(), Status::invalid_parameter) << bad;
  }
  Layer::Params p = spec_layer();
  p.centers(2, 5) = kNaN;
  EXPECT_EQ(Layer(p).status(), Status::invalid_parameter);
  EXPECT_EQ(Layer(spec_layer()).status(), Status::ok);
}

// ---------------------------------------------------------------------------------- eq. (13)

struct WeightCase {
  W73 W;
  V7 h;
  V3 s;
};

WeightCase weight_case(unsigned seed) {
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> n(0.0, 1.0);
  WeightCase c;
  for (int i = 0; i < 7; ++i)
    for (int j = 0; j < 3; ++j) c.W(i, j) = n(rng);
  const Layer layer(spec_layer());
  V6 x;
  for (int i = 0; i < 6; ++i) x(i) = 0.1 * n(rng);
  c.h = layer.activations(x);
  c.s = V3(n(rng), n(rng), n(rng));
  return c;
}

TEST(RbfWeightStep, EqualsTheExactHeldInputSolution) {  // spec §B.3 step 14, eq. (13)
  struct Gains {
    V3 tau;
    double beta, T;
  };
  const std::vector<Gains> gains{{kTau, kBeta, 1e-4},            // scenario, RK4 period
                                 {kTau, kBeta, 2.0},             // scenario gains, long hold
                                 {V3(0.5, 0.25, 2.0), 0.8, 1.5},  // strong leakage, τβT up to 2.4
                                 {V3(3.0, 0.0, 1.0), 2.0, 0.7}};  // one column frozen (τ = 0)
  for (unsigned seed = 1; seed <= 4; ++seed) {
    const WeightCase c = weight_case(seed);
    for (const Gains& g : gains) {
      const W73 exact = rk4_weights(c.W, c.h, c.s, g.tau, g.beta, g.T, 2000);
      const W73 step = adcs::rbf_weight_step<7, 3>(c.W, c.h, c.s, g.tau, g.beta, g.T);
      EXPECT_LT((step - exact).cwiseAbs().maxCoeff(), 1e-12 * (1.0 + exact.cwiseAbs().maxCoeff()))
          << "seed " << seed << " beta " << g.beta << " T " << g.T;
    }
  }
}

TEST(RbfWeightStep, AgreesWithExplicitEulerToSecondOrder) {  // rbf_network.hpp header claim
  const WeightCase c = weight_case(7);
  const V3 tau(0.5, 1.0, 2.0);
  const double beta = 0.5;
  double prev = 0.0;
  for (double T : {0.2, 0.1, 0.05, 0.025}) {
    const double diff = (adcs::rbf_weight_step<7, 3>(c.W, c.h, c.s, tau, beta, T) -
                         euler_weights(c.W, c.h, c.s, tau, beta, T))
                            .cwiseAbs()
                            .maxCoeff();
    EXPECT_GT(diff, 0.0);
    if (prev > 0.0) {
      EXPECT_NEAR(prev / diff, 4.0, 0.25) << T;  // halving T quarters the gap
    }
    prev = diff;
  }
}

TEST(RbfWeightStep, ZeroLeakageIsThePlainEulerStep) {  // eq. (13) with β = 0
  for (unsigned seed = 1; seed <= 3; ++seed) {
    const WeightCase c = weight_case(seed);
    const V3 tau(0.5, 0.25, 3.0);
    for (double T : {1e-4, 0.1, 5.0}) {
      const W73 step = adcs::rbf_weight_step<7, 3>(c.W, c.h, c.s, tau, 0.0, T);
      const W73 euler = euler_weights(c.W, c.h, c.s, tau, 0.0, T);
      EXPECT_LT((step - euler).cwiseAbs().maxCoeff(), 1e-15 * (1.0 + euler.cwiseAbs().maxCoeff()));
      // Column i only moves along h, by τ_i T s_i.
      for (int i = 0; i < 3; ++i) {
        const W73 d = step - c.W;
        EXPECT_LT((d.col(i) - tau(i) * T * c.s(i) * c.h).norm(), 1e-14);
      }
    }
  }
}

TEST(RbfWeightStep, LeakageAloneDecaysWithoutOvershoot) {  // header: "never overshoots the leakage"
  const WeightCase c = weight_case(9);
  const V3 tau(0.5, 5.0, 50.0);
  // s = 0: Ŵ_i⁺ = e^{−τ_i β T} Ŵ_i, even where Euler (factor 1 − τβT < −1) would blow up.
  const W73 step = adcs::rbf_weight_step<7, 3>(c.W, c.h, V3::Zero(), tau, 0.1, 1.0);
  for (int i = 0; i < 3; ++i) {
    const double factor = std::exp(-tau(i) * 0.1 * 1.0);
    EXPECT_LT((step.col(i) - factor * c.W.col(i)).norm(), 1e-15 * c.W.col(i).norm());
    EXPECT_GT(factor, 0.0);
  }
  // Fixed point W_i = s_i h / β is kept exactly (the ZOH equilibrium).
  W73 eq;
  for (int i = 0; i < 3; ++i) eq.col(i) = c.s(i) * c.h / 0.1;
  EXPECT_LT((adcs::rbf_weight_step<7, 3>(eq, c.h, c.s, tau, 0.1, 3.0) - eq).cwiseAbs().maxCoeff(), 1e-13);
}

// ---------------------------------------------------------------------------------- B-S12

double rk4_bound(double mu, double s_norm, double tau, double gamma, double T, int n) {
  const double dt = T / n;
  auto f = [&](double m) { return tau * (s_norm - gamma * m); };
  for (int k = 0; k < n; ++k) {
    const double k1 = f(mu), k2 = f(mu + 0.5 * dt * k1), k3 = f(mu + 0.5 * dt * k2), k4 = f(mu + dt * k3);
    mu += dt / 6.0 * (k1 + 2 * k2 + 2 * k3 + k4);
  }
  return mu;
}

TEST(BoundEstimator, EstimateStaysNonNegative) {  // spec B-S12 (μ̂(t) ≥ 0 for all t)
  std::mt19937_64 rng(12);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int k = 0; k < 5000; ++k) {
    const double mu = (k % 5 == 0) ? 0.0 : std::pow(10.0, 8 * u(rng) - 6);
    const double s_norm = (k % 7 == 0) ? 0.0 : std::pow(10.0, 8 * u(rng) - 6);
    const double tau = std::pow(10.0, 4 * u(rng) - 2);
    const double gamma = (k % 3 == 0) ? 0.0 : std::pow(10.0, 4 * u(rng) - 3);
    const double T = std::pow(10.0, 7 * u(rng) - 5);  // 1e-5 … 100 s, including τγT ≫ 1
    const double next = adcs::bound_estimate_step(mu, s_norm, tau, gamma, T);
    EXPECT_GE(next, 0.0) << mu << " " << s_norm << " " << tau << " " << gamma << " " << T;
    EXPECT_TRUE(std::isfinite(next));
  }
  // A long run with ‖s‖ switching on and off, scenario gains, RK4 period: never negative.
  double mu = 0.0;
  for (int k = 0; k < 20000; ++k) {
    mu = adcs::bound_estimate_step(mu, (k / 1000) % 2 == 0 ? 0.0 : 3.0 * u(rng), 0.5, kGamma, 1e-2);
    ASSERT_GE(mu, 0.0) << k;
  }
}

TEST(BoundEstimator, StepEqualsTheExactHeldInputSolution) {  // spec eq. (14), §B.3 step 14
  struct Case {
    double mu, s_norm, tau, gamma, T;
  };
  for (const Case& c : {Case{0.0, 0.3, 0.5, kGamma, 1e-4}, Case{0.0, 0.3, 0.5, kGamma, 5.0},
                        Case{2.0, 0.1, 0.5, kGamma, 5.0}, Case{1.0, 0.0, 2.0, 0.8, 3.0},
                        Case{0.5, 4.0, 1.5, 0.5, 2.0}}) {
    const double exact = rk4_bound(c.mu, c.s_norm, c.tau, c.gamma, c.T, 5000);
    EXPECT_NEAR(adcs::bound_estimate_step(c.mu, c.s_norm, c.tau, c.gamma, c.T), exact,
                1e-12 * (1.0 + std::abs(exact)));
  }
  // γ = 0: plain Euler step μ̂ + τ T ‖s‖ (exact for a constant rate).
  EXPECT_DOUBLE_EQ(adcs::bound_estimate_step(0.2, 0.7, 0.5, 0.0, 0.3), 0.2 + 0.5 * 0.3 * 0.7);
  // Equilibrium μ̂ = ‖s‖/γ is a fixed point.
  EXPECT_NEAR(adcs::bound_estimate_step(0.4 / 0.05, 0.4, 0.5, 0.05, 10.0), 0.4 / 0.05, 1e-13);
}

TEST(BoundEstimator, RobustTermIsBoundedByTheEstimate) {  // spec B-S12, eq. (12)
  std::mt19937_64 rng(13);
  std::normal_distribution<double> n(0.0, 1.0);
  for (double mu : {1e-6, 1e-3, 0.1, 1.0, 10.0, 1e3}) {
    for (double s_mag : {1e-9, 1e-4, 1e-2, 1.0, 1e2, 1e4}) {
      const V3 s = V3(n(rng), n(rng), n(rng)).normalized() * s_mag;
      const V3 term = adcs::bound_robust_term(mu, s, kSigma);
      ASSERT_TRUE(adcs::all_finite(term));
      const double gain = mu * mu / (mu * s.norm() + kSigma);
      EXPECT_LT(gain * s.norm(), mu);  // μ̂²‖s‖/(μ̂‖s‖ + σ) < μ̂
      EXPECT_LE(term.norm(), mu * (1.0 + 1e-15));
      EXPECT_LE(term.norm(), mu * mu * s.norm() / kSigma * (1.0 + 1e-15));  // denominator ≥ σ
      EXPECT_LT((term - gain * s).norm(), 1e-15 * (1.0 + term.norm()));
      // Parallel to s.
      EXPECT_NEAR(term.dot(s), term.norm() * s.norm(), 1e-12 * (1.0 + term.norm() * s.norm()));
    }
  }
}

TEST(BoundEstimator, RobustTermVanishesForZeroEstimateAndIsFiniteForZeroS) {  // spec B-S12
  const V3 s(0.3, -1.0, 2.0);
  EXPECT_EQ(adcs::bound_robust_term(0.0, s, kSigma), V3::Zero());
  for (double mu : {0.0, 1e-3, 1.0, 1e6}) {
    const V3 zero = V3::Zero();  // a plain vector: Vector is deduced from the argument
    const V3 term = adcs::bound_robust_term(mu, zero, kSigma);
    EXPECT_TRUE(adcs::all_finite(term));
    EXPECT_EQ(term, V3::Zero());
  }
}
}  // namespace

using namespace ADCS_UNITY_ID;  // as an anonymous namespace would (CMakeLists.txt, adcs_unity)
