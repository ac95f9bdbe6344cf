// Step benchmarks and counted runs of every flight component, generated from the one list of
// components (tests/components/component_list.hpp): BM_Component_<name>_Step in adcs-bench and
// Component<name> in adcs-stepcount (callgrind instruction counts). A component added to the list
// is benchmarked and counted with no code here. Each fixture cycles through 64 inputs of its
// ComponentFixture (so the branches are the list's, not one repeated sample). The per-seed
// fixtures (steps_*.cpp) stay: they time whole paper samples (reference, desired state, chains).
#include <array>
#include <string>
#include <type_traits>
#include <vector>

#include "component_list.hpp"  // tests/components
#include "step_benchmark.hpp"

namespace adcs::bench {
namespace ADCS_UNITY_ID {

template <class C>
class ComponentStep {
 public:
  using Fx = test::ComponentFixture<C>;
  static constexpr int kInputs = 64;
  ComponentStep() : c_(Fx::params()) {
    for (int k = 0; k < kInputs; ++k) in_[static_cast<std::size_t>(k)] = Fx::input(k);
  }
  void operator()() {
    benchmark::DoNotOptimize(c_.step(in_[static_cast<std::size_t>(k_)], out_));
    benchmark::DoNotOptimize(&out_);
    k_ = k_ + 1 == kInputs ? 0 : k_ + 1;
  }

 private:
  C c_;
  std::array<typename C::Input, kInputs> in_{};
  typename C::Output out_{};
  int k_ = 0;
};

//! The adcs-stepcount entries (names stored here for the table's lifetime) and the benchmarks.
struct Registry {
  std::vector<std::string> names;
  std::vector<StepEntry> entries;
  Registry() {
    test::for_each_component([this](auto* type) {
      using C = std::remove_pointer_t<decltype(type)>;
      names.push_back(std::string("Component") + test::ComponentFixture<C>::name);
      benchmark::RegisterBenchmark(("BM_Component_" + std::string(test::ComponentFixture<C>::name) + "_Step").c_str(),
                                   &BM_Step<ComponentStep<C>>);
    });
    std::size_t i = 0;
    test::for_each_component([this, &i](auto* type) {
      using C = std::remove_pointer_t<decltype(type)>;
      entries.push_back(StepEntry{names[i++].c_str(), &run<ComponentStep<C>>});
    });
  }
};

const Registry& registry() {
  static const Registry r;
  return r;
}
// Benchmarks must be registered before benchmark::Initialize: at static initialisation.
[[maybe_unused]] const bool kRegistered = (registry(), true);

}  // namespace
using namespace ADCS_UNITY_ID;  // as an anonymous namespace would (CMakeLists.txt, adcs_unity)

StepTable component_steps() noexcept {
  const Registry& r = registry();
  return StepTable{r.entries.data(), static_cast<int>(r.entries.size())};
}

}  // namespace adcs::bench
