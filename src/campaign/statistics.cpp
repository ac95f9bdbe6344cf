#include "campaign/statistics.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace adcs::sim::campaign {

double percentile_sorted(const std::vector<double>& x, double q) {
  if (x.empty()) return std::numeric_limits<double>::quiet_NaN();
  const double pos = (static_cast<double>(x.size()) - 1.0) * q / 100.0;
  const std::size_t lo = static_cast<std::size_t>(std::floor(pos));
  const std::size_t hi = std::min(lo + 1, x.size() - 1);
  const double frac = pos - static_cast<double>(lo);
  return x[lo] + frac * (x[hi] - x[lo]);
}

Summary summarize(std::vector<double> v) {
  Summary s;
  const auto end = std::remove_if(v.begin(), v.end(), [](double x) { return !std::isfinite(x); });
  s.nonfinite = static_cast<std::size_t>(v.end() - end);
  v.erase(end, v.end());
  s.count = v.size();
  if (v.empty()) {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    s.min = s.p1 = s.p5 = s.median = s.p95 = s.p99 = s.max = s.mean = s.std = nan;
    return s;
  }
  std::sort(v.begin(), v.end());
  s.min = v.front();
  s.max = v.back();
  s.p1 = percentile_sorted(v, 1.0);
  s.p5 = percentile_sorted(v, 5.0);
  s.median = percentile_sorted(v, 50.0);
  s.p95 = percentile_sorted(v, 95.0);
  s.p99 = percentile_sorted(v, 99.0);
  double sum = 0.0;
  for (double x : v) sum += x;
  s.mean = sum / static_cast<double>(v.size());
  double ss = 0.0;
  for (double x : v) ss += (x - s.mean) * (x - s.mean);
  s.std = v.size() > 1 ? std::sqrt(ss / static_cast<double>(v.size() - 1)) : 0.0;
  return s;
}

}  // namespace adcs::sim::campaign
