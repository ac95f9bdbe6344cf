#pragma once
// Statistics a reviewer reads over a campaign's runs (issue 18): order statistics and moments of
// one metric over the runs, with non-finite values counted apart.
#include <cstddef>
#include <vector>

namespace adcs::sim::campaign {

//! The percentile levels every summary reports (in %).
inline constexpr double kPercentiles[] = {1.0, 5.0, 50.0, 95.0, 99.0};

struct Summary {
  std::size_t count = 0;      //!< finite values
  std::size_t nonfinite = 0;  //!< NaN or ±inf (a metric that is undefined in that run)
  double min = 0, p1 = 0, p5 = 0, median = 0, p95 = 0, p99 = 0, max = 0, mean = 0, std = 0;  //!< NaN when count = 0
};

//! The q-th percentile (0 <= q <= 100) of sorted finite values, interpolated linearly between
//! order statistics (numpy's default, "type 7"): x[(n-1) q/100]. NaN for an empty vector.
double percentile_sorted(const std::vector<double>& sorted, double q);

//! Summary of `values` (any order; non-finite ones counted in `nonfinite`); std is the sample
//! standard deviation (n - 1), 0 for one value. The mean is summed in sorted order, so the result
//! does not depend on the order of the runs.
Summary summarize(std::vector<double> values);

}  // namespace adcs::sim::campaign
