#pragma once
// Scalar figures of merit computed from recorded time series: windowed max/RMS, settling time,
// Welch power spectral density. Ground code: plain std::vector in, numbers out.
// Size mismatches and invalid arguments throw adcs::sim::SimError; an empty selection gives NaN.
#include <cstddef>
#include <vector>

#include "sim/sim_error.hpp"

namespace adcs::sim::metrics {

//! max |y_i| over the samples with t_begin <= t_i <= t_end [s]; NaN if no sample is in the
//! window or one of them is NaN.
double max_abs_in_window(const std::vector<double>& t, const std::vector<double>& y,
                         double t_begin, double t_end);

//! sqrt(mean(y_i^2)) over the samples with t_begin <= t_i <= t_end [s] (each sample weighs the
//! same: meant for uniformly sampled signals); NaN if no sample is in the window.
double rms_in_window(const std::vector<double>& t, const std::vector<double>& y, double t_begin,
                     double t_end);

//! Settling time [s], measured from t.front(): t_i - t_0 for the first sample i from which
//! |y_j| <= band for every j >= i until the end. 0 if y is always inside the band, NaN if the last
//! sample is outside (never settles) or the series is empty. The resolution is the sample spacing.
double settling_time(const std::vector<double>& t, const std::vector<double>& y, double band);

//! As above for several signals sampled at t: settled when all of them are inside the band.
double settling_time(const std::vector<double>& t, const std::vector<std::vector<double>>& ys,
                     double band);

struct WelchResult {
  std::vector<double> f_hz;  //!< [Hz] k * fs / L, k = 0 .. floor(L/2)
  std::vector<double> psd;   //!< [unit^2/Hz] one-sided power spectral density
};

//! Welch's averaged periodogram: segments of segment_length L samples overlapping by
//! round(overlap * L), each with its mean removed and a periodic Hann window w applied;
//! PSD(f_k) = 2 |sum_n w_n x_n e^{-i 2 pi k n / L}|^2 / (fs sum_n w_n^2), without the factor 2 at
//! DC and (even L) Nyquist, averaged over segments. So sum_k PSD_k * fs/L ~ variance of x.
//! Throws SimError unless fs_hz > 0, 2 <= L <= x.size() and 0 <= overlap < 1.
WelchResult welch_psd(const std::vector<double>& x, double fs_hz, std::size_t segment_length,
                      double overlap = 0.5);

//! Amplitude spectral density [unit/sqrt(Hz)]: element-wise sqrt of a PSD.
std::vector<double> asd(const std::vector<double>& psd);

//! Median (mean of the two middle values for an even count); NaN for an empty vector.
double median(std::vector<double> values);

}  // namespace adcs::sim::metrics
