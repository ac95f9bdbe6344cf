// The wheels-only loop with 4 wheels (one instantiation per file: the cores build them in parallel).
#include "vehicle/rw_loop.hpp"

namespace adcs::sim::vehicle {
template RunResult run_rw_loop<4>(const VehicleConfig&, const RunContext&);
}  // namespace adcs::sim::vehicle
