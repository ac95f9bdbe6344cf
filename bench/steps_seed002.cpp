// Step benchmarks of seed 002's Euler-angle tracking laws,
// compiled once for adcs-bench (the benchmarks) and adcs-stepcount (the counted runs).
#include "step_fixtures_seed002.hpp"
#include "step_benchmark.hpp"

namespace adcs::bench {
ADCS_STEP_BENCHMARK(FlexiblePPC);  // seed 002 PPATC
ADCS_STEP_BENCHMARK(AdaptiveTracking);  // seed 002 ATC baseline

namespace ADCS_UNITY_ID {
const StepEntry kSeed002Steps[] = {
    ADCS_STEP_ENTRY(FlexiblePPC),
    ADCS_STEP_ENTRY(AdaptiveTracking),
};
}  // namespace

using namespace ADCS_UNITY_ID;  // as an anonymous namespace would (CMakeLists.txt, adcs_unity)
StepTable seed002_steps() noexcept { return step_table(kSeed002Steps); }
}  // namespace adcs::bench
