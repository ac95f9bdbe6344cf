#pragma once
// A vehicle file as a Scenario (issue 18): `adcs-sim run FILE`, `describe FILE` and Monte Carlo
// campaigns over it work like on a registered scenario. The file's values are the declared
// parameters, named by their dotted path (spacecraft.J_kgm2, wheels.axes_B, ...; the [run] keys
// keep the names every scenario declares: duration_s, control_period_s, ...), each with the
// "FILE:LINE" it came from as its source. Schema: docs/VEHICLE-FILES.md.
#include <memory>
#include <string>

#include "scenarios/scenario.hpp"

namespace adcs::sim::vehicle {

//! Loads a vehicle file; throws ParamError whose message is one line starting "FILE:LINE: " (or
//! "FILE: " when no line applies) for a malformed file, an unknown key, a wrong type or shape, or
//! an unsupported actuator count.
std::unique_ptr<Scenario> load_vehicle_file(const std::string& path);

}  // namespace adcs::sim::vehicle
