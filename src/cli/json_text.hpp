#pragma once
// The text of adcs-sim's JSON. nlohmann/json holds the document (ordered_json: members stay in
// insertion order, which is part of the output) and escapes its strings; the numbers and the
// layout are ours, because the outputs (and the tests, and readers diffing them) pin them byte
// for byte and nlohmann's dump() produces neither:
//   - a number is the shorter of %.15g and %.17g that reads back exactly ("1", "0.1", "1e-300",
//     "2e+300", "0.79999999999999993"); NaN and infinities are null. dump() writes the shortest
//     digits that read back ("0.7999999999999999") and "2.0" for an integral double.
//   - containers opened at a depth below `pretty_depth` put each member on its own line (two
//     spaces a level); deeper ones stay on one line, with ", " and ": " as separators. dump()
//     indents every level or none, and its compact form uses "," and ":".
// Strings: UTF-8 passes through; ", \, control characters and DEL are escaped (\u00XX); an
// invalid UTF-8 byte becomes U+FFFD (the file stays valid JSON).
#include <string>

#include <nlohmann/json.hpp>

namespace adcs::sim::cli {

using Json = nlohmann::ordered_json;

//! A JSON number text, or "null" when x is NaN or infinite.
std::string json_number(double x);

//! `value` as text (see above); pretty_depth 0 is one line, e.g. {"scenario": "x", "seed": 1}.
std::string json_text(const Json& value, int pretty_depth = 0);

}  // namespace adcs::sim::cli
