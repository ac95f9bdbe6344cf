#pragma once
// adcs-stepcount's entry point (bench/step_entries.cpp) over the step fixtures that bench/steps_*.cpp
// compile once for adcs-bench and adcs-stepcount.

namespace adcs::bench {
//! adcs-stepcount's command line: NAME [STEPS] runs STEPS counted steps of fixture NAME (after
//! 100 uncounted warm-up steps); --list prints the names. Returns the process exit status.
int run_step_count(int argc, char** argv);
}  // namespace adcs::bench
