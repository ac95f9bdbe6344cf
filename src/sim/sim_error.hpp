#pragma once
// The one exception type of the ground harness (src/sim/). Flight code never throws; ground code
// reports integrator failures, bad options and I/O errors with a SimError whose message names the
// failing call (e.g. "CVode failed: flag -1 (CV_TOO_MUCH_WORK): ...").
#include <cstdio>
#include <stdexcept>
#include <string>

namespace adcs::sim {

struct SimError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

//! A double for an error message, round-trip exact (%.17g; std::to_string's %f would print
//! 1e-9 as "0.000000").
inline std::string format_double(double x) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.17g", x);
  return buffer;
}

}  // namespace adcs::sim
