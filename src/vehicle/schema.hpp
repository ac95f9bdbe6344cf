#pragma once
// The vehicle-file schema (issue 18): every table and key a vehicle file may hold, with its shape,
// unit and whether it is required or what its default is. The loader (vehicle_file.cpp) refuses
// any key or table not listed here, so a typo is never silently ignored; docs/VEHICLE-FILES.md
// documents the same list (a test checks that every key below is in it).
//
// Parameter names: a key `k` of table `t` is the declared parameter `t.k` (e.g. spacecraft.J_kgm2),
// except the keys of [run], which keep the names every scenario declares (duration_s,
// control_period_s, integrator, ...: scenarios/scenario.hpp and adcs-sim's run checks rely on them).
#include <string>
#include <string_view>
#include <vector>

namespace adcs::sim::vehicle {

//! The shape of a value. Actuator-sized shapes take their size from the file: N = rows of
//! wheels.axes_B, M = rows of cmgs.gimbal_axes_B.
enum class Shape {
  text,        //!< a string (name, description; not a parameter)
  number,      //!< a finite number
  vec3,        //!< 3 numbers
  vec2,        //!< 2 numbers (a [t0, t1] window)
  vec_wheels,  //!< N numbers, one per wheel
  vec_cmgs,    //!< M numbers, one per CMG
  mat33,       //!< 3 x 3 matrix (rows of 3)
  mat_wheels,  //!< N x 3 matrix, one row per wheel
  mat_cmgs,    //!< M x 3 matrix, one row per CMG
  name,        //!< one of `allowed` (a string in the file)
  flag,        //!< true / false (declared as the name "true" / "false")
};

enum class Presence {
  required,   //!< the file must give it (when its table is present)
  defaulted,  //!< a documented default is declared when absent
  optional,   //!< absent: no parameter (a requirement that is not checked)
};

struct KeySpec {
  std::string_view table;  //!< "" for the top level, "run", "sensors.gyro", ...
  std::string_view key;
  Shape shape;
  std::string_view unit;   //!< "" for text, names and flags
  Presence presence;
  double default_value;              //!< defaulted numbers; the fill value of a defaulted vector
  std::string_view default_name;     //!< defaulted names and flags
  std::string_view default_from;     //!< defaulted to the value of this parameter (knowledge = truth)
  std::vector<std::string_view> allowed;  //!< names: the allowed values
  std::string_view only_for;         //!< controller keys: the controller.type they belong to
  std::string_view doc;              //!< what the default is, in one line (for the parameter source)
};

struct TableSpec {
  std::string_view path;  //!< dotted, e.g. "sensors.gyro"
  bool required;
  bool array;             //!< an array of tables ([[reference.slews]])
};

//! Every key, in declaration order (the order of `adcs-sim describe`).
const std::vector<KeySpec>& key_specs();
//! Every table; a table not listed (or a table where a value is expected) is refused.
const std::vector<TableSpec>& table_specs();

//! The key's spec, or nullptr.
const KeySpec* find_key(std::string_view table, std::string_view key);
//! The table's spec, or nullptr.
const TableSpec* find_table(std::string_view path);

//! The declared parameter name of a key (see the header comment).
std::string param_name(const KeySpec& k);
std::string param_name(std::string_view table, std::string_view key);

}  // namespace adcs::sim::vehicle
