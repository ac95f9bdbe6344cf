// The wheels-only loop with 3 wheels (one instantiation per file: the cores build them in parallel).
#include "vehicle/rw_loop.hpp"

namespace adcs::sim::vehicle {
template RunResult run_rw_loop<3>(const VehicleConfig&, const RunContext&);
}  // namespace adcs::sim::vehicle
