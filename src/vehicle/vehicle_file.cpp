// Reading a vehicle file with toml++ (the only file that sees the TOML tree): the tree is walked
// against the schema (vehicle/schema.hpp), every value converted to a declared parameter with the
// "FILE:LINE" it came from. No value is interpreted here beyond its shape (vehicle/config.cpp).
#include "vehicle/vehicle_file.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>

#include <toml++/toml.h>

#include "vehicle/loops.hpp"
#include "vehicle/schema.hpp"

namespace adcs::sim::vehicle {

void fail_at(const std::string& where, const std::string& message) { throw ParamError(where + ": " + message); }

namespace ADCS_UNITY_ID {

//! A value found in the file: its node and where.
struct Found {
  const toml::node* node = nullptr;
  std::string where;  //!< "FILE:LINE"
};

std::string plural(int n, const char* one, const char* many) {
  return std::to_string(n) + " " + (n == 1 ? one : many);
}

std::string describe(Shape s, const Layout& l) {
  switch (s) {
    case Shape::text: return "a string";
    case Shape::number: return "a number";
    case Shape::vec3: return "a vector of 3 numbers";
    case Shape::vec2: return "a vector of 2 numbers [t0, t1]";
    case Shape::vec_wheels: return "a vector of " + plural(l.wheels, "number", "numbers") + " (one per wheel)";
    case Shape::vec_cmgs: return "a vector of " + plural(l.cmgs, "number", "numbers") + " (one per CMG)";
    case Shape::mat33: return "a 3x3 matrix [[a, b, c], [d, e, f], [g, h, i]]";
    case Shape::mat_wheels: return "a " + std::to_string(l.wheels) + "x3 matrix (one row per wheel)";
    case Shape::mat_cmgs: return "a " + std::to_string(l.cmgs) + "x3 matrix (one row per CMG)";
    case Shape::name: return "a string";
    case Shape::flag: return "true or false";
  }
  return "?";
}

const char* toml_type(const toml::node& n) {
  switch (n.type()) {
    case toml::node_type::table: return "a table";
    case toml::node_type::array: return "an array";
    case toml::node_type::string: return "a string";
    case toml::node_type::integer: return "an integer";
    case toml::node_type::floating_point: return "a float";
    case toml::node_type::boolean: return "a boolean";
    case toml::node_type::date: return "a date";
    case toml::node_type::time: return "a time";
    case toml::node_type::date_time: return "a date-time";
    case toml::node_type::none: break;
  }
  return "nothing";
}

class Reader {
 public:
  explicit Reader(std::string path) : path_(std::move(path)) {}

  VehicleFile read() {
    const toml::table root = parse();
    walk(root, "");
    VehicleFile f;
    f.path = path_;
    for (const TableSpec& t : table_specs())
      if (t.required && !t.path.empty() && !tables_.count(std::string(t.path)))
        fail_at(path_, "missing table [" + std::string(t.path) + "] (required; see docs/VEHICLE-FILES.md)");
    layout(f);
    for (const KeySpec& k : key_specs()) declare(k, f);
    return f;
  }

 private:
  toml::table parse() {
    std::ifstream in(path_, std::ios::binary);
    if (!in) fail_at(path_, "cannot open the vehicle file for reading");
    std::ostringstream text;
    text << in.rdbuf();
    try {
      return toml::parse(text.str(), path_);
    } catch (const toml::parse_error& e) {
      fail_at(at(e.source().begin.line), "malformed TOML: " + std::string(e.description()));
    }
  }

  std::string at(toml::source_index line) const {
    return line > 0 ? path_ + ":" + std::to_string(line) : path_;
  }
  std::string at(const toml::node& n) const { return at(n.source().begin.line); }

  //! Checks every table and key against the schema and records where each value is.
  void walk(const toml::table& t, const std::string& table) {
    tables_[table] = at(t);
    for (auto&& [key, node] : t) {
      const std::string k(key.str());
      const std::string child = table.empty() ? k : table + "." + k;
      const std::string where = at(key.source().begin.line);
      const TableSpec* ts = find_table(child);
      if (ts && !ts->array) {
        if (!node.is_table()) fail_at(where, "'" + child + "' must be a table [" + child + "], got " + toml_type(node));
        walk(*node.as_table(), child);
        continue;
      }
      if (ts && ts->array) {
        const toml::array* a = node.as_array();
        if (!a || !a->is_array_of_tables())
          fail_at(where, "'" + child + "' must be an array of tables [[" + child + "]], got " + toml_type(node));
        int i = 0;
        for (const toml::node& e : *a) walk_element(*e.as_table(), child, ++i);
        continue;
      }
      if (!find_key(table, k)) fail_at(where, unknown(table, k, node));
      values_[param_name(table, k)] = Found{&node, at(node)};
    }
  }

