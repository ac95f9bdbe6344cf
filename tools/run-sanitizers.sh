#!/usr/bin/env bash
# The flight and ground test groups under AddressSanitizer + LeakSanitizer +
# UndefinedBehaviorSanitizer (clang++-14), plus the libFuzzer harnesses (ADCS_FUZZ=ON: ctest label
# fuzz, tests/fuzz/CMakeLists.txt): every unit, property, harness, CLI, parameter, foundation- and
# fault-scenario, no-allocation and install-consumer test, and the papers' closed loops and their
# claims (adcs_claim_tests), with any sanitizer report fatal (halt_on_error,
# -fno-sanitize-recover=undefined); the units of fixed-size flight code (the scenario libraries,
# the vehicle loops, the flight unit tests) without ASan, see below. Called by tools/run-tests.sh after the Release suite.
#   clang++-14, not g++: the same -O1 ASan+UBSan build of the Eigen-heavy tests compiles ~3-4x
#        faster (measured per translation unit: g++ -O1 -g 138 s, clang++ -O1 -g 36 s), which is
#        what lets the suite run in CI; it also puts a second compiler's warnings (-Werror) on
#        every file.
#   -O2: the scenario tests run 10^5 controller steps each; at -O1 they were ~30x slower than
#        the Release build.
#   UBSan without its pointer checks (alignment, null, object-size, pointer-overflow, vptr,
#        function) on every test and on the fuzzers' corpus replay (ADCS_TEST_COMPILE_OPTIONS,
#        ADCS_FUZZ_NO_SANITIZE): they made the closed loops' Eigen code ~9x slower than ASan
#        alone and cost ~40 % of the unit tests' and ~half of the fuzzers' compile time. What they
#        would catch is still caught: out-of-bounds and object-size by ASan, Eigen's
#        unaligned-array and index asserts (armed: no NDEBUG), null by the segfault. The
#        arithmetic checks (overflow, float-cast, shifts, division, bounds, bool/enum,
#        return/unreachable) stay on everywhere; the standalone fuzz campaigns
#        (tools/run-fuzzers.sh) run the full UBSan.
#   -O1 for the unit tests that run loops (ADCS_FLIGHT_TEST_OPT), -O0 for the others
#        (ADCS_SHORT_RUN_OPT): they run milliseconds of flight code each. The no-allocation test
#        is -O0 in every build.
#   The units whose code under test is fixed-size flight code on the stack, without ASan, with
#        UBSan, armed asserts and -D_GLIBCXX_ASSERTIONS (ADCS_SCENARIO_COMPILE_OPTIONS through
#        adcs_fixed_size_options): the scenario libraries (src/scenarios: the closed loops of the
#        claim, fault and vehicle tests), the vehicle loops (src/vehicle/*_loop_*.cpp) and the
#        flight unit tests. ASan made the loops ~2.5x slower than the same code without
#        sanitizers and was ~20 % of the unit tests' compile time; an out-of-range index there
#        is Eigen's armed assert, a fixed array's UBSan's bounds check, a container's
#        libstdc++'s. ASan stays on every component's step() in the no-allocation and fuzz
#        tests, on the C interface (its test and example), the harness (src/sim), the ground
#        code (command line, campaigns, vehicle files) and the other tests' own code.
#   No debug info (CMAKE_CXX_FLAGS_DEBUG empty): a report names each frame's function (symbol
#        table); -gline-tables-only, which adds file:line, cost ~12 % of this tree's compile time
#        (docs/DECISIONS.md, "CI under 20 minutes"). For file:line, reconfigure with
#        -DCMAKE_CXX_FLAGS_DEBUG=-gline-tables-only. The fuzzers keep it: their reports come from
#        new inputs. Debug build type otherwise, so NDEBUG stays undefined and Eigen's own
#        asserts (bounds, sizes) are armed too.
#   Bench and the Cortex-M7 check are off: neither runs host code under test.
# Usage: tools/run-sanitizers.sh [BUILD_DIR]   (default: build-asan). Prints the wall and CPU time
# of each phase (tools/phases.sh); exits non-zero on any build error, test failure or sanitizer
# report.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build=${1:-"$root/build-asan"}
jobs=$(nproc 2>/dev/null || echo 2)
# Flags live in CMakePresets.json (preset "asan").
export ASAN_OPTIONS=detect_leaks=1:halt_on_error=1
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
standalone=${ADCS_PHASE_LOG:-yes}  # called by run-tests.sh: its table prints these phases too
# shellcheck source=tools/phases.sh
. "$root/tools/phases.sh"
[ "$standalone" != yes ] || trap phase_table EXIT
phase asan_configure cmake --preset asan -S "$root" -B "$build"
phase asan_build cmake --build "$build" -j "$jobs"
phase asan_ctest ctest --test-dir "$build" --output-on-failure -j "$jobs"
