#include "vehicle/loops.hpp"

#include <string>

namespace adcs::sim::vehicle {

RunResult run_vehicle_loop(const VehicleConfig& c, const RunContext& ctx) {
  const int m = c.cmgs.count, n = c.wheels.count;
  if (m == 0) {
    switch (n) {
      case 3: return run_rw_loop<3>(c, ctx);
      case 4: return run_rw_loop<4>(c, ctx);
      case 5: return run_rw_loop<5>(c, ctx);
      case 6: return run_rw_loop<6>(c, ctx);
      default: break;
    }
  } else if (n == 0) {
    switch (m) {
      case 3: return run_cmg_loop<3, 0>(c, ctx);
      case 4: return run_cmg_loop<4, 0>(c, ctx);
      case 5: return run_cmg_loop<5, 0>(c, ctx);
      case 6: return run_cmg_loop<6, 0>(c, ctx);
      default: break;
    }
  } else if (m == 4 && n == 3) {
    return run_cmg_loop<4, 3>(c, ctx);
  }
  // The loader refuses these; reaching here is a programming error.
  throw ParamError(std::to_string(m) + " CMGs and " + std::to_string(n) +
                   " wheels: unsupported actuator set (supported: " + kSupportedActuators + ")");
}

}  // namespace adcs::sim::vehicle