  //! One [[reference.slews]] entry: its keys become reference.slews.I.KEY.
  void walk_element(const toml::table& t, const std::string& table, int index) {
    for (auto&& [key, node] : t) {
      const std::string k(key.str());
      if (!find_key(table, k) || node.is_table() || find_table(table + "." + k))
        fail_at(at(key.source().begin.line), unknown(table, k, node));
      values_[table + "." + std::to_string(index) + "." + k] = Found{&node, at(node)};
    }
    elements_[table].push_back(at(t));
  }

  //! "unknown key 'x' in [table] (known: a, b, c)".
  static std::string unknown(const std::string& table, const std::string& key, const toml::node& node) {
    std::string known;
    for (const KeySpec& s : key_specs())
      if (s.table == table) known += (known.empty() ? "" : ", ") + std::string(s.key);
    for (const TableSpec& s : table_specs()) {
      const std::string p(s.path);
      if (!p.empty() && p.rfind(table.empty() ? "" : table + ".", 0) == 0 &&
          p.find('.', table.empty() ? 0 : table.size() + 1) == std::string::npos)
        known += (known.empty() ? "[" : ", [") + p + "]";
    }
    const std::string what = node.is_table() ? "table" : "key";
    const std::string in = table.empty() ? "at the top level" : "in [" + table + "]";
    return "unknown " + what + " '" + key + "' " + in + " (known: " + (known.empty() ? "none" : known) +
           "; see docs/VEHICLE-FILES.md)";
  }

  const Found* find(const std::string& name) const {
    const auto it = values_.find(name);
    return it == values_.end() ? nullptr : &it->second;
  }

  //! Rows of an actuator matrix (checked as "rows of 3 numbers" here, fully in declare()).
  int rows(const std::string& name) const {
    const Found* f = find(name);
    if (!f) return 0;
    const toml::array* a = f->node->as_array();
    if (!a) fail_at(f->where, name + ": expected a matrix (one row [x, y, z] per actuator), got " + toml_type(*f->node));
    return static_cast<int>(a->size());
  }

  void layout(VehicleFile& f) {
    Layout& l = f.layout;
    // The actuator counts come from these two matrices: report them missing before anything else.
    for (const char* t : {"wheels", "cmgs"}) {
      const std::string key = std::string(t) == "wheels" ? "axes_B" : "gimbal_axes_B";
      if (tables_.count(t) && !find(std::string(t) + "." + key))
        fail_at(tables_[t], "[" + std::string(t) + "] is missing the required key '" + key + "'");
    }
    l.wheels = tables_.count("wheels") ? rows("wheels.axes_B") : 0;
    l.cmgs = tables_.count("cmgs") ? rows("cmgs.gimbal_axes_B") : 0;
    l.controller = text_of("controller.type", "controller");
    l.actuation = text_of("actuation.type", "actuation");
    l.gyro = tables_.count("sensors.gyro") != 0;
    l.star_tracker = tables_.count("sensors.star_tracker") != 0;
    l.harmonic = tables_.count("disturbances.harmonic") != 0;
    l.gravity_gradient = tables_.count("disturbances.gravity_gradient") != 0;
    l.slews = static_cast<int>(elements_["reference.slews"].size());
    l.pointing_requirement = find("requirements.pointing_deg") != nullptr;
    l.settle_requirement = find("requirements.settle_s") != nullptr;

    const Found* axes = l.cmgs > 0 ? find("cmgs.gimbal_axes_B") : find("wheels.axes_B");
    f.actuator_where = axes ? axes->where : path_;
    if (!supported_actuators(l.cmgs, l.wheels)) {
      std::string set = l.cmgs > 0 ? plural(l.cmgs, "CMG", "CMGs") + " and " + plural(l.wheels, "wheel", "wheels")
                                   : plural(l.wheels, "wheel", "wheels");
      std::string why = l.cmgs == 0 && l.wheels > 0 && l.wheels < 3 ? "; fewer than 3 wheels cannot give three-axis torque"
                                                                      : "";
      fail_at(f.actuator_where, set + ": unsupported actuator set (supported: " + std::string(kSupportedActuators) + why + ")");
    }
    const Found* act = find("actuation.type");
    if (l.actuation == "rw_allocation" && l.cmgs > 0)
      fail_at(act->where, "actuation.type = rw_allocation drives wheels only, the file has " +
                              plural(l.cmgs, "CMG", "CMGs") + ": use vscmg_steering");
    if (l.actuation == "vscmg_steering" && l.cmgs == 0)
      fail_at(act->where, "actuation.type = vscmg_steering needs [cmgs]; a wheels-only vehicle uses rw_allocation");
  }

