#pragma once
// One HDF5 file per campaign with the percentile envelopes of its chosen time series (issue 18),
// read by tools/plot.py (h5py) for the band plots. Layout:
//   /<series>/t                 [n]      sample times [s]
//   /<series>/percentiles       [9 x n]  rows at the levels of /<series>/levels
//   /<series>/levels            [9]      0, 1, 5, 25, 50, 75, 95, 99, 100 (%)
//   /<series>/mean              [n]
//   attribute runs on /<series>: how many runs contributed
// Written with object time tracking off, so the same envelopes give the same bytes (a merged
// campaign's file equals the unsharded one's).
#include <string>
#include <vector>

#include "campaign/series.hpp"

namespace adcs::sim::campaign {

//! Writes `envelopes` to `path` (created or truncated); throws std::runtime_error naming the
//! HDF5 call that failed.
void write_envelopes_h5(const std::string& path, const std::vector<Envelope>& envelopes);

}  // namespace adcs::sim::campaign
