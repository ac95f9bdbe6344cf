// actuator/quantizer.hpp, spec §A.11 #7: error bound ϖ on random and boundary inputs, interval
// semantics against a direct reading of the §A.3 definition, oddness, tiling, sat → Q limits,
// transmission counting, non-finite input.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <vector>

#include "adcs/actuator/quantizer.hpp"
#include "scenarios/seed003_data.hpp"  // seed 003's scenario data (paper data, not flight code)

namespace ADCS_UNITY_ID {
using adcs::QuantizerChannel;
using adcs::QuantizerChannelParams;
using adcs::Status;

constexpr double kInf = std::numeric_limits<double>::infinity();

// Seed 003 channels, spec §A.8 "Proposed Table 1" [A]; actuator limits [P].
const QuantizerChannelParams kTorque{0.3, 1e-3, 0.2, 0.1};  // limit 0.5 N m
const QuantizerChannelParams kForce{0.5, 1e-3, 2.0, 1.0};   // limit 5 N

adcs::Vec6 seed003_limits() {
  adcs::Vec6 l;
  l << 0.5, 0.5, 0.5, 5.0, 5.0, 5.0;
  return l;
}

// Q_log straight from the §A.3 interval definition by a linear scan over the levels (no log,
// no index formula), with the quantizer's canonical boundaries b_j = u_j/(1+δ).
double reference_log(const QuantizerChannel& c, double u) {
  const double a = std::fabs(u);
  if (a <= c.lower_boundary(1)) return 0.0;
  int j = 1;
  while (j < c.level_count() && a > c.lower_boundary(j + 1)) ++j;
  return std::copysign(c.level(j), u);
}

// Every place where Q can switch, ±1 ulp: level boundaries in both forms u_j/(1±δ), the
// levels, u_s, the multiples of σ in [−10 limit, 10 limit], the limits; both signs; extremes.
std::vector<double> boundary_inputs(const QuantizerChannel& c, double limit) {
  const QuantizerChannelParams& p = c.params();
  std::vector<double> base{0.0, p.u_s, limit, 1e20, 0x1p50 * p.sigma, 0x1p52 * p.sigma,
                           std::numeric_limits<double>::max(),
                           std::numeric_limits<double>::denorm_min()};
  for (int j = 1; j <= c.level_count() + 1; ++j) {
    const double uj = adcs::quantizer_level(p, j);
    base.insert(base.end(), {uj, uj / (1.0 + c.delta()), uj / (1.0 - c.delta())});
  }
  const int kmax = static_cast<int>(std::lround(10.0 * limit / p.sigma));
  for (int k = 0; k <= kmax; ++k) base.push_back(k * p.sigma);
  std::vector<double> out;
  for (double b : base) {
    for (double x : {b, std::nextafter(b, kInf), std::nextafter(b, -kInf)}) {
      if (std::isfinite(x)) out.insert(out.end(), {x, -x});
    }
  }
  return out;
}

struct ChannelCase {
  QuantizerChannelParams p;
  double limit;
};

// |Q(u) − u| ≤ ϖ for 1e6 uniform samples in [−10 limit, 10 limit] and every boundary ±1 ulp;
// in the log region Q equals the direct definition and is odd; in the uniform region the
// floor-type error lies in (−σ, 1e-12σ].
TEST(Quantizer, ErrorBoundHoldsOnRandomAndBoundaryInputs) {
  std::mt19937_64 rng(20240603);
  for (const ChannelCase& cc : {ChannelCase{kTorque, 0.5}, ChannelCase{kForce, 5.0}}) {
    const QuantizerChannel c(cc.p);
    ASSERT_EQ(c.status(), Status::ok);
    const double bound = c.error_bound();
    double worst = 0.0;
    int log_mismatch = 0, not_odd = 0, uni_outside = 0;
    auto check = [&](double u) {
      const double q = c.quantize(u);
      worst = std::max(worst, std::fabs(q - u));
      if (std::fabs(u) <= cc.p.u_s) {
        log_mismatch += q != reference_log(c, u);
        not_odd += c.quantize(-u) != -q;
      } else {
        uni_outside += !(q - u > -cc.p.sigma && q - u <= 1e-12 * cc.p.sigma);
      }
    };
    const double span = 20.0 * cc.limit;
    for (int k = 0; k < 1000000; ++k) {
      check((static_cast<double>(rng() >> 11) * 0x1p-53 - 0.5) * span);  // 53-bit uniform
    }
    for (double u : boundary_inputs(c, cc.limit)) check(u);
    EXPECT_LE(worst, bound) << "rho " << cc.p.rho;
    EXPECT_GT(worst, 0.9 * cc.p.sigma);  // the samples reach the uniform region's worst case
    EXPECT_EQ(log_mismatch, 0);
    EXPECT_EQ(not_odd, 0);
    EXPECT_EQ(uni_outside, 0);
  }
}

// Hysteresis-free intervals (b_j, b_{j+1}]: the boundary itself belongs to the level below,
// one ulp above it to the level above; the dead zone is [0, u_min/(1+δ)].
TEST(Quantizer, BoundariesBelongToTheLowerLevel) {
  for (const QuantizerChannelParams& p : {kTorque, kForce}) {
    const QuantizerChannel c(p);
    for (int j = 1; j <= c.level_count(); ++j) {
      const double b = c.lower_boundary(j);
      ASSERT_LT(b, p.u_s);
      EXPECT_EQ(c.quantize(b), j == 1 ? 0.0 : c.level(j - 1));
      EXPECT_EQ(c.quantize(std::nextafter(b, kInf)), c.level(j));
      EXPECT_EQ(c.quantize(-std::nextafter(b, kInf)), -c.level(j));
    }
    EXPECT_EQ(c.quantize(p.u_s), c.quantize_log(p.u_s));  // |u| = u_s is still log
    const double above = std::nextafter(p.u_s, kInf);
    EXPECT_EQ(c.quantize(above), c.quantize_uniform(above));
  }
}

// Far outside the saturated range u/σ and σ·floor(·) round by more than the 1e-12 guard; these
// inputs (found by search) would exceed σ by 1e-3σ without the quantizer's one-level correction.
TEST(Quantizer, UniformBoundHoldsFarOutsideTheLimits) {
  const QuantizerChannel c({0.3, 1e-3, 0.2, 0.01});
  for (double u : {-329229007573.09003, 1158787655332.9299}) {
    EXPECT_LE(std::fabs(c.quantize(u) - u), 0.01) << u;
  }
}

// Levels tile (0, ∞): u_j/(1−δ) = u_{j+1}/(1+δ); n is just enough to cover u_s. Level counts by
// hand: ceil(ln(0.2·(1+7/13)/1e-3)/ln(1/0.3)) = ceil(4.76) = 5, ceil(ln(2·(4/3)/1e-3)/ln 2) =
// ceil(11.38) = 12. ϖ = max{σ, δu_s + u_min} (spec §A.3 [P]).
TEST(Quantizer, LevelsTileAndDerivedConstantsMatchTable1) {
  const QuantizerChannel t(kTorque), f(kForce);
  EXPECT_EQ(t.level_count(), 5);
  EXPECT_EQ(f.level_count(), 12);
  for (const QuantizerChannel* c : {&t, &f}) {
    const double d = c->delta();
    const int n = c->level_count();
    for (int j = 1; j < n; ++j) {
      const double upper = c->level(j) / (1.0 - d), next_lower = c->level(j + 1) / (1.0 + d);
      EXPECT_NEAR(upper, next_lower, 1e-12 * next_lower);
    }
    EXPECT_GE(c->level(n) / (1.0 - d), c->params().u_s);
    EXPECT_LT(c->level(n - 1) / (1.0 - d), c->params().u_s);
  }
  EXPECT_NEAR(t.delta(), 0.538, 5e-4);  // Table 1: δ = 0.538 / 0.333
  EXPECT_NEAR(f.delta(), 0.333, 5e-4);
  EXPECT_DOUBLE_EQ(t.error_bound(), 0.7 / 1.3 * 0.2 + 1e-3);  // 0.10869 N m
  EXPECT_EQ(f.error_bound(), 1.0);                            // σ dominates: 2/3 + 1e-3 < 1
  // Table 1 prints ϖ_rot = 0.1076 N m: that is δu_s = 0.10769 alone (truncated), without the
  // + u_min of the [P] formula the code implements; the difference is u_min = 1e-3 N m.
  EXPECT_NEAR(t.delta() * kTorque.u_s, 0.1076, 1e-4);
  EXPECT_DOUBLE_EQ(adcs::quantizer_error_bound(kTorque), t.error_bound());
}

// u_c = clip(Q(sat(u))): the limits are exact levels, so Q(sat(u)) is within the limits before
// the final clip; the composite equals the scalar channels.
TEST(Quantizer, SaturateThenQuantizeStaysWithinLimits) {
  const adcs::Vec6 lim = seed003_limits();
  const QuantizerChannel t(kTorque), f(kForce);
  EXPECT_EQ(t.quantize(0.5), 0.5);
  EXPECT_EQ(t.quantize(-0.5), -0.5);
  EXPECT_EQ(f.quantize(5.0), 5.0);
  EXPECT_EQ(f.quantize(-5.0), -5.0);
  adcs::CompositeQuantizer<6> q(adcs::seed003_quantizer_params());
  ASSERT_EQ(q.status(), Status::ok);
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> draw(-1.0, 1.0);
  for (int k = 0; k < 2000; ++k) {
    const double scale = (k % 2 == 0) ? 10.0 : 0.5;  // mostly saturated / mostly not
    adcs::Vec6 u;
    for (int i = 0; i < 6; ++i) u(i) = scale * lim(i) * draw(rng);
    adcs::Vec6 uc;
    const Status s = adcs::saturate_then_quantize<6>(u, lim, q, uc);
    ASSERT_TRUE(s == Status::ok || s == Status::saturated);
    EXPECT_EQ(s == Status::saturated, (u.cwiseAbs().array() > lim.array()).any());
    for (int i = 0; i < 6; ++i) {
      const double us = std::min(std::max(u(i), -lim(i)), lim(i));
      const double qs = (i < 3 ? t : f).quantize(us);
      EXPECT_LE(std::fabs(qs), lim(i));  // before the clip
      EXPECT_EQ(uc(i), qs);
    }
  }
}

TEST(Quantizer, TransmissionsCountFirstTickAndChangesOnly) {
  adcs::CompositeQuantizer<6> q(adcs::seed003_quantizer_params());
  adcs::Vec6 u, uq;
  u << 0.3, -0.05, 0.0, 3.2, -1.5, 0.004;
  std::uint32_t mask = 0;
  ASSERT_EQ(q.apply(u, uq, &mask), Status::ok);
  EXPECT_EQ(q.transmissions(), 6u);  // first tick: every channel
  EXPECT_EQ(mask, 0x3Fu);
  ASSERT_EQ(q.apply(u, uq, &mask), Status::ok);
  EXPECT_EQ(q.transmissions(), 6u);
  EXPECT_EQ(mask, 0u);
  u(0) = 0.35;  // same uniform level 0.3
  u(5) = 0.0041;  // same log level
  ASSERT_EQ(q.apply(u, uq, &mask), Status::ok);
  EXPECT_EQ(q.transmissions(), 6u);
  u(1) = -0.2;  // log level change
  u(3) = 4.0;   // uniform level change
  ASSERT_EQ(q.apply(u, uq, &mask), Status::ok);
  EXPECT_EQ(q.transmissions(), 8u);
  EXPECT_EQ(mask, 0x0Au);
  EXPECT_EQ(q.channel_transmissions()[1], 2u);
  EXPECT_EQ(q.channel_transmissions()[0], 1u);
  EXPECT_EQ(uq, q.last_output());
  q.reset();
  EXPECT_EQ(q.transmissions(), 0u);
  ASSERT_EQ(q.apply(u, uq, &mask), Status::ok);  // after reset() the first tick again sends all
  EXPECT_EQ(q.transmissions(), 6u);
  EXPECT_EQ(mask, 0x3Fu);
}

TEST(Quantizer, NonFiniteInputLeavesOutputsAndCountersUnchanged) {
  adcs::CompositeQuantizer<6> q(adcs::seed003_quantizer_params());
  adcs::Vec6 u = adcs::Vec6::Constant(0.1), uq;
  ASSERT_EQ(q.apply(u, uq), Status::ok);
  const adcs::Vec6 held = uq;
  for (double bad : {std::nan(""), kInf, -kInf}) {
    adcs::Vec6 v = u;
    v(4) = bad;
    std::uint32_t mask = 0xDEADu;
    EXPECT_EQ(q.apply(v, uq, &mask), Status::non_finite_input);
    EXPECT_EQ(adcs::saturate_then_quantize<6>(v, seed003_limits(), q, uq, &mask),
              Status::non_finite_input);
    EXPECT_EQ(uq, held);
    EXPECT_EQ(mask, 0xDEADu);
    EXPECT_EQ(q.transmissions(), 6u);
    EXPECT_EQ(q.last_output(), held);
  }
  std::uint32_t mask = 1;
  ASSERT_EQ(q.apply(u, uq, &mask), Status::ok);  // the remembered output really was kept
  EXPECT_EQ(mask, 0u);
}

TEST(Quantizer, RejectsInvalidParameters) {
  const QuantizerChannelParams bad[] = {
      {1.0, 1e-3, 0.2, 0.1},  {0.0, 1e-3, 0.2, 0.1}, {0.3, 0.0, 0.2, 0.1},
      {0.3, 0.3, 0.2, 0.1},   {0.3, 1e-3, 0.2, 0.0}, {std::nan(""), 1e-3, 0.2, 0.1},
      {0.3, 1e-3, kInf, 0.1}, {0.9, 1e-6, 1e3, 1.0},  // needs > kMaxQuantizerLevels levels
  };
  for (const QuantizerChannelParams& p : bad) {
    EXPECT_FALSE(adcs::valid(p));
    EXPECT_EQ(QuantizerChannel(p).status(), Status::invalid_parameter);
    EXPECT_EQ(QuantizerChannel(p).quantize(0.123), 0.123);  // passes through, invents nothing
    adcs::CompositeQuantizer<2>::Params cp;
    cp.channel[1] = p;
    adcs::CompositeQuantizer<2> q(cp);
    adcs::Vec<2> uq = adcs::Vec<2>::Constant(9.0);
    EXPECT_EQ(q.apply(adcs::Vec<2>(0.1, 0.1), uq), Status::invalid_parameter);
    EXPECT_EQ(uq, adcs::Vec<2>::Constant(9.0));
  }
}
}  // namespace

using namespace ADCS_UNITY_ID;  // as an anonymous namespace would (CMakeLists.txt, adcs_unity)