  //! A required name read before the others (it decides which keys apply).
  std::string text_of(const std::string& name, const std::string& table) {
    const Found* f = find(name);
    if (!f) return {};  // reported as a missing required key by declare()
    const std::optional<std::string_view> s = f->node->value<std::string_view>();
    if (!s) fail_at(f->where, name + ": expected a string, got " + toml_type(*f->node));
    const KeySpec* k = find_key(table, "type");
    for (std::string_view a : k->allowed)
      if (a == *s) return std::string(*s);
    fail_at(f->where, name + ": '" + std::string(*s) + "' is not one of: " + join(k->allowed));
  }

  static std::string join(const std::vector<std::string_view>& v) {
    std::string s;
    for (std::string_view x : v) s += (s.empty() ? "" : ", ") + std::string(x);
    return s;
  }

  //! Whether a key of the schema applies to this file at all (its table present, its actuators).
  bool applies(const KeySpec& k, const Layout& l) const {
    if (!tables_.count(std::string(k.table)) && k.table != "reference.slews" && k.table != "knowledge")
      return false;
    if (!k.only_for.empty() && k.only_for != l.controller) return false;
    if (k.table == "knowledge") {
      if (k.shape == Shape::mat_wheels || k.shape == Shape::vec_wheels) return l.wheels > 0;
      if (k.shape == Shape::mat_cmgs || k.shape == Shape::vec_cmgs) return l.cmgs > 0;
    }
    return true;
  }

  void declare(const KeySpec& k, VehicleFile& f) {
    const Layout& l = f.layout;
    if (k.table == "reference.slews") {
      for (int i = 1; i <= l.slews; ++i)
        declare_one(k, f, "reference.slews." + std::to_string(i) + "." + std::string(k.key),
                    elements_["reference.slews"][static_cast<std::size_t>(i - 1)],
                    "[[reference.slews]] entry " + std::to_string(i));
      return;
    }
    const std::string name = param_name(k);
    const std::string table(k.table);
    if (!applies(k, l)) {
      if (const Found* v = find(name)) {
        std::string why = "does not apply to this vehicle";
        if (!k.only_for.empty()) why = "is a key of controller type " + std::string(k.only_for) + ", not " + l.controller;
        else if (k.table == "knowledge") why = "names actuators this vehicle does not have";
        fail_at(v->where, name + " " + why);
      }
      return;
    }
    declare_one(k, f, name, !table.empty() && tables_.count(table) ? tables_[table] : path_,
                table.empty() ? std::string("the top level") : "[" + table + "]");
  }

