#include "vehicle/vehicle_scenario.hpp"

#include <utility>

#include "vehicle/config.hpp"
#include "vehicle/loops.hpp"
#include "vehicle/vehicle_file.hpp"

namespace adcs::sim::vehicle {
namespace ADCS_UNITY_ID {

class VehicleScenario final : public Scenario {
 public:
  explicit VehicleScenario(VehicleFile f) : f_(std::move(f)) {}
  std::string name() const override { return f_.name; }
  std::string description() const override { return f_.description; }

  void declare(ParamSet& p) const override {
    for (const Declared& d : f_.params) {
      switch (d.kind) {
        case ParamKind::number: p.number(d.key, d.value.number, d.unit, d.source); break;
        case ParamKind::vector: p.vector(d.key, d.value.vector, d.unit, d.source); break;
        case ParamKind::matrix: p.matrix(d.key, d.value.matrix, d.unit, d.source); break;
        case ParamKind::name: p.name(d.key, d.value.name, d.allowed, d.source); break;
      }
    }
  }

  RunResult run(const ParamSet& p, const RunContext& ctx) const override {
    return run_vehicle_loop(read_config(f_, p), ctx);
  }

  const VehicleFile& file() const noexcept { return f_; }

 private:
  VehicleFile f_;
};

}  // namespace
using namespace ADCS_UNITY_ID;  // as an anonymous namespace would (CMakeLists.txt, adcs_unity)

std::unique_ptr<Scenario> load_vehicle_file(const std::string& path) {
  auto s = std::make_unique<VehicleScenario>(parse_vehicle_file(path));
  // The values' meaning is checked now, so a bad file fails on load with its FILE:LINE (a value
  // set later on the command line is checked again by run()).
  ParamSet p;
  s->declare(p);
  (void)read_config(s->file(), p);
  return s;
}

}  // namespace adcs::sim::vehicle
