#include "cli/json_text.hpp"

#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace adcs::sim::cli {
namespace ADCS_UNITY_ID {

//! `s` quoted and escaped by nlohmann.
std::string string_text(const std::string& s) {
  std::string text = Json(s).dump(-1, ' ', /*ensure_ascii=*/false, Json::error_handler_t::replace);
  // nlohmann leaves DEL (0x7f) raw, which JSON allows; adcs-sim has always escaped it. A 0x7f
  // byte cannot be part of a UTF-8 sequence, so replacing each one is exact.
  for (auto at = text.find('\x7f'); at != std::string::npos; at = text.find('\x7f', at))
    text.replace(at, 1, "\\u007f");
  return text;
}

void newline_indent(std::string& out, std::size_t depth) {
  out += '\n';
  out.append(2 * depth, ' ');
}

void append(std::string& out, const Json& value, int pretty_depth, std::size_t depth) {
  if (value.is_object() || value.is_array()) {
    const bool object = value.is_object();
    const bool pretty = static_cast<int>(depth) < pretty_depth;
    out += object ? '{' : '[';
    bool first = true;
    for (auto it = value.begin(); it != value.end(); ++it) {
      if (!first) out += pretty ? "," : ", ";
      first = false;
      if (pretty) newline_indent(out, depth + 1);
      if (object) {
        out += string_text(it.key());
        out += ": ";
      }
      append(out, it.value(), pretty_depth, depth + 1);
    }
    if (pretty && !value.empty()) newline_indent(out, depth);
    out += object ? '}' : ']';
  } else if (value.is_number_float()) {
    out += json_number(value.get<double>());
  } else if (value.is_string()) {
    out += string_text(value.get_ref<const std::string&>());
  } else {
    out += value.dump();  // null, true, false, integers: nlohmann's text is ours
  }
}

}  // namespace
using namespace ADCS_UNITY_ID;  // as an anonymous namespace would (CMakeLists.txt, adcs_unity)

std::string json_number(double x) {
  if (!std::isfinite(x)) return "null";
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.15g", x);
  if (std::strtod(buf, nullptr) != x) std::snprintf(buf, sizeof buf, "%.17g", x);
  return buf;
}

std::string json_text(const Json& value, int pretty_depth) {
  std::string out;
  append(out, value, pretty_depth, 0);
  return out;
}

}  // namespace adcs::sim::cli