  void declare_one(const KeySpec& k, VehicleFile& f, const std::string& name, const std::string& table_where,
                   const std::string& table_label) {
    const Found* v = find(name);
    if (!v) {
      if (k.presence == Presence::required)
        fail_at(table_where, table_label + " is missing the required key '" + std::string(k.key) + "'" +
                                 (k.unit.empty() ? "" : " [" + std::string(k.unit) + "]"));
      if (k.presence == Presence::optional) return;
      declare_default(k, f, name);
      return;
    }
    if (k.shape == Shape::text) {
      const std::optional<std::string_view> s = v->node->value<std::string_view>();
      if (!s) fail_at(v->where, name + ": expected a string, got " + toml_type(*v->node));
      if (k.key == "name") {
        const bool ok = !s->empty() && std::all_of(s->begin(), s->end(), [](char c) {
          return (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '-';
        });
        if (!ok) fail_at(v->where, "name '" + std::string(*s) + "' must be lower-case letters, digits and '-' (it names the output files)");
        f.name = std::string(*s);
      } else {
        f.description = std::string(*s);
      }
      return;
    }
    Declared d;
    d.key = name;
    d.unit = std::string(k.unit);
    d.source = v->where;
    d.value = convert(k, f.layout, *v, name, d.kind, d.allowed);
    f.where[name] = v->where;
    f.params.push_back(std::move(d));
  }

  void declare_default(const KeySpec& k, VehicleFile& f, const std::string& name) {
    Declared d;
    d.key = name;
    d.unit = std::string(k.unit);
    if (!k.default_from.empty()) {  // knowledge: a copy of the truth parameter's value
      const std::string from(k.default_from);
      for (const Declared& p : f.params)
        if (p.key == from) {
          d.kind = p.kind;
          d.value = p.value;
        }
      const std::string w = f.where.count(from) ? f.where[from] : path_;
      d.source = w + ": default: " + from + " (" + std::string(k.doc) + ")";
      f.where[name] = w;
    } else if (k.shape == Shape::name || k.shape == Shape::flag) {
      d.kind = ParamKind::name;
      d.value.name = std::string(k.default_name);
      for (std::string_view a : k.allowed) d.allowed.emplace_back(a);
      d.source = path_ + ": default: " + std::string(k.default_name) + " (" + std::string(k.doc) + ")";
      f.where[name] = path_;
    } else {
      const int n = length(k.shape, f.layout);
      if (k.shape == Shape::number) {
        d.kind = ParamKind::number;
        d.value.number = k.default_value;
      } else {
        d.kind = ParamKind::vector;
        d.value.vector.assign(static_cast<std::size_t>(n), k.default_value);
      }
      d.source = path_ + ": default (" + std::string(k.doc) + ")";
      f.where[name] = path_;
    }
    f.params.push_back(std::move(d));
  }

  static int length(Shape s, const Layout& l) {
    switch (s) {
      case Shape::vec3: case Shape::mat33: case Shape::mat_wheels: case Shape::mat_cmgs: return 3;
      case Shape::vec2: return 2;
      case Shape::vec_wheels: return l.wheels;
      case Shape::vec_cmgs: return l.cmgs;
      default: return 1;
    }
  }
  static int matrix_rows(Shape s, const Layout& l) {
    return s == Shape::mat33 ? 3 : (s == Shape::mat_wheels ? l.wheels : l.cmgs);
  }

  //! A finite number, or an error naming the key and what it got.
  double number(const toml::node& n, const std::string& where, const std::string& name, const std::string& expected) const {
    if (!n.is_number()) fail_at(where, name + ": expected " + expected + ", got " + toml_type(n));
    const std::optional<double> x = n.value<double>();
    if (!x || !std::isfinite(*x)) fail_at(where, name + ": values must be finite numbers");
    return *x;
  }

  std::vector<double> numbers(const toml::node& n, int size, const std::string& where, const std::string& name,
                              const std::string& expected) const {
    const toml::array* a = n.as_array();
    if (!a || static_cast<int>(a->size()) != size)
      fail_at(where, name + ": expected " + expected + ", got " +
                         (a ? plural(static_cast<int>(a->size()), "element", "elements") : std::string(toml_type(n))));
    std::vector<double> v;
    for (const toml::node& e : *a) v.push_back(number(e, at(e), name, expected));
    return v;
  }

  ParamValue convert(const KeySpec& k, const Layout& l, const Found& f, const std::string& name, ParamKind& kind,
                     std::vector<std::string>& allowed) const {
    ParamValue v;
    const std::string expected = describe(k.shape, l);
    switch (k.shape) {
      case Shape::number:
        kind = ParamKind::number;
        v.number = number(*f.node, f.where, name, expected);
        break;
      case Shape::vec3: case Shape::vec2: case Shape::vec_wheels: case Shape::vec_cmgs:
        kind = ParamKind::vector;
        v.vector = numbers(*f.node, length(k.shape, l), f.where, name, expected);
        break;
      case Shape::mat33: case Shape::mat_wheels: case Shape::mat_cmgs: {
        kind = ParamKind::matrix;
        const toml::array* a = f.node->as_array();
        const int rows = matrix_rows(k.shape, l);
        if (!a || static_cast<int>(a->size()) != rows)
          fail_at(f.where, name + ": expected " + expected + ", got " +
                               (a ? plural(static_cast<int>(a->size()), "row", "rows") : std::string(toml_type(*f.node))));
        if (rows == 0) fail_at(f.where, name + ": expected at least one row");
        for (const toml::node& row : *a) v.matrix.push_back(numbers(row, 3, at(row), name, "rows of 3 numbers"));
        break;
      }
      case Shape::name: {
        kind = ParamKind::name;
        const std::optional<std::string_view> s = f.node->value<std::string_view>();
        if (!s) fail_at(f.where, name + ": expected a string, got " + toml_type(*f.node));
        bool ok = false;
        for (std::string_view a : k.allowed) {
          allowed.emplace_back(a);
          ok = ok || a == *s;
        }
        if (!ok) fail_at(f.where, name + ": '" + std::string(*s) + "' is not one of: " + join(k.allowed));
        v.name = std::string(*s);
        if (k.key == "type") allowed = {v.name};  // fixed by the file (it decides the template and keys)
        break;
      }
      case Shape::flag: {
        kind = ParamKind::name;
        const std::optional<bool> b = f.node->is_boolean() ? f.node->value<bool>() : std::nullopt;
        if (!b) fail_at(f.where, name + ": expected true or false, got " + toml_type(*f.node));
        v.name = *b ? "true" : "false";
        allowed = {"true", "false"};
        break;
      }
      case Shape::text: break;
    }
    return v;
  }

  std::string path_;
  std::map<std::string, std::string> tables_;                 //!< present table -> where
  std::map<std::string, Found> values_;                       //!< parameter -> value node
  std::map<std::string, std::vector<std::string>> elements_;  //!< array of tables -> where of each
};

}  // namespace

using namespace ADCS_UNITY_ID;  // as an anonymous namespace would (CMakeLists.txt, adcs_unity)

VehicleFile parse_vehicle_file(const std::string& path) { return Reader(path).read(); }

}  // namespace adcs::sim::vehicle
