// Core of the target size baseline (tools/target-costs.py): the replay driver, start-up and
// libraries of every replay program with an empty System, so that
//   controller bytes = replay ELF - baseline ELF - recorded input rows
// isolates what a controller adds (its code, libm functions, constants and state).
#include "replay_runtime.hpp"

namespace replay {
class EmptySystem {
 public:
  static constexpr const char* kName = "baseline";
  static constexpr int kInputWidth = 1, kCommandSize = 0, kParts = 1;
  static constexpr double kPeriod = 1.0;
  static constexpr Column kColumns[] = {{"status", 0.0}};
  adcs::Status init_status() const noexcept { return adcs::Status::ok; }
  void step(const double*) noexcept {}
  void step_part(int, const double*) noexcept {}
  void outputs(double* v) const noexcept { v[0] = 0.0; }
  void command(double*) const noexcept {}
};
}  // namespace replay

namespace {
replay::EmptySystem g_system;
}

const replay::Api replay::kBaseline = replay::ApiOf<replay::EmptySystem, &g_system>::make();
