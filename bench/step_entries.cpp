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
namespace {
const StepEntry* find_entry(const StepTable* tables, int n_tables, const char* name) noexcept {
  for (int j = 0; j < n_tables; ++j)
    for (int i = 0; i < tables[j].size; ++i)
      if (std::strcmp(tables[j].entries[i].name, name) == 0) return &tables[j].entries[i];
  return nullptr;
}

long parse_steps(const char* text) noexcept {
  const long steps = std::strtol(text, nullptr, 10);
  if (steps <= 0) std::fprintf(stderr, "adcs-stepcount: STEPS must be > 0\n");
  return steps;
}
}  // namespace

int run_step_count(int argc, char** argv) {
  // In the order of the fixtures' headers: seed 004 before seed 003, as adcs-stepcount always listed them.
  const StepTable tables[] = {attitude_steps(), seed002_steps(), seed004_steps(), seed003_steps(), component_steps()};
  const int n_tables = static_cast<int>(sizeof tables / sizeof tables[0]);
  if (argc >= 2 && std::strcmp(argv[1], "--list") == 0) {
    for (const StepTable& t : tables)
      for (int i = 0; i < t.size; ++i) std::printf("%s\n", t.entries[i].name);
    return 0;
  }
  // --each STEPS NAME...: every named fixture in turn, each freshly constructed, in one process
  // (tools/callgrind-counts.py: one valgrind start-up for all of them instead of one per fixture;
  // callgrind dumps after each counted region). Names are checked before anything runs.
  if (argc >= 2 && std::strcmp(argv[1], "--each") == 0) {
    if (argc < 4) {
      std::fprintf(stderr, "usage: adcs-stepcount --each STEPS NAME...\n");
      return 2;
    }
    const long steps = parse_steps(argv[2]);
    if (steps <= 0) return 2;
    for (int a = 3; a < argc; ++a)
      if (find_entry(tables, n_tables, argv[a]) == nullptr) {
        std::fprintf(stderr, "adcs-stepcount: unknown step '%s' (see --list)\n", argv[a]);
        return 2;
      }
    for (int a = 3; a < argc; ++a) find_entry(tables, n_tables, argv[a])->fn(steps);
    return 0;
  }
  if (argc < 2 || argc > 3) {
    std::fprintf(stderr, "usage: adcs-stepcount NAME [STEPS] | --each STEPS NAME... | --list\n");
    return 2;
  }
  const long steps = argc == 3 ? parse_steps(argv[2]) : 1000;
  if (steps <= 0) return 2;
  if (const StepEntry* e = find_entry(tables, n_tables, argv[1])) return e->fn(steps);
  std::fprintf(stderr, "adcs-stepcount: unknown step '%s' (see --list)\n", argv[1]);
  return 2;
}
}  // namespace adcs::bench
