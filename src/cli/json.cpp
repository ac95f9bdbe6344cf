#include "cli/json.hpp"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <stdexcept>

namespace adcs::sim::cli {

std::string json_string(std::string_view s) {
  std::string out;
  out.reserve(s.size() + 2);
  out += '"';
  for (const char ch : s) {
    const auto c = static_cast<unsigned char>(ch);
    switch (c) {
      case '"': out += "\\\""; break;
      case '\\': out += "\\\\"; break;
      case '\n': out += "\\n"; break;
      case '\r': out += "\\r"; break;
      case '\t': out += "\\t"; break;
      case '\b': out += "\\b"; break;
      case '\f': out += "\\f"; break;
      default:
        if (c < 0x20 || c == 0x7f) {
          char buf[8];
          std::snprintf(buf, sizeof buf, "\\u%04x", c);
          out += buf;
        } else {
          out += ch;
        }
    }
  }
  out += '"';
  return out;
}

std::string json_number(double x) {
  if (!std::isfinite(x)) return "null";
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.15g", x);
  if (std::strtod(buf, nullptr) != x) std::snprintf(buf, sizeof buf, "%.17g", x);
  return buf;
}

void JsonWriter::newline_indent(std::size_t depth) {
  out_ += '\n';
  out_.append(2 * depth, ' ');
}

void JsonWriter::before_value() {
  if (stack_.empty()) {
    if (has_root_) throw std::logic_error("JsonWriter: a second root value");
    has_root_ = true;
    return;
  }
  Level& l = stack_.back();
  if (l.object) {
    if (!l.have_key) throw std::logic_error("JsonWriter: object member without a key");
    l.have_key = false;
    return;
  }
  if (l.count++) out_ += l.pretty ? "," : ", ";
  if (l.pretty) newline_indent(stack_.size());
}

JsonWriter& JsonWriter::key(std::string_view k) {
  if (stack_.empty() || !stack_.back().object || stack_.back().have_key)
    throw std::logic_error("JsonWriter: key outside an object or twice");
  Level& l = stack_.back();
  if (l.count++) out_ += l.pretty ? "," : ", ";
  if (l.pretty) newline_indent(stack_.size());
  out_ += json_string(k);
  out_ += ": ";
  l.have_key = true;
  return *this;
}

JsonWriter& JsonWriter::open(char c, bool object) {
  before_value();
  const bool pretty = static_cast<int>(stack_.size()) < pretty_depth_;
  out_ += c;
  stack_.push_back(Level{object, pretty});
  return *this;
}

JsonWriter& JsonWriter::close(char c, bool object) {
  if (stack_.empty() || stack_.back().object != object || stack_.back().have_key)
    throw std::logic_error("JsonWriter: unbalanced close");
  const Level l = stack_.back();
  stack_.pop_back();
  if (l.pretty && l.count) newline_indent(stack_.size());
  out_ += c;
  return *this;
}

JsonWriter& JsonWriter::begin_object() { return open('{', true); }
JsonWriter& JsonWriter::end_object() { return close('}', true); }
JsonWriter& JsonWriter::begin_array() { return open('[', false); }
JsonWriter& JsonWriter::end_array() { return close(']', false); }

JsonWriter& JsonWriter::raw(std::string_view json) {
  before_value();
  out_ += json;
  return *this;
}

JsonWriter& JsonWriter::value(double x) { return raw(json_number(x)); }
JsonWriter& JsonWriter::value(bool b) { return raw(b ? "true" : "false"); }
JsonWriter& JsonWriter::integer(long long x) { return raw(std::to_string(x)); }
JsonWriter& JsonWriter::uinteger(unsigned long long x) { return raw(std::to_string(x)); }
JsonWriter& JsonWriter::value(std::string_view s) { return raw(json_string(s)); }
JsonWriter& JsonWriter::null() { return raw("null"); }
JsonWriter& JsonWriter::value(const std::optional<bool>& b) {
  return b ? value(*b) : null();
}

JsonWriter& JsonWriter::value(const std::vector<double>& v) {
  begin_array();
  for (double x : v) value(x);
  return end_array();
}

JsonWriter& JsonWriter::value(const std::vector<std::vector<double>>& m) {
  begin_array();
  for (const auto& row : m) value(row);
  return end_array();
}

JsonWriter& JsonWriter::value(const std::vector<std::string>& v) {
  begin_array();
  for (const auto& s : v) value(s);
  return end_array();
}

}  // namespace adcs::sim::cli
