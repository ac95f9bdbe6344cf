#!/usr/bin/env bash
# "Run the tests" (README command 2; .ci/run calls exactly this):
#   install missing Debian packages, configure + build everything (Release, warnings are
#   errors), run every ctest test (unit, property, scenario, CLI, install consumer, and the
#   Cortex-M7 compile check of every public header).
# Usage: tools/run-tests.sh [BUILD_DIR]   (default: build)
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
