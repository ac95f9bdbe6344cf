#pragma once
// How many equal pieces of at most `step` cover a time span: the one rounding rule shared by the
// RK4 substeps and the sampled-data loop.
#include <cmath>
#include <cstddef>
#include <string>

#include "sim/sim_error.hpp"

namespace adcs::sim {

//! ceil(span / step), except that a ratio within 1e-9 above an integer counts as that integer.
//! Why: t_end = 10 s with T = 0.1 s gives span/step = 100.00000000000001 in floating point, and a
//! literal ceil() would add a spurious 1e-15 s interval (which CVODE rejects as CV_TOO_CLOSE).
//! Returns 0 for span == 0. Throws SimError for step <= 0, span < 0 or non-finite inputs.
inline std::size_t interval_count(double span_s, double step_s) {
  if (!(step_s > 0.0) || !std::isfinite(step_s) || !(span_s >= 0.0) || !std::isfinite(span_s))
    throw SimError("interval_count: need finite span >= 0 and step > 0 (span = " +
                   format_double(span_s) + " s, step = " + format_double(step_s) + " s)");
  if (span_s == 0.0) return 0;
  constexpr double kRatioTolerance = 1e-9;
  const double n = std::ceil(span_s / step_s - kRatioTolerance);
  return n < 1.0 ? std::size_t{1} : static_cast<std::size_t>(n);
}

}  // namespace adcs::sim
