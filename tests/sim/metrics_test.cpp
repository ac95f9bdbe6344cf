// metrics: windowed max/RMS, settling time, Welch PSD against known signals.
#include <gtest/gtest.h>

#include <cmath>
#include <numeric>
#include <vector>

#include "sim/metrics.hpp"
#include "sim/random.hpp"

namespace m = adcs::sim::metrics;
using adcs::sim::SimError;

namespace ADCS_UNITY_ID {

constexpr double kPi = 3.14159265358979323846;

std::vector<double> times(std::size_t n, double dt) {
  std::vector<double> t(n);
  for (std::size_t i = 0; i < n; ++i) t[i] = static_cast<double>(i) * dt;
  return t;
}

}  // namespace

using namespace ADCS_UNITY_ID;  // as an anonymous namespace would (CMakeLists.txt, adcs_unity)

TEST(Metrics, WindowMaxAndRms) {
  const std::vector<double> t = times(1001, 0.01);  // 0 .. 10 s
  std::vector<double> y(t.size());
  for (std::size_t i = 0; i < t.size(); ++i) y[i] = 2.0 * std::sin(2.0 * kPi * t[i]) + (t[i] < 1.0 ? 10.0 : 0.0);
  // [2, 10] s: whole periods of a 2-amplitude sine (the 10 offset before 1 s is excluded).
  EXPECT_NEAR(m::max_abs_in_window(t, y, 2.0, 10.0), 2.0, 1e-12);
  EXPECT_NEAR(m::rms_in_window(t, y, 2.0, 9.99), std::sqrt(2.0), 1e-12);  // 800 samples, 8 periods
  EXPECT_NEAR(m::max_abs_in_window(t, y, 0.0, 10.0), 12.0, 0.01);
  EXPECT_TRUE(std::isnan(m::max_abs_in_window(t, y, 20.0, 30.0)));
  EXPECT_TRUE(std::isnan(m::rms_in_window(t, y, 20.0, 30.0)));
  std::vector<double> with_nan = y;
  with_nan[500] = std::nan("");
  EXPECT_TRUE(std::isnan(m::max_abs_in_window(t, with_nan, 0.0, 10.0)));
  EXPECT_THROW(m::rms_in_window(t, std::vector<double>(3), 0.0, 1.0), SimError);
}

TEST(Metrics, SettlingTimeOfExponentialDecay) {
  const double dt = 0.01;
  const std::vector<double> t = times(1001, dt);
  std::vector<double> y(t.size()), z(t.size());
  for (std::size_t i = 0; i < t.size(); ++i) {
    y[i] = std::exp(-t[i]);
    z[i] = -0.5 * std::exp(-2.0 * t[i]);
  }
  const double ts = m::settling_time(t, y, 0.02);
  EXPECT_GE(ts, std::log(50.0));  // e^-t <= 0.02  <=>  t >= ln 50
  EXPECT_LT(ts, std::log(50.0) + dt);
  // Several signals: the slowest decides (z settles at ln(25)/2 < ln 50).
  EXPECT_EQ(m::settling_time(t, {z, y}, 0.02), ts);
  EXPECT_EQ(m::settling_time(t, y, 2.0), 0.0);               // always inside
  EXPECT_TRUE(std::isnan(m::settling_time(t, y, 1e-9)));      // never settles
  std::vector<double> bump = y;
  bump[800] = 0.5;  // leaves the band again at t = 8 s
  EXPECT_NEAR(m::settling_time(t, bump, 0.02), 8.01, 1e-9);
}

