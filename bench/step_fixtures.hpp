#pragma once
// One fixture per controller/estimator step measured by adcs-bench (Google Benchmark, wall time)
// and by adcs-stepcount (valgrind callgrind, instructions): the constructor builds the object
// once, operator() runs exactly one step with inputs that move every call, so nothing is
// constant-folded and both tools time the same code. Fixtures own no heap memory in operator().
// One header per seed, so that each translation unit that compiles fixtures (bench/steps_*.cpp)
// pays only for its own seed's templates; this one includes them all (the nomalloc test).
#include "step_fixtures_attitude.hpp"
#include "step_fixtures_seed002.hpp"
#include "step_fixtures_seed003.hpp"
#include "step_fixtures_seed004.hpp"
