// adcs-stepcount: runs one step fixture (bench/step_fixtures.hpp) under valgrind's callgrind so
// tools/callgrind-counts.sh can read a deterministic instruction count per step:
//   valgrind --tool=callgrind --toggle-collect=adcs_counted_steps adcs-stepcount NAME [STEPS]
// Collection is on only inside adcs_counted_steps (never inlined), so construction, warm-up and
// process start-up are not counted; instructions per step = Ir / STEPS.
//   adcs-stepcount --list   prints the fixture names.
#include <cstdio>
#include <cstdlib>
#include <cstring>

#include "step_fixtures.hpp"

namespace {

template <class Fixture>
__attribute__((noinline)) void adcs_counted_steps(Fixture& f, long steps) {
  for (long k = 0; k < steps; ++k) f();
}

template <class Fixture>
int run(long steps) {
  Fixture f;
  for (int k = 0; k < 100; ++k) f();  // warm-up: the same branches as in the counted steps
  adcs_counted_steps(f, steps);
  return 0;
}

struct Entry {
  const char* name;
  int (*fn)(long);
};
#define ADCS_STEP_ENTRY(N) Entry{#N, &run<adcs::bench::N##Step>}
constexpr Entry kEntries[] = {
    ADCS_STEP_ENTRY(MrpPd),          ADCS_STEP_ENTRY(RwAllocation),       ADCS_STEP_ENTRY(HybridAdaptive),
    ADCS_STEP_ENTRY(HybridAdaptiveNormalized), ADCS_STEP_ENTRY(FlexiblePPC), ADCS_STEP_ENTRY(AdaptiveTracking),
    ADCS_STEP_ENTRY(DragFreeEskf),   ADCS_STEP_ENTRY(SaturatedEsf),       ADCS_STEP_ENTRY(Fusion),
    ADCS_STEP_ENTRY(Adrc),           ADCS_STEP_ENTRY(Pid),                ADCS_STEP_ENTRY(DragFreeAdrc),
    ADCS_STEP_ENTRY(SE3PrescribedTime), ADCS_STEP_ENTRY(SE3Ftsmc),        ADCS_STEP_ENTRY(CompositeQuantizer),
};

}  // namespace

int main(int argc, char** argv) {
  if (argc >= 2 && std::strcmp(argv[1], "--list") == 0) {
    for (const Entry& e : kEntries) std::printf("%s\n", e.name);
    return 0;
  }
  if (argc < 2 || argc > 3) {
    std::fprintf(stderr, "usage: adcs-stepcount NAME [STEPS] | --list\n");
    return 2;
  }
  const long steps = argc == 3 ? std::strtol(argv[2], nullptr, 10) : 1000;
  if (steps <= 0) {
    std::fprintf(stderr, "adcs-stepcount: STEPS must be > 0\n");
    return 2;
  }
  for (const Entry& e : kEntries)
    if (std::strcmp(e.name, argv[1]) == 0) return e.fn(steps);
  std::fprintf(stderr, "adcs-stepcount: unknown step '%s' (see --list)\n", argv[1]);
  return 2;
}
