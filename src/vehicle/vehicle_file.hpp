#pragma once
// A vehicle file read into declared parameters (issue 18; schema in vehicle/schema.hpp, keys and
// units in docs/VEHICLE-FILES.md). Only the syntax and the schema are checked here: TOML syntax,
// unknown tables and keys, types and shapes, required keys, the actuator counts. What the values
// mean (unit axes, positive inertias, a star-tracker rate dividing the control rate, ...) is
// checked by read_config() (vehicle/config.hpp) on the declared parameters, so a value set on the
// command line is checked the same way. Errors: ParamError "FILE:LINE: ..." ("FILE: ..." when no
// line applies).
#include <map>
#include <string>
#include <vector>

#include "scenarios/params.hpp"

namespace adcs::sim::vehicle {

//! One parameter the file declares (its value, or its documented default).
struct Declared {
  std::string key;                   //!< dotted path, e.g. "spacecraft.J_kgm2"
  ParamKind kind = ParamKind::number;
  ParamValue value;
  std::string unit;
  std::string source;                //!< "FILE:LINE" of the value, or "FILE: default ..."
  std::vector<std::string> allowed;  //!< names: the allowed values
};

//! What the file's structure fixes for a run (not overridable by --set: template sizes and the
//! choice of law and sensors).
struct Layout {
  int wheels = 0;                  //!< N, rows of wheels.axes_B
  int cmgs = 0;                    //!< M, rows of cmgs.gimbal_axes_B
  std::string controller;          //!< "mrp_pd" or "ppc"
  std::string actuation;           //!< "rw_allocation" or "vscmg_steering"
  bool gyro = false, star_tracker = false;
  bool harmonic = false, gravity_gradient = false;
  int slews = 0;                   //!< [[reference.slews]] entries
  bool pointing_requirement = false, settle_requirement = false;
};

struct VehicleFile {
  std::string path, name, description;
  Layout layout;
  std::vector<Declared> params;                //!< declaration order
  std::map<std::string, std::string> where;    //!< parameter -> "FILE:LINE" (or "FILE") for messages
  std::string actuator_where;                  //!< where the actuator set is given (count errors)
};

//! Reads and checks the file's structure; throws ParamError "FILE:LINE: ..." (see above).
VehicleFile parse_vehicle_file(const std::string& path);

//! "FILE:LINE: " + message (the one-line error of the loader).
[[noreturn]] void fail_at(const std::string& where, const std::string& message);

}  // namespace adcs::sim::vehicle
