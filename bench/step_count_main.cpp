// adcs-stepcount: runs one step fixture (bench/step_fixtures.hpp) under valgrind's callgrind so
// tools/callgrind-counts.py can read a deterministic instruction count per step:
//   valgrind --tool=callgrind --toggle-collect=adcs_counted_steps adcs-stepcount NAME [STEPS]
// Collection is on only inside adcs_counted_steps (never inlined; bench/step_entries.cpp), so
// construction, warm-up and process start-up are not counted; instructions per step = Ir / STEPS.
//   adcs-stepcount --list   prints the fixture names.
//   adcs-stepcount --each STEPS NAME...   runs the named fixtures in turn in one process, each
//     freshly constructed; with --dump-after=adcs_count_region_end callgrind writes one count per
//     region (how tools/callgrind-counts.py runs them all under one valgrind start-up).
#include "step_entries.hpp"

int main(int argc, char** argv) { return adcs::bench::run_step_count(argc, argv); }
