#include "sim/metrics.hpp"

#include <algorithm>
#include <cmath>
#include <complex>
#include <limits>
#include <string>
#include <unsupported/Eigen/FFT>

namespace adcs::sim::metrics {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kPi = 3.14159265358979323846;

void check_same_size(const std::vector<double>& t, const std::vector<double>& y,
                     const char* who) {
  if (t.size() != y.size())
    throw SimError(std::string(who) + ": t has " + std::to_string(t.size()) + " samples, y has " +
                   std::to_string(y.size()));
}

// Index of the first sample of the final run inside the band (size() if the last one is outside).
template <class Inside>
std::size_t start_of_final_inside_run(std::size_t n, Inside inside) {
  std::size_t i = n;
  while (i > 0 && inside(i - 1)) --i;
  return i;
}

}  // namespace

double max_abs_in_window(const std::vector<double>& t, const std::vector<double>& y,
                         double t_begin, double t_end) {
  check_same_size(t, y, "max_abs_in_window");
  bool any = false;
  double m = 0.0;
  for (std::size_t i = 0; i < t.size(); ++i) {
    if (t[i] < t_begin || t[i] > t_end) continue;
    const double a = std::abs(y[i]);
    if (std::isnan(a)) return kNaN;  // why: std::max would silently drop a NaN sample
    m = any ? std::max(m, a) : a;
    any = true;
  }
  return any ? m : kNaN;
}

double rms_in_window(const std::vector<double>& t, const std::vector<double>& y, double t_begin,
                     double t_end) {
  check_same_size(t, y, "rms_in_window");
  double sum_sq = 0.0;
  std::size_t count = 0;
  for (std::size_t i = 0; i < t.size(); ++i) {
    if (t[i] < t_begin || t[i] > t_end) continue;
    sum_sq += y[i] * y[i];
    ++count;
  }
  return count == 0 ? kNaN : std::sqrt(sum_sq / static_cast<double>(count));
}

double settling_time(const std::vector<double>& t, const std::vector<double>& y, double band) {
  check_same_size(t, y, "settling_time");
  const std::size_t i =
      start_of_final_inside_run(t.size(), [&](std::size_t j) { return std::abs(y[j]) <= band; });
  return i == t.size() ? kNaN : t[i] - t.front();
}

double settling_time(const std::vector<double>& t, const std::vector<std::vector<double>>& ys,
                     double band) {
  for (const auto& y : ys) check_same_size(t, y, "settling_time");
  const std::size_t i = start_of_final_inside_run(t.size(), [&](std::size_t j) {
    return std::all_of(ys.begin(), ys.end(),
                       [&](const std::vector<double>& y) { return std::abs(y[j]) <= band; });
  });
  return i == t.size() ? kNaN : t[i] - t.front();
}

WelchResult welch_psd(const std::vector<double>& x, double fs_hz, std::size_t segment_length,
                      double overlap) {
  const std::size_t L = segment_length;
  if (!(fs_hz > 0.0) || !std::isfinite(fs_hz) || L < 2 || L > x.size() || !(overlap >= 0.0) ||
      !(overlap < 1.0))
    throw SimError("welch_psd: need fs > 0, 2 <= segment_length <= x.size() and 0 <= overlap < 1 "
                   "(fs = " + format_double(fs_hz) + " Hz, segment_length = " +
                   std::to_string(L) + ", x.size() = " + std::to_string(x.size()) +
                   ", overlap = " + format_double(overlap) + ")");
  const auto overlap_samples = static_cast<std::size_t>(std::lround(overlap * static_cast<double>(L)));
  const std::size_t hop = std::max<std::size_t>(1, L - std::min(overlap_samples, L - 1));
  const std::size_t segments = 1 + (x.size() - L) / hop;

  // Periodic Hann window (as scipy.signal.welch's default): w_n = 0.5 - 0.5 cos(2 pi n / L).
  std::vector<double> w(L);
  double sum_w2 = 0.0;
  for (std::size_t n = 0; n < L; ++n) {
    w[n] = 0.5 - 0.5 * std::cos(2.0 * kPi * static_cast<double>(n) / static_cast<double>(L));
    sum_w2 += w[n] * w[n];
  }

  const std::size_t bins = L / 2 + 1;
  WelchResult r;
  r.f_hz.resize(bins);
  r.psd.assign(bins, 0.0);
  for (std::size_t k = 0; k < bins; ++k)
    r.f_hz[k] = static_cast<double>(k) * fs_hz / static_cast<double>(L);

  Eigen::FFT<double> fft;
  std::vector<double> segment(L);
  std::vector<std::complex<double>> spectrum;
  for (std::size_t s = 0; s < segments; ++s) {
    const double* xs = x.data() + s * hop;
    double mean = 0.0;
    for (std::size_t n = 0; n < L; ++n) mean += xs[n];
    mean /= static_cast<double>(L);
    for (std::size_t n = 0; n < L; ++n) segment[n] = w[n] * (xs[n] - mean);
    fft.fwd(spectrum, segment);
    for (std::size_t k = 0; k < bins; ++k) r.psd[k] += std::norm(spectrum[k]);
  }

  const double scale = 1.0 / (fs_hz * sum_w2 * static_cast<double>(segments));
  for (std::size_t k = 0; k < bins; ++k) {
    // One-sided: fold the negative frequencies in, except DC and (even L) Nyquist, which have none.
    const bool unpaired = k == 0 || (L % 2 == 0 && k == L / 2);
    r.psd[k] *= (unpaired ? 1.0 : 2.0) * scale;
  }
  return r;
}

std::vector<double> asd(const std::vector<double>& psd) {
  std::vector<double> a(psd.size());
  std::transform(psd.begin(), psd.end(), a.begin(), [](double p) { return std::sqrt(p); });
  return a;
}

double median(std::vector<double> values) {
  if (values.empty()) return kNaN;
  const std::size_t mid = values.size() / 2;
  std::nth_element(values.begin(), values.begin() + static_cast<std::ptrdiff_t>(mid), values.end());
  const double upper = values[mid];
  if (values.size() % 2 == 1) return upper;
  const double lower = *std::max_element(values.begin(), values.begin() + static_cast<std::ptrdiff_t>(mid));
  return 0.5 * (lower + upper);
}

}  // namespace adcs::sim::metrics
