// adcs-stepcount's command line over the step fixtures of bench/steps_*.cpp, and the process's
// allocation counter. Every step is compiled once, in its seed's translation unit
// (bench/steps_attitude.cpp, _seed002, _seed003, _seed004), which adcs-bench and adcs-stepcount
// both link (object library adcs_step_entries): each executable used to compile all fifteen
// fixtures in one translation unit of its own (~270 g++ CPU-seconds apiece, the longest job of
// the Release build). The step code and its inlining into both loops (bench/step_benchmark.hpp)
// are unchanged.
#include <cstdio>
#include <cstdlib>
#include <cstring>

#include "counting_new.hpp"  // tests/nomalloc: counts every operator new (allocs_per_step)
#include "step_benchmark.hpp"
#include "step_entries.hpp"

namespace adcs::bench {
int run_step_count(int argc, char** argv) {
  // In the order of the fixtures' headers: seed 004 before seed 003, as adcs-stepcount always listed them.
  const StepTable tables[] = {attitude_steps(), seed002_steps(), seed004_steps(), seed003_steps(), component_steps()};
  if (argc >= 2 && std::strcmp(argv[1], "--list") == 0) {
    for (const StepTable& t : tables)
      for (int i = 0; i < t.size; ++i) std::printf("%s\n", t.entries[i].name);
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
  for (const StepTable& t : tables)
    for (int i = 0; i < t.size; ++i)
      if (std::strcmp(t.entries[i].name, argv[1]) == 0) return t.entries[i].fn(steps);
  std::fprintf(stderr, "adcs-stepcount: unknown step '%s' (see --list)\n", argv[1]);
  return 2;
}
}  // namespace adcs::bench
