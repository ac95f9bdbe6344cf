// The CMG loop with 4 CMGs and 3 wheels (seed 001's hybrid cluster layout).
#include "vehicle/cmg_loop.hpp"

namespace adcs::sim::vehicle {
template RunResult run_cmg_loop<4, 3>(const VehicleConfig&, const RunContext&);
}  // namespace adcs::sim::vehicle