TEST(Metrics, WelchSinusoidPeakAndPower) {
  const double fs = 100.0;  // [Hz]
  const double f0 = 12.5;   // [Hz], on a bin for L = 256 (bin spacing 0.390625 Hz)
  const double amplitude = 3.0;
  std::vector<double> x(20000);
  for (std::size_t n = 0; n < x.size(); ++n)
    x[n] = amplitude * std::sin(2.0 * kPi * f0 * static_cast<double>(n) / fs);
  const m::WelchResult r = m::welch_psd(x, fs, 256);
  ASSERT_EQ(r.f_hz.size(), 129u);
  ASSERT_EQ(r.psd.size(), 129u);
  EXPECT_DOUBLE_EQ(r.f_hz.back(), fs / 2.0);
  const auto peak = std::max_element(r.psd.begin(), r.psd.end()) - r.psd.begin();
  EXPECT_NEAR(r.f_hz[static_cast<std::size_t>(peak)], f0, fs / 256.0);
  const double df = r.f_hz[1] - r.f_hz[0];
  const double power = std::accumulate(r.psd.begin(), r.psd.end(), 0.0) * df;
  EXPECT_NEAR(power, amplitude * amplitude / 2.0, 0.01 * amplitude * amplitude / 2.0);

  // Off-bin frequency: the Hann leakage spreads the peak, the total power stays.
  for (std::size_t n = 0; n < x.size(); ++n)
    x[n] = amplitude * std::sin(2.0 * kPi * 7.3 * static_cast<double>(n) / fs + 0.4);
  const m::WelchResult r2 = m::welch_psd(x, fs, 256);
  const double power2 = std::accumulate(r2.psd.begin(), r2.psd.end(), 0.0) * df;
  EXPECT_NEAR(power2, amplitude * amplitude / 2.0, 0.01 * amplitude * amplitude / 2.0);
  const auto peak2 = std::max_element(r2.psd.begin(), r2.psd.end()) - r2.psd.begin();
  EXPECT_NEAR(r2.f_hz[static_cast<std::size_t>(peak2)], 7.3, fs / 256.0);
}

TEST(Metrics, WelchWhiteNoiseLevel) {
  const double fs = 50.0;    // [Hz]
  const double sigma = 0.3;  // [unit]
  adcs::sim::Rng rng(7);
  std::vector<double> x(1 << 16);
  for (double& v : x) v = sigma * rng.normal();
  const m::WelchResult r = m::welch_psd(x, fs, 256, 0.5);
  // Mean over the bins with a negative-frequency twin (DC and Nyquist carry half).
  const double mean_psd =
      std::accumulate(r.psd.begin() + 1, r.psd.end() - 1, 0.0) / static_cast<double>(r.psd.size() - 2);
  EXPECT_NEAR(mean_psd, 2.0 * sigma * sigma / fs, 0.05 * 2.0 * sigma * sigma / fs);
  EXPECT_NEAR(m::median(m::asd(r.psd)), std::sqrt(2.0 * sigma * sigma / fs),
              0.1 * std::sqrt(2.0 * sigma * sigma / fs));
}

TEST(Metrics, WelchRejectsBadArguments) {
  const std::vector<double> x(100, 1.0);
  EXPECT_THROW(m::welch_psd(x, 0.0, 32), SimError);
  EXPECT_THROW(m::welch_psd(x, 10.0, 1), SimError);
  EXPECT_THROW(m::welch_psd(x, 10.0, 101), SimError);
  EXPECT_THROW(m::welch_psd(x, 10.0, 32, 1.0), SimError);
  EXPECT_NO_THROW(m::welch_psd(x, 10.0, 33, 0.0));  // odd length: no Nyquist bin
  EXPECT_EQ(m::welch_psd(x, 10.0, 33, 0.0).psd.size(), 17u);
}

TEST(Metrics, MedianAndAsd) {
  EXPECT_EQ(m::median({3.0, 1.0, 2.0}), 2.0);
  EXPECT_EQ(m::median({4.0, 1.0, 3.0, 2.0}), 2.5);
  EXPECT_TRUE(std::isnan(m::median({})));
  EXPECT_EQ(m::asd({4.0, 0.25}), (std::vector<double>{2.0, 0.5}));
}
