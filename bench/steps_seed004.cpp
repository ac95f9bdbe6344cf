// Step benchmarks of seed 004's filters and laws (one 0.1 s sample),
// compiled once for adcs-bench (the benchmarks) and adcs-stepcount (the counted runs).
#include "step_fixtures_seed004.hpp"
#include "step_benchmark.hpp"

namespace adcs::bench {
ADCS_STEP_BENCHMARK(DragFreeEskf);  // seed 004 Algorithm 1 (U-D factors)
ADCS_STEP_BENCHMARK(DragFreeEskfJoseph);  // the same in the Joseph form (the reference, issue 20)
ADCS_STEP_BENCHMARK(SaturatedEsf);  // seed 004 Algorithm 2, one axis
ADCS_STEP_BENCHMARK(Fusion);  // seed 004 Algorithm 3, one axis
ADCS_STEP_BENCHMARK(Adrc);  // seed 004 ADRC law alone
ADCS_STEP_BENCHMARK(Pid);  // seed 004 PID baseline
ADCS_STEP_BENCHMARK(DragFreeAdrc);  // seed 004 whole sample: Algorithms 1-3 + ADRC

namespace ADCS_UNITY_ID {
const StepEntry kSeed004Steps[] = {
    ADCS_STEP_ENTRY(DragFreeEskf),
    ADCS_STEP_ENTRY(DragFreeEskfJoseph),
    ADCS_STEP_ENTRY(SaturatedEsf),
    ADCS_STEP_ENTRY(Fusion),
    ADCS_STEP_ENTRY(Adrc),
    ADCS_STEP_ENTRY(Pid),
    ADCS_STEP_ENTRY(DragFreeAdrc),
};
}  // namespace

using namespace ADCS_UNITY_ID;  // as an anonymous namespace would (CMakeLists.txt, adcs_unity)
StepTable seed004_steps() noexcept { return step_table(kSeed004Steps); }
}  // namespace adcs::bench
