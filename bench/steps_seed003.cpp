// Step benchmarks of seed 003's SE(3) laws and quantizer,
// compiled once for adcs-bench (the benchmarks) and adcs-stepcount (the counted runs).
#include "step_fixtures_seed003.hpp"
#include "step_benchmark.hpp"

namespace adcs::bench {
ADCS_STEP_BENCHMARK(SE3PrescribedTime);  // seed 003 BsPdTC
ADCS_STEP_BENCHMARK(SE3Ftsmc);  // seed 003 FTSMC baseline
ADCS_STEP_BENCHMARK(CompositeQuantizer);  // seed 003 sat + quantizer, 6 channels

namespace ADCS_UNITY_ID {
const StepEntry kSeed003Steps[] = {
    ADCS_STEP_ENTRY(SE3PrescribedTime),
    ADCS_STEP_ENTRY(SE3Ftsmc),
    ADCS_STEP_ENTRY(CompositeQuantizer),
};
}  // namespace

using namespace ADCS_UNITY_ID;  // as an anonymous namespace would (CMakeLists.txt, adcs_unity)
StepTable seed003_steps() noexcept { return step_table(kSeed003Steps); }
}  // namespace adcs::bench
