// Issue 19: the actuation stages of seed 003 in single precision (QuantizerChannelT<float>,
// CompositeQuantizer<6, float>, SaturatedQuantizer<6, float>, Saturation<6, float>): the error
// bound ϖ holds as computed in float, Q_log is odd and picks the same level as the interval
// definition, the level table is the double one rounded to float, sat → Q stays within the limits,
// and the failure paths are the double ones.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

#include "adcs/actuator/quantizer.hpp"
#include "adcs/actuator/saturation.hpp"
#include "scenarios/seed003_data.hpp"  // seed 003's scenario data (paper data, not flight code)

namespace ADCS_UNITY_ID {
using adcs::Status;
using QF = adcs::QuantizerChannelT<float>;

// The paper's two channels (seed003_quantizer_params: torque 0, force 3), rounded to float once.
adcs::CompositeQuantizerParams<6, float> seed003_float() { return adcs::seed003_quantizer_params().cast<float>(); }

// Q_log by a linear scan of the float channel's own boundaries (the §A.3 interval definition).
float reference_log(const QF& c, float u) {
  const float a = std::fabs(u);
  if (a <= c.lower_boundary(1)) return 0.0f;
  int j = 1;
  while (j < c.level_count() && a > c.lower_boundary(j + 1)) ++j;
  return std::copysign(c.level(j), u);
}

TEST(QuantizerFloat, LevelsAreTheDoubleLevelsRoundedAndTheBoundHolds) {
  const adcs::CompositeQuantizerParams<6, float> qf = seed003_float();
  const adcs::CompositeQuantizerParams<6> qd = adcs::seed003_quantizer_params();
  std::mt19937 rng(19);
  for (int ch : {0, 3}) {
    const QF f(qf.channel[static_cast<std::size_t>(ch)]);
    const adcs::QuantizerChannel d(qd.channel[static_cast<std::size_t>(ch)]);
    ASSERT_EQ(f.status(), Status::ok);
    ASSERT_EQ(f.level_count(), d.level_count()) << ch;  // n = 5 (torque), 12 (force)
    for (int j = 1; j <= f.level_count(); ++j)  // float powf against double pow: a few ulps
      EXPECT_NEAR(f.level(j), d.level(j), 4e-7 * d.level(j)) << ch << " " << j;
    EXPECT_NEAR(f.error_bound(), d.error_bound(), 1e-7 * d.error_bound());
    // |Q(u) − u| ≤ ϖ as computed, on log-uniform magnitudes from 1e-6 to 1e6 of the channel's unit,
    // both signs; Q_log odd and equal to the interval definition below u_s.
    std::uniform_real_distribution<float> e(-6.0f, 6.0f);
    for (int k = 0; k < 20000; ++k) {
      const float u = (k % 2 ? -1.0f : 1.0f) * std::pow(10.0f, e(rng));
      const float q = f.quantize(u);
      ASSERT_LE(std::fabs(q - u), f.error_bound()) << ch << " u=" << u;
      if (std::fabs(u) <= f.params().u_s) {
        EXPECT_EQ(q, reference_log(f, u)) << ch << " u=" << u;
        EXPECT_EQ(f.quantize(-u), -q) << ch << " u=" << u;
      }
    }
    // Exact multiples of σ stay on their own level (the float floor offset, 1e-4).
    for (int m = 3; m <= 200; ++m) {
      const float u = static_cast<float>(m) * f.params().sigma;
      EXPECT_EQ(f.quantize(u), u) << ch << " m=" << m;
    }
  }
}

TEST(QuantizerFloat, SaturatedQuantizerStaysWithinTheLimitsAndRefusesBadInput) {
  const adcs::Vec<6, float> limit = (adcs::Vec<6, float>() << 0.5f, 0.5f, 0.5f, 5.0f, 5.0f, 5.0f).finished();
  adcs::SaturatedQuantizer<6, float> sq(adcs::SaturatedQuantizerParams<6, float>{seed003_float(), limit});
  ASSERT_EQ(sq.status(), Status::ok);
  std::mt19937 rng(20);
  std::uniform_real_distribution<float> u(-20.0f, 20.0f);
  adcs::Vec<6, float> out;
  for (int k = 0; k < 2000; ++k) {
    adcs::Vec<6, float> in;
    for (int i = 0; i < 6; ++i) in(i) = (i < 3 ? 0.1f : 1.0f) * u(rng);
    const Status s = sq.step(in, out);
    ASSERT_TRUE(s == Status::ok || s == Status::saturated);
    ASSERT_TRUE((out.cwiseAbs().array() <= limit.array()).all()) << k;
  }
  const std::uint64_t tx = sq.quantizer().transmissions();
  adcs::Vec<6, float> bad = adcs::Vec<6, float>::Zero();
  bad(3) = std::numeric_limits<float>::infinity();
  EXPECT_EQ(sq.step(bad, out), Status::non_finite_input);
  EXPECT_EQ(out, (adcs::Vec<6, float>::Zero()));  // the actuators idle
  EXPECT_EQ(sq.quantizer().transmissions(), tx);  // counters untouched
  // A limit beyond float's range rounds to +Inf (no limit); a NaN limit is refused.
  adcs::SaturationParams<6> pd{adcs::Vec6::Constant(1e300)};
  using SatF = adcs::Saturation<6, float>;
  EXPECT_EQ(SatF(pd.cast<float>()).status(), Status::ok);
  pd.limit(2) = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(SatF(pd.cast<float>()).status(), Status::invalid_parameter);
}

}  // namespace ADCS_UNITY_ID
