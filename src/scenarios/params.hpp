#pragma once
// Declared scenario parameters: defaults with unit and source, typed access, and the strict
// parser for `adcs-sim run NAME --set key=value` (ground code: allocates, throws).
//
// Value syntax of --set (whitespace allowed inside brackets and around the value):
//   number   1e-3  -2  0.5  +.5  3.      (finite only: nan/inf text and overflow are rejected)
//   vector   [a, b, c]      ([] is an empty vector, accepted only by vector_any parameters)
//   matrix   [[a, b], [c, d]]  (row-major, rectangular, no empty rows)
//   name     adams  bdf  sr_inverse  sr-inverse  (bare identifier: letter or '_' first, then
//            letters, digits, '_', '-', '.')
#include <cstddef>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

#include <Eigen/Core>

namespace adcs::sim {

//! A bad parameter value or key supplied by the user (`adcs-sim` exits with status 2).
struct ParamError : std::runtime_error {
  using runtime_error::runtime_error;
};

enum class ParamKind { number, vector, matrix, name };

//! What a --set value text parsed to, before it is checked against a declaration.
struct ParsedValue {
  enum class Shape { number, vector, matrix, name };
  Shape shape = Shape::number;
  double number = 0.0;
  std::vector<double> vector;
  std::vector<std::vector<double>> matrix;
  std::string name;
};

//! Parses a value text; throws ParamError (malformed, empty element, ragged matrix, nan/inf,
//! trailing garbage, ...). The message does not name the key.
ParsedValue parse_value(const std::string& text);

//! A value of any kind (only the member for the parameter's kind is meaningful).
struct ParamValue {
  double number = 0.0;
  std::vector<double> vector;
  std::vector<std::vector<double>> matrix;
  std::string name;
};

//! One declared parameter with its current value.
struct Param {
  std::string key;
  ParamKind kind = ParamKind::number;
  std::string unit;    // "" for names
  std::string source;  // where the default comes from ("seed 002 Table 1", "assumed: ...")
  ParamValue value;          // current value
  ParamValue default_value;  // as declared
  // Declared shape / constraints.
  int size = -1;  // vector: required length, -1 for any
  int rows = 0;   // matrix shape
  int cols = 0;
  std::vector<std::string> allowed;  // name: allowed values (empty = any identifier)
  bool overridden = false;  // set from the command line
};

//! Formats a value like a --set value ("0.5", "[1, 2]", "[[1, 0], [0, 1]]", "adams");
//! numbers with the shortest of %.15g/%.17g that round-trips.
std::string format_value(ParamKind kind, const ParamValue& v);
inline std::string format_value(const Param& p) { return format_value(p.kind, p.value); }
std::string format_number(double x);
//! "a number", "a vector of 3 numbers", "a 3x3 matrix", "one of: adams, bdf", ...
std::string describe_kind(const Param& p);

//! Declared parameters of one scenario, kept in declaration order.
//! Declaration mistakes (duplicate key, ragged default, default name not allowed, non-finite
//! default, bad key characters) are programming errors: std::logic_error.
//! Reading an undeclared key or with the wrong kind: std::logic_error.
//! User input errors (set(), a get_vec/get_mat size mismatch on a vector_any value): ParamError.
class ParamSet {
 public:
  void number(const std::string& key, double def, std::string unit, std::string source);
  //! Fixed length def.size().
  void vector(const std::string& key, std::vector<double> def, std::string unit,
              std::string source);
  //! Any length (including empty).
  void vector_any(const std::string& key, std::vector<double> def, std::string unit,
                  std::string source);
  //! Shape fixed by def (rectangular, at least 1x1).
  void matrix(const std::string& key, std::vector<std::vector<double>> def, std::string unit,
              std::string source);
  //! A bare identifier; if `allowed` is non-empty the value must be one of them.
  void name(const std::string& key, std::string def, std::vector<std::string> allowed,
            std::string source);

  double get_number(const std::string& key) const;
  std::vector<double> get_vector(const std::string& key) const;
  std::vector<std::vector<double>> get_matrix(const std::string& key) const;
  std::string get_name(const std::string& key) const;

  template <int N>
  Eigen::Matrix<double, N, 1> get_vec(const std::string& key) const {
    const std::vector<double> v = get_vector(key);
    Eigen::Matrix<double, N, 1> out;
    if constexpr (N == Eigen::Dynamic) {
      out.resize(static_cast<Eigen::Index>(v.size()));
    } else {
      if (v.size() != static_cast<std::size_t>(N)) size_mismatch(key, std::to_string(N), v.size());
    }
    for (std::size_t i = 0; i < v.size(); ++i) out(static_cast<Eigen::Index>(i)) = v[i];
    return out;
  }

  template <int R, int C>
  Eigen::Matrix<double, R, C> get_mat(const std::string& key) const {
    static_assert(R > 0 && C > 0, "get_mat needs a fixed shape");
    const std::vector<std::vector<double>> m = get_matrix(key);
    if (m.size() != static_cast<std::size_t>(R) || m.front().size() != static_cast<std::size_t>(C))
      shape_mismatch(key, R, C, m.size(), m.front().size());
    Eigen::Matrix<double, R, C> out;
    for (int i = 0; i < R; ++i)
      for (int j = 0; j < C; ++j)
        out(i, j) = m[static_cast<std::size_t>(i)][static_cast<std::size_t>(j)];
    return out;
  }

  //! Parses `text` and assigns it to `key`; throws ParamError naming the key on an unknown key,
  //! malformed text, or a value of the wrong kind or shape. Marks the parameter overridden.
  void set(const std::string& key, const std::string& text);
  bool has(const std::string& key) const;

  //! Declaration order.
  const std::vector<Param>& params() const noexcept { return params_; }
  std::vector<Param>::const_iterator begin() const noexcept { return params_.begin(); }
  std::vector<Param>::const_iterator end() const noexcept { return params_.end(); }
  std::size_t size() const noexcept { return params_.size(); }
  //! The declared parameter (std::logic_error if undeclared).
  const Param& at(const std::string& key) const;
  //! Declared keys closest to `key` (for "did you mean" hints), best first, at most 3.
  std::vector<std::string> suggestions(const std::string& key) const;

 private:
  Param& declare(const std::string& key, ParamKind kind);
  const Param& checked(const std::string& key, ParamKind kind) const;
  [[noreturn]] static void size_mismatch(const std::string& key, const std::string& want,
                                         std::size_t got);
  [[noreturn]] static void shape_mismatch(const std::string& key, int r, int c, std::size_t gr,
                                          std::size_t gc);
  std::vector<Param> params_;
  std::map<std::string, std::size_t> index_;
};

//! Declares `scalar` (double | float, issue 19): the scalar the flight components of a scenario
//! run in; the plant stays double under CVODE. Scenarios whose parameters are a bound struct
//! (param_binding.hpp) declare the same name with kScalarHelp.
void declare_scalar(ParamSet& p);
inline constexpr const char* kScalarHelp =
    "scalar of the flight components (law, steering, allocation); the plant integrates in double";

}  // namespace adcs::sim
