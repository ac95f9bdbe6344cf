#pragma once
// How a run is judged against a paper's own number (issue 16): the rules every scenario uses for
// Claim::paper_verdict, in one place, so "reproduced" means the same thing in every row.
//   - a bound the paper states ("≤ x", "below x", "> x% fewer"): reproduced when ours meets it,
//     partly when ours misses it by at most a factor `partly_factor` (default 2), else not;
//   - an order of magnitude ("0.3 rad order"): reproduced within a factor √10 of the stated
//     value (the same decade, centred), partly within a factor 10, else not;
//   - a value the paper reports ("3.72e-3°"): reproduced within rel_tol (default 30 %, the
//     reading accuracy of a figure), partly within a factor 2, else not;
//   - a qualitative statement: reproduced / not reproduced from the run's own test, or partly
//     when the run shows it only in part (the caller says which).
#include <cmath>

#include "scenarios/scenario.hpp"

namespace adcs::sim {

//! The paper states ours ≤ bound (bound > 0).
inline PaperVerdict verdict_at_most(double ours, double bound, double partly_factor = 2.0) {
  if (!(ours == ours)) return PaperVerdict::not_reproduced;  // NaN: nothing to compare
  if (ours <= bound) return PaperVerdict::reproduced;
  return ours <= partly_factor * bound ? PaperVerdict::partly : PaperVerdict::not_reproduced;
}

//! The paper states ours ≥ bound (bound > 0).
inline PaperVerdict verdict_at_least(double ours, double bound, double partly_factor = 2.0) {
  if (!(ours == ours)) return PaperVerdict::not_reproduced;
  if (ours >= bound) return PaperVerdict::reproduced;
  return ours * partly_factor >= bound ? PaperVerdict::partly : PaperVerdict::not_reproduced;
}

//! The paper states "of the order of `order`" (order > 0).
inline PaperVerdict verdict_order_of(double ours, double order) {
  if (!(ours > 0.0)) return PaperVerdict::not_reproduced;
  const double decades = std::fabs(std::log10(ours / order));
  if (decades <= 0.5) return PaperVerdict::reproduced;
  return decades <= 1.0 ? PaperVerdict::partly : PaperVerdict::not_reproduced;
}

//! The paper reports the value `paper` (≠ 0).
inline PaperVerdict verdict_value(double ours, double paper, double rel_tol = 0.3) {
  if (!(ours == ours) || paper == 0.0) return PaperVerdict::not_reproduced;
  const double ratio = ours / paper;
  if (std::fabs(ratio - 1.0) <= rel_tol) return PaperVerdict::reproduced;
  return ratio >= 0.5 && ratio <= 2.0 ? PaperVerdict::partly : PaperVerdict::not_reproduced;
}

//! A qualitative statement: reproduced if the run shows it, partly if only in part.
inline PaperVerdict verdict_if(bool shown, bool partly = false) {
  if (shown) return PaperVerdict::reproduced;
  return partly ? PaperVerdict::partly : PaperVerdict::not_reproduced;
}

}  // namespace adcs::sim
