#!/usr/bin/env bash
# "Run the tests" (README command 2; .ci/run calls exactly this):
#   1. install missing Debian packages;
#   2. configure + build everything (Release, g++, warnings are errors) and run every ctest test
#      (unit, property, scenario, CLI, install consumer, instruction counts, and the Cortex-M7
#      header check and QEMU replays);
#   3. the same suite again under ASan + UBSan (clang++-14, second build directory build-asan,
#      tools/run-sanitizers.sh), with the libFuzzer harnesses run for their fixed number of
#      inputs (ctest label fuzz, docs/FUZZING.md).
# Usage: tools/run-tests.sh [BUILD_DIR]   (default: build; the sanitizer build is build-asan)
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build=${1:-"$root/build"}
jobs=$(nproc 2>/dev/null || echo 2)

bash "$root/tools/setup-deps.sh"
cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release
cmake --build "$build" -j "$jobs"
# The Cortex-M7 check is also a ctest test; building it here first keeps its output readable.
cmake --build "$build" --target adcs_target_check -j "$jobs"
ctest --test-dir "$build" --output-on-failure -j "$jobs"
bash "$root/tools/run-sanitizers.sh" "$root/build-asan"
