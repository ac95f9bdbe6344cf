#include "scenarios/params.hpp"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <system_error>
#include <utility>

namespace adcs::sim {
namespace ADCS_UNITY_ID {

bool is_space(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; }
bool is_digit(char c) { return c >= '0' && c <= '9'; }
bool is_alpha(char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z'); }
bool is_ident_start(char c) { return is_alpha(c) || c == '_'; }
bool is_ident_char(char c) { return is_ident_start(c) || is_digit(c) || c == '-' || c == '.'; }

std::string lower(std::string s) {
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

bool is_nonfinite_word(const std::string& s) {
  const std::string l = lower(s);
  return l == "nan" || l == "inf" || l == "infinity";
}

// Recursive-descent parser over the value text. Positions in messages are 1-based.
class Parser {
 public:
  explicit Parser(const std::string& text) : s_(text) {}

  ParsedValue parse() {
    skip_ws();
    if (at_end()) fail_plain("empty value");
    ParsedValue v;
    const char c = s_[pos_];
    if (c == '[') {
      parse_list(v);
    } else if (is_ident_start(c)) {
      v.shape = ParsedValue::Shape::name;
      v.name = parse_ident();
      if (is_nonfinite_word(v.name))
        fail_plain("'" + v.name + "' is not allowed: values must be finite numbers");
    } else {
      v.shape = ParsedValue::Shape::number;
      v.number = parse_number();
    }
    skip_ws();
    if (!at_end()) fail("unexpected '" + rest() + "' after the value");
    return v;
  }

 private:
  bool at_end() const { return pos_ >= s_.size(); }
  void skip_ws() {
    while (!at_end() && is_space(s_[pos_])) ++pos_;
  }
  std::string rest() const {
    std::string r = s_.substr(pos_);
    if (r.size() > 20) r = r.substr(0, 20) + "...";
    return r;
  }
  [[noreturn]] void fail(const std::string& what) const {
    throw ParamError(what + " at character " + std::to_string(pos_ + 1) + " of '" + s_ + "'");
  }
  [[noreturn]] void fail_plain(const std::string& what) const { throw ParamError(what); }

  std::string parse_ident() {
    const std::size_t b = pos_;
    while (!at_end() && is_ident_char(s_[pos_])) ++pos_;
    return s_.substr(b, pos_ - b);
  }

  // [+-]? ( digits [. digits?] | . digits ) ( [eE] [+-]? digits )?
  double parse_number() {
    const std::size_t b = pos_;
    if (!at_end() && (s_[pos_] == '+' || s_[pos_] == '-')) ++pos_;
    std::size_t int_digits = 0, frac_digits = 0;
    while (!at_end() && is_digit(s_[pos_])) ++pos_, ++int_digits;
    if (!at_end() && s_[pos_] == '.') {
      ++pos_;
      while (!at_end() && is_digit(s_[pos_])) ++pos_, ++frac_digits;
    }
    if (int_digits + frac_digits == 0) {
      if (!at_end() && is_alpha(s_[pos_])) {
        const std::string word = parse_ident();
        if (is_nonfinite_word(word))
          fail_plain("'" + s_.substr(b, pos_ - b) +
                     "' is not allowed: values must be finite numbers");
      }
      pos_ = b;
      if (at_end() || s_[pos_] == ',' || s_[pos_] == ']') fail("empty element");
      fail("malformed number '" + rest() + "'");
    }
    if (!at_end() && (s_[pos_] == 'e' || s_[pos_] == 'E')) {
      const std::size_t e = pos_;
      ++pos_;
      if (!at_end() && (s_[pos_] == '+' || s_[pos_] == '-')) ++pos_;
      std::size_t exp_digits = 0;
      while (!at_end() && is_digit(s_[pos_])) ++pos_, ++exp_digits;
      if (exp_digits == 0) {
        pos_ = e;
        fail("malformed exponent in '" + s_.substr(b) + "'");
      }
    }
    if (!at_end() && (is_ident_char(s_[pos_]) || s_[pos_] == '.')) {
      fail("malformed number '" + s_.substr(b, pos_ - b + 1) + "'");
    }
    // from_chars does not accept a leading '+'.
    const char* first = s_.data() + b;
    const char* last = s_.data() + pos_;
    if (*first == '+') ++first;
    double x = 0.0;
    const auto r = std::from_chars(first, last, x, std::chars_format::general);
    if (r.ec == std::errc::result_out_of_range) {
      // Overflow or underflow: strtod tells which (HUGE_VAL on overflow).
      const std::string t(first, last);
      errno = 0;
      x = std::strtod(t.c_str(), nullptr);
      if (!std::isfinite(x) || std::fabs(x) == HUGE_VAL)
        fail_plain("'" + std::string(s_.data() + b, last) +
                   "' is out of range: values must be finite numbers");
    } else if (r.ec != std::errc() || r.ptr != last) {
      pos_ = b;
      fail("malformed number");
    }
    if (!std::isfinite(x)) fail_plain("values must be finite numbers");
    return x;
  }

  // '[' already at pos_. Either a list of numbers (vector) or a list of lists (matrix).
  void parse_list(ParsedValue& v) {
    ++pos_;  // '['
    skip_ws();
    if (!at_end() && s_[pos_] == ']') {  // []
      ++pos_;
      v.shape = ParsedValue::Shape::vector;
      return;
    }
    if (!at_end() && s_[pos_] == '[') {
      v.shape = ParsedValue::Shape::matrix;
      for (;;) {
        skip_ws();
        if (at_end()) fail("missing ']'");
        if (s_[pos_] != '[') {
          if (s_[pos_] == ',' || s_[pos_] == ']') fail("empty row");
          fail("a matrix row must be a bracketed list '[..]'");
        }
        ++pos_;
        std::vector<double> row = parse_numbers("row");
        if (row.empty()) fail("empty row");
        if (!v.matrix.empty() && row.size() != v.matrix.front().size())
          fail("ragged matrix: row " + std::to_string(v.matrix.size() + 1) + " has " +
               std::to_string(row.size()) + " elements, row 1 has " +
               std::to_string(v.matrix.front().size()));
        v.matrix.push_back(std::move(row));
        skip_ws();
        if (at_end()) fail("missing ']'");
        if (s_[pos_] == ',') {
          ++pos_;
          continue;
        }
        if (s_[pos_] == ']') {
          ++pos_;
          return;
        }
        fail("expected ',' or ']'");
      }
    }
    v.shape = ParsedValue::Shape::vector;
    v.vector = parse_numbers("vector");
  }

  // After '[': numbers separated by ',' up to and including ']'. Returns empty for "[]".
  std::vector<double> parse_numbers(const char* what) {
    std::vector<double> out;
    skip_ws();
    if (!at_end() && s_[pos_] == ']') {
      ++pos_;
      return out;
    }
    for (;;) {
      skip_ws();
      if (at_end()) fail(std::string("missing ']' (unterminated ") + what + ")");
      if (s_[pos_] == '[') fail("too deeply nested: at most a matrix [[..],[..]]");
      out.push_back(parse_number());
      skip_ws();
      if (at_end()) fail(std::string("missing ']' (unterminated ") + what + ")");
      if (s_[pos_] == ',') {
        ++pos_;
        continue;
      }
      if (s_[pos_] == ']') {
        ++pos_;
        return out;
      }
      fail("expected ',' or ']'");
    }
  }

  const std::string& s_;
  std::size_t pos_ = 0;
};

const char* kind_name(ParamKind k) {
  switch (k) {
    case ParamKind::number: return "a number";
    case ParamKind::vector: return "a vector";
    case ParamKind::matrix: return "a matrix";
    case ParamKind::name: return "a name";
  }
  return "?";
}

const char* shape_name(ParsedValue::Shape s) {
  switch (s) {
    case ParsedValue::Shape::number: return "a number";
    case ParsedValue::Shape::vector: return "a vector";
    case ParsedValue::Shape::matrix: return "a matrix";
    case ParsedValue::Shape::name: return "a name";
  }
  return "?";
}

bool valid_key(const std::string& key) {
  if (key.empty()) return false;
  return std::all_of(key.begin(), key.end(), [](char c) {
    return is_alpha(c) || is_digit(c) || c == '_' || c == '.';
  });
}

bool valid_ident(const std::string& s) {
  if (s.empty() || !is_ident_start(s.front())) return false;
  return std::all_of(s.begin(), s.end(), is_ident_char);
}

std::string join(const std::vector<std::string>& v, const char* sep) {
  std::string out;
  for (std::size_t i = 0; i < v.size(); ++i) {
    if (i) out += sep;
    out += v[i];
  }
  return out;
}

std::size_t edit_distance(const std::string& a, const std::string& b) {
  std::vector<std::size_t> prev(b.size() + 1), cur(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) prev[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    cur[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t subst = prev[j - 1] + (a[i - 1] == b[j - 1] ? 0 : 1);
      cur[j] = std::min({prev[j] + 1, cur[j - 1] + 1, subst});
    }
    std::swap(prev, cur);
  }
  return prev[b.size()];
}

std::string format_list(const std::vector<double>& v) {
  std::string out = "[";
  for (std::size_t i = 0; i < v.size(); ++i) {
    if (i) out += ", ";
    out += format_number(v[i]);
  }
  return out + "]";
}

}  // namespace
using namespace ADCS_UNITY_ID;  // as an anonymous namespace would (CMakeLists.txt, adcs_unity)

ParsedValue parse_value(const std::string& text) { return Parser(text).parse(); }

std::string format_number(double x) {
  if (std::isnan(x)) return "nan";
  if (std::isinf(x)) return x > 0 ? "inf" : "-inf";
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.15g", x);
  if (std::strtod(buf, nullptr) != x) std::snprintf(buf, sizeof buf, "%.17g", x);
  return buf;
}

std::string format_value(ParamKind kind, const ParamValue& v) {
  switch (kind) {
    case ParamKind::number: return format_number(v.number);
    case ParamKind::vector: return format_list(v.vector);
    case ParamKind::matrix: {
      std::string out = "[";
      for (std::size_t i = 0; i < v.matrix.size(); ++i) {
        if (i) out += ", ";
        out += format_list(v.matrix[i]);
      }
      return out + "]";
    }
    case ParamKind::name: return v.name;
  }
  return "";
}

std::string describe_kind(const Param& p) {
  switch (p.kind) {
    case ParamKind::number: return "a number";
    case ParamKind::vector:
      return p.size < 0 ? std::string("a vector [a, b, ...] of any length")
                        : "a vector of " + std::to_string(p.size) + " numbers";
    case ParamKind::matrix:
      return "a " + std::to_string(p.rows) + "x" + std::to_string(p.cols) +
             " matrix [[..], ..] (row-major)";
    case ParamKind::name:
      return p.allowed.empty() ? std::string("a name") : "one of: " + join(p.allowed, ", ");
  }
  return "";
}

// ---- declaration ---------------------------------------------------------------------------

Param& ParamSet::declare(const std::string& key, ParamKind kind) {
  if (!valid_key(key))
    throw std::logic_error("parameter key '" + key + "' must be non-empty [A-Za-z0-9_.]");
  if (index_.count(key)) throw std::logic_error("parameter '" + key + "' declared twice");
  index_.emplace(key, params_.size());
  params_.emplace_back();
  Param& p = params_.back();
  p.key = key;
  p.kind = kind;
  return p;
}

void ParamSet::number(const std::string& key, double def, std::string unit, std::string source) {
  if (!std::isfinite(def))
    throw std::logic_error("parameter '" + key + "': default must be finite");
  Param& p = declare(key, ParamKind::number);
  p.value.number = def;
  p.unit = std::move(unit);
  p.source = std::move(source);
  p.default_value = p.value;
}

void ParamSet::vector(const std::string& key, std::vector<double> def, std::string unit,
                      std::string source) {
  if (def.empty())
    throw std::logic_error("parameter '" + key + "': a fixed-size vector needs a non-empty "
                           "default (use vector_any for any length)");
  for (double x : def)
    if (!std::isfinite(x))
      throw std::logic_error("parameter '" + key + "': default must be finite");
  Param& p = declare(key, ParamKind::vector);
  p.size = static_cast<int>(def.size());
  p.value.vector = std::move(def);
  p.unit = std::move(unit);
  p.source = std::move(source);
  p.default_value = p.value;
}

void ParamSet::vector_any(const std::string& key, std::vector<double> def, std::string unit,
                          std::string source) {
  for (double x : def)
    if (!std::isfinite(x))
      throw std::logic_error("parameter '" + key + "': default must be finite");
  Param& p = declare(key, ParamKind::vector);
  p.size = -1;
  p.value.vector = std::move(def);
  p.unit = std::move(unit);
  p.source = std::move(source);
  p.default_value = p.value;
}

void ParamSet::matrix(const std::string& key, std::vector<std::vector<double>> def,
                      std::string unit, std::string source) {
  if (def.empty() || def.front().empty())
    throw std::logic_error("parameter '" + key + "': matrix default must be at least 1x1");
  for (const auto& row : def) {
    if (row.size() != def.front().size())
      throw std::logic_error("parameter '" + key + "': matrix default is ragged");
    for (double x : row)
      if (!std::isfinite(x))
        throw std::logic_error("parameter '" + key + "': default must be finite");
  }
  Param& p = declare(key, ParamKind::matrix);
  p.rows = static_cast<int>(def.size());
  p.cols = static_cast<int>(def.front().size());
  p.value.matrix = std::move(def);
  p.unit = std::move(unit);
  p.source = std::move(source);
  p.default_value = p.value;
}

void ParamSet::name(const std::string& key, std::string def, std::vector<std::string> allowed,
                    std::string source) {
  if (!valid_ident(def))
    throw std::logic_error("parameter '" + key + "': default '" + def +
                           "' is not a bare identifier");
  for (const auto& a : allowed)
    if (!valid_ident(a))
      throw std::logic_error("parameter '" + key + "': allowed value '" + a +
                             "' is not a bare identifier");
  if (!allowed.empty() && std::find(allowed.begin(), allowed.end(), def) == allowed.end())
    throw std::logic_error("parameter '" + key + "': default '" + def + "' is not allowed");
  Param& p = declare(key, ParamKind::name);
  p.value.name = std::move(def);
  p.allowed = std::move(allowed);
  p.source = std::move(source);
  p.default_value = p.value;
}

// ---- access --------------------------------------------------------------------------------

bool ParamSet::has(const std::string& key) const { return index_.count(key) != 0; }

const Param& ParamSet::at(const std::string& key) const {
  const auto it = index_.find(key);
  if (it == index_.end()) throw std::logic_error("parameter '" + key + "' is not declared");
  return params_[it->second];
}

const Param& ParamSet::checked(const std::string& key, ParamKind kind) const {
  const Param& p = at(key);
  if (p.kind != kind)
    throw std::logic_error("parameter '" + key + "' is " + kind_name(p.kind) + ", read as " +
                           kind_name(kind));
  return p;
}

double ParamSet::get_number(const std::string& key) const {
  return checked(key, ParamKind::number).value.number;
}
std::vector<double> ParamSet::get_vector(const std::string& key) const {
  return checked(key, ParamKind::vector).value.vector;
}
std::vector<std::vector<double>> ParamSet::get_matrix(const std::string& key) const {
  return checked(key, ParamKind::matrix).value.matrix;
}
std::string ParamSet::get_name(const std::string& key) const {
  return checked(key, ParamKind::name).value.name;
}

void ParamSet::size_mismatch(const std::string& key, const std::string& want, std::size_t got) {
  throw ParamError("parameter '" + key + "' must be a vector of " + want + " numbers, got " +
                   std::to_string(got));
}

void ParamSet::shape_mismatch(const std::string& key, int r, int c, std::size_t gr,
                              std::size_t gc) {
  throw ParamError("parameter '" + key + "' must be a " + std::to_string(r) + "x" +
                   std::to_string(c) + " matrix, got " + std::to_string(gr) + "x" +
                   std::to_string(gc));
}

std::vector<std::string> ParamSet::suggestions(const std::string& key) const {
  std::vector<std::pair<std::size_t, std::string>> scored;
  const std::string lk = lower(key);
  for (const auto& p : params_) {
    const std::string lp = lower(p.key);
    std::size_t d = edit_distance(lk, lp);
    if (lp.find(lk) != std::string::npos || lk.find(lp) != std::string::npos)
      d = std::min<std::size_t>(d, 1);
    if (d <= std::max<std::size_t>(2, key.size() / 3)) scored.emplace_back(d, p.key);
  }
  std::stable_sort(scored.begin(), scored.end(),
                   [](const auto& a, const auto& b) { return a.first < b.first; });
  std::vector<std::string> out;
  for (std::size_t i = 0; i < scored.size() && i < 3; ++i) out.push_back(scored[i].second);
  return out;
}

void ParamSet::set(const std::string& key, const std::string& text) {
  const auto it = index_.find(key);
  if (it == index_.end()) {
    std::string msg = "unknown parameter '" + key + "'";
    const auto near = suggestions(key);
    if (!near.empty()) msg += " (did you mean " + join(near, ", ") + "?)";
    throw ParamError(msg);
  }
  Param& p = params_[it->second];
  ParsedValue v;
  try {
    v = parse_value(text);
  } catch (const ParamError& e) {
    throw ParamError("parameter '" + key + "': " + e.what());
  }
  const auto wrong = [&](const std::string& want) {  // throws
    std::string got = shape_name(v.shape);
    if (v.shape == ParsedValue::Shape::name) got += " '" + v.name + "'";
    if (v.shape == ParsedValue::Shape::vector)
      got += " of " + std::to_string(v.vector.size()) + " numbers";
    if (v.shape == ParsedValue::Shape::matrix)
      got += " " + std::to_string(v.matrix.size()) + "x" +
             std::to_string(v.matrix.front().size());
    throw ParamError("parameter '" + key + "' must be " + want + ", got " + got);
  };
  switch (p.kind) {
    case ParamKind::number:
      if (v.shape != ParsedValue::Shape::number) wrong(describe_kind(p));
      p.value.number = v.number;
      break;
    case ParamKind::vector:
      if (v.shape != ParsedValue::Shape::vector ||
          (p.size >= 0 && v.vector.size() != static_cast<std::size_t>(p.size)))
        wrong(describe_kind(p));
      p.value.vector = std::move(v.vector);
      break;
    case ParamKind::matrix:
      if (v.shape != ParsedValue::Shape::matrix ||
          v.matrix.size() != static_cast<std::size_t>(p.rows) ||
          v.matrix.front().size() != static_cast<std::size_t>(p.cols))
        wrong(describe_kind(p));
      p.value.matrix = std::move(v.matrix);
      break;
    case ParamKind::name:
      if (v.shape != ParsedValue::Shape::name ||
          (!p.allowed.empty() &&
           std::find(p.allowed.begin(), p.allowed.end(), v.name) == p.allowed.end()))
        wrong(describe_kind(p));
      p.value.name = std::move(v.name);
      break;
  }
  p.overridden = true;
}

void declare_scalar(ParamSet& p) {
  p.name("scalar", "double", {"double", "float"}, kScalarHelp);
}

}  // namespace adcs::sim
