#pragma once
// The closed loops a vehicle file can fly, one per supported actuator set. Actuator counts are
// template sizes (fixed-size flight code), so each set is an explicit instantiation in a .cpp of
// its own (rw_loop_N.cpp, cmg_loop_M[_N].cpp: the cores compile them in parallel); a file with
// another set is refused when it is loaded (docs/VEHICLE-FILES.md, "Supported actuator sets").
#include "scenarios/scenario.hpp"
#include "vehicle/config.hpp"

namespace adcs::sim::vehicle {

//! The supported sets, as the loader's error message lists them.
inline constexpr const char* kSupportedActuators = "3, 4, 5 or 6 wheels; 3, 4, 5 or 6 CMGs; 4 CMGs + 3 wheels";

//! True when the set of `cmgs` CMGs and `wheels` wheels has a loop.
constexpr bool supported_actuators(int cmgs, int wheels) noexcept {
  if (cmgs == 0) return wheels >= 3 && wheels <= 6;
  if (wheels == 0) return cmgs >= 3 && cmgs <= 6;
  return cmgs == 4 && wheels == 3;
}

//! Wheels only, rw_allocation (vehicle/rw_loop.hpp).
template <int N>
RunResult run_rw_loop(const VehicleConfig& c, const RunContext& ctx);

//! M CMGs (with N wheels), vscmg_steering (vehicle/cmg_loop.hpp).
template <int M, int N>
RunResult run_cmg_loop(const VehicleConfig& c, const RunContext& ctx);

//! The loop of c's actuator set (vehicle/loops.cpp).
RunResult run_vehicle_loop(const VehicleConfig& c, const RunContext& ctx);

}  // namespace adcs::sim::vehicle
