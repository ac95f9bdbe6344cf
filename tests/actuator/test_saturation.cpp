// actuator/saturation.hpp: per-element limits, "no limit" encodings, count of clipped elements.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "adcs/actuator/saturation.hpp"

TEST(Saturation, ClipsEachElementToItsOwnLimitAndCounts) {
  const double inf = std::numeric_limits<double>::infinity();
  adcs::Vec<6> u;
  u << 2.0, -3.0, 0.5, -0.5, 100.0, -100.0;
  adcs::Vec<6> lim;
  lim << 1.0, 1.0, 1.0, 0.0, inf, std::nan("");
  EXPECT_EQ(adcs::saturate_each<6>(u, lim), 2);
  adcs::Vec<6> want;
  want << 1.0, -1.0, 0.5, -0.5, 100.0, -100.0;  // 0, inf and NaN limits: untouched
  EXPECT_EQ(u, want);
  EXPECT_EQ(adcs::saturate_each<6>(u, lim), 0);  // idempotent
  lim.setConstant(-1.0);                           // negative = no limit
  EXPECT_EQ(adcs::saturate_each<6>(u, lim), 0);
  EXPECT_EQ(u, want);
}
