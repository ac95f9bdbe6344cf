// control/nonsingular_power.hpp, spec §A.11 #8: S and S' continuous at ±ε, S'(0) = l1 finite,
// S odd / S' even, S = sig^{1−p} outside the patch, S' = dS/dz (central differences).
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "adcs/control/nonsingular_power.hpp"

namespace ADCS_UNITY_ID {
using adcs::NonsingularPower;
using adcs::NonsingularPowerParams;

constexpr double kInf = std::numeric_limits<double>::infinity();
const NonsingularPowerParams kCases[] = {{0.5, 0.01}, {0.1, 1e-3}, {0.9, 1.0}, {0.3, 0.05}};

TEST(NonsingularPower, ContinuousAtPlusMinusEpsAndFiniteAtZero) {
  for (const NonsingularPowerParams& q : kCases) {
    const NonsingularPower s(q);
    ASSERT_EQ(s.status(), adcs::Status::ok);
    for (double e : {q.eps, -q.eps}) {
      const double out = std::nextafter(e, e > 0 ? kInf : -kInf);  // first point outside
      EXPECT_NEAR(s.value(e), s.value(out), 1e-12 * std::fabs(s.value(e))) << q.p << " " << e;
      EXPECT_NEAR(s.derivative(e), s.derivative(out), 1e-12 * s.derivative(e)) << q.p << " " << e;
      const double edge = std::pow(q.eps, 1.0 - q.p);  // S(ε) = ε^{1−p}
      EXPECT_NEAR(s.value(e), std::copysign(edge, e), 1e-12 * edge);
    }
    EXPECT_EQ(s.l1(), (1.0 + q.p) * std::pow(q.eps, -q.p));
    EXPECT_EQ(s.derivative(0.0), s.l1());
    EXPECT_TRUE(std::isfinite(s.derivative(0.0)));
    EXPECT_EQ(s.value(0.0), 0.0);
  }
}

TEST(NonsingularPower, OddMatchesSigOutsideAndDerivativeMatchesDifferences) {
  for (const NonsingularPowerParams& q : kCases) {
    const NonsingularPower s(q);
    for (double r : {1e-9, 0.1, 0.37, 0.999, 1.5, 7.0, 100.0}) {
      const double z = r * q.eps;
      EXPECT_EQ(s.value(-z), -s.value(z));
      EXPECT_EQ(s.derivative(-z), s.derivative(z));
      if (r > 1.0) {
        EXPECT_EQ(s.value(z), adcs::sig(z, 1.0 - q.p));
        EXPECT_NEAR(s.value(-z), -std::pow(z, 1.0 - q.p), 1e-15 * std::pow(z, 1.0 - q.p));
      }
      const double h = 1e-6 * z;  // stays on one side of ±ε for these r
      const double fd = (s.value(z + h) - s.value(z - h)) / (2.0 * h);
      EXPECT_NEAR(s.derivative(z), fd, 1e-7 * std::fabs(s.derivative(z))) << q.p << " " << z;
    }
  }
}

TEST(NonsingularPower, SigAndComponentwiseAndInvalid) {
  EXPECT_EQ(adcs::sig(-4.0, 0.5), -2.0);  // sqrt path
  EXPECT_EQ(adcs::sig(0.0, 0.5), 0.0);
  EXPECT_EQ(adcs::sig(-0.0, 1.5), 0.0);
  EXPECT_DOUBLE_EQ(adcs::sig(-2.0, 1.5), -std::pow(2.0, 1.5));
  const NonsingularPower s;
  const adcs::Vec3 z(-0.5, 0.004, 0.0);
  const adcs::Vec3 v = s.value(z), d = s.derivative(z);
  const adcs::Vec3 sz = adcs::sig(z, 1.5);
  for (int i = 0; i < 3; ++i) {
    EXPECT_EQ(v(i), s.value(z(i)));
    EXPECT_EQ(d(i), s.derivative(z(i)));
    EXPECT_EQ(sz(i), adcs::sig(z(i), 1.5));
  }
  const NonsingularPowerParams bad_cases[] = {{1.0, 0.01}, {0.5, 0.0}, {0.0, 0.01}, {std::nan(""), 0.01}};
  for (const NonsingularPowerParams& bad : bad_cases) {
    const NonsingularPower b(bad);
    EXPECT_EQ(b.status(), adcs::Status::invalid_parameter);
    EXPECT_EQ(b.value(0.3), 0.0);
    EXPECT_EQ(b.derivative(0.0), 0.0);
  }
}
}  // namespace

using namespace ADCS_UNITY_ID;  // as an anonymous namespace would (CMakeLists.txt, adcs_unity)
