// The CMG loop with 3 CMGs and no wheels (one instantiation per file: the cores build them in parallel).
#include "vehicle/cmg_loop.hpp"

namespace adcs::sim::vehicle {
template RunResult run_cmg_loop<3, 0>(const VehicleConfig&, const RunContext&);
}  // namespace adcs::sim::vehicle
