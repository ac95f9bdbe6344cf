#!/usr/bin/env bash
# "Run the tests" (README command 2; .ci/run calls exactly this). About 30-35 minutes on 2 cores (over the 20-minute budget; README)
# from a fresh clone with the packages installed (the table at the end gives each phase; README
# has the measured figure).
#   1. install missing Debian packages (tools/setup-deps.sh);
#   2. Release tree (clang++-14, -Werror), BUILD_DIR: the Cortex-M7 checks (every public header,
#      the Cortex-M4F float replays of every controller, the C example on both boards,
#      the instantiation units, the host/QEMU replays and their instruction counts), the callgrind
#      instruction counts and adcs-bench (adcs-sim only when run-main asks for it);
#   3. ASan + UBSan tree (clang++-14, -Werror), build-asan (tools/run-sanitizers.sh): every unit,
#      no-allocation, harness, CLI, parameter, foundation- and fault-scenario and install test,
#      the papers' closed loops and their claims (adcs_claim_tests; the scenario libraries with
#      UBSan and asserts but without ASan), the example programs
#      (examples/, which check their own results), and the five libFuzzer harnesses replaying
#      their committed corpora plus new inputs.
# Each test is built in the one tree where it is needed (docs/DECISIONS.md, "Each test in one
# tree"); no test runs in neither. Every phase prints its wall and CPU time, and a table of all
# of them closes the run.
#
# Usage: tools/run-tests.sh [--quick] [BUILD_DIR]   (default build; the sanitizer tree is build-asan)
#   --quick  the developers' inner loop: one clang++-14 tree without sanitizers (build-quick, or
#            BUILD_DIR) with the unit, no-allocation, harness and paper-claim tests, and ctest on
#            it; no Cortex-M7, no instruction counts, no ASan, no fuzzing. Not what CI runs.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
quick=0
if [ "${1:-}" = "--quick" ]; then quick=1; shift; fi
jobs=$(nproc 2>/dev/null || echo 2)
# shellcheck source=tools/phases.sh
. "$root/tools/phases.sh"
trap phase_table EXIT

phase setup bash "$root/tools/setup-deps.sh"

if [ "$quick" -eq 1 ]; then
  build=${1:-"$root/build-quick"}
  # clang compiles the Eigen-heavy tests ~3x faster than g++; -O2 with asserts armed (no NDEBUG).
  phase configure cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Debug \
    -DCMAKE_CXX_COMPILER=clang++-14 -DCMAKE_CXX_FLAGS_DEBUG=-O2 -DADCS_WERROR=ON \
    -DADCS_BUILD_BENCH=OFF -DADCS_TARGET_CHECK=OFF -DADCS_FUZZ=OFF
  phase build cmake --build "$build" -j "$jobs"
  phase ctest ctest --test-dir "$build" --output-on-failure -j "$jobs" -L 'unit|component|nomalloc|sim|examples|docs'
  exit 0
fi

build=${1:-"$root/build"}
# clang++-14 like the other trees: the bench's step fixtures and the host replay cores took ~540
# g++ CPU-s here, about half that with clang (docs/DECISIONS.md, "CI under 20 minutes"). g++
# still compiles every flight header with -Werror: arm-none-eabi-g++ 12 (the host's g++
# version) in the Cortex-M7 units and replays. The host C library (adcs_c) is built and tested
# in the ASan tree (the C example, adcs_c_tests); here it would only be compiled (~40 CPU-s).
# ADCS_SHORT_RUN_OPT=-O0: in this tree it reaches only the host side of the target replays (the
# recorder, the gain design, the C example's reference and the host replays), which run a few
# hundred steps; the bench, the scenarios it runs and the Cortex-M builds keep their -O2/-O3.
phase configure cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release \
  -DCMAKE_CXX_COMPILER=clang++-14 -DADCS_WERROR=ON \
  -DADCS_TESTS_FLIGHT=OFF -DADCS_TESTS_GROUND=OFF -DADCS_TESTS_CLAIMS=OFF -DADCS_BUILD_EXAMPLES=OFF \
  -DADCS_BUILD_C=OFF -DADCS_SHORT_RUN_OPT=-O0
# The Cortex-M programs (two nested builds, ExternalProject, not in ALL) are built here rather
# than inside ctest's target_compile_check, so that a phase shows their time: first every host
# object and check (adcs_target_host) on all cores, then the two nested builds one after the
# other, each on all cores (-j 1 here runs one nested build at a time; each runs -j
# ADCS_TARGET_BUILD_JOBS). Built together, up to six compilers shared the 2 cores and took twice
# the CPU time (docs/DECISIONS.md, "CI under 20 minutes", item 26).
phase build cmake --build "$build" -j "$jobs" --target all adcs_target_host
phase target_build cmake --build "$build" -j 1 --target adcs_target_check
phase ctest ctest --test-dir "$build" --output-on-failure -j "$jobs"
bash "$root/tools/run-sanitizers.sh" "$root/build-asan"
