#pragma once
// A tiny JSON writer for adcs-sim output: escaped strings, numbers with the shortest of
// %.15g / %.17g that round-trips (exact), null for non-finite numbers, arrays and objects.
// Compact output uses ", " and ": " separators, e.g. {"scenario": "x", "seed": 1}.
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace adcs::sim::cli {

//! `s` quoted and escaped (", \, control characters; UTF-8 passes through).
std::string json_string(std::string_view s);
//! A JSON number text, or "null" when x is NaN or infinite.
std::string json_number(double x);

class JsonWriter {
 public:
  //! Containers opened at nesting depth < pretty_depth put each member on its own line
  //! (two-space indent); deeper ones, and all with pretty_depth = 0, stay on one line.
  explicit JsonWriter(int pretty_depth = 0) : pretty_depth_(pretty_depth) {}

  JsonWriter& begin_object();
  JsonWriter& end_object();
  JsonWriter& begin_array();
  JsonWriter& end_array();
  //! Inside an object: the next member's key (the value follows).
  JsonWriter& key(std::string_view k);

  JsonWriter& value(double x);  // non-finite -> null
  JsonWriter& value(bool b);
  JsonWriter& value(int x) { return integer(x); }
  JsonWriter& value(long x) { return integer(x); }
  JsonWriter& value(long long x) { return integer(x); }
  JsonWriter& value(unsigned x) { return uinteger(x); }
  JsonWriter& value(unsigned long x) { return uinteger(x); }
  JsonWriter& value(unsigned long long x) { return uinteger(x); }
  JsonWriter& value(std::string_view s);
  JsonWriter& value(const char* s) { return value(std::string_view(s)); }
  JsonWriter& value(const std::string& s) { return value(std::string_view(s)); }
  JsonWriter& value(const std::optional<bool>& b);  // empty -> null
  JsonWriter& value(const std::vector<double>& v);
  JsonWriter& value(const std::vector<std::vector<double>>& m);
  JsonWriter& value(const std::vector<std::string>& v);
  JsonWriter& null();
  //! Inserts already-formatted JSON text as one value.
  JsonWriter& raw(std::string_view json);

  //! The text so far; complete once every container is closed.
  const std::string& str() const noexcept { return out_; }
  bool complete() const noexcept { return stack_.empty() && has_root_; }

 private:
  JsonWriter& integer(long long x);
  JsonWriter& uinteger(unsigned long long x);
  void before_value();
  void newline_indent(std::size_t depth);
  JsonWriter& open(char c, bool object);
  JsonWriter& close(char c, bool object);

  struct Level {
    bool object;
    bool pretty;
    std::size_t count = 0;
    bool have_key = false;
  };
  int pretty_depth_;
  std::string out_;
  std::vector<Level> stack_;
  bool has_root_ = false;
};

}  // namespace adcs::sim::cli
