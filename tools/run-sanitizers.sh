#!/usr/bin/env bash
# The whole ctest suite under AddressSanitizer + LeakSanitizer + UndefinedBehaviorSanitizer (g++):
# every unit, property, scenario, no-allocation, CLI and install-consumer test, with any sanitizer
# report fatal (halt_on_error, -fno-sanitize-recover=undefined).
#   -O1: the usual ASan compromise (-O0 makes the CVODE scenario tests ~3x slower, -O2 hides
#        fewer bugs but costs build time); Debug build type so Eigen's own asserts (bounds,
#        sizes) are armed too.
#   Bench and the Cortex-M7 check are off: neither runs host code under test.
# Nothing is excluded: the install consumer only installs headers and compiles a 14-line main
# with the default flags, cli_contract runs the ASan-built adcs-sim on 2 s scenarios, and
# plot_report is Python.
# Usage: tools/run-sanitizers.sh [BUILD_DIR]   (default: build-asan). Prints the wall time of
# each phase; exits non-zero on any build error, test failure or sanitizer report.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build=${1:-"$root/build-asan"}
jobs=$(nproc 2>/dev/null || echo 2)
# Flags live in CMakePresets.json (preset "asan"): g++ -O1 -fsanitize=address,undefined
# -fno-omit-frame-pointer -fno-sanitize-recover=undefined, Debug, bench and target check off.
# -Wno-error=maybe-uninitialized there: GCC's manual (Instrumentation Options) warns that
# sanitizers raise the rate of false-positive -Wmaybe-uninitialized and advises against -Werror
# with them; g++ 12 at -O1 flags Eigen's debug-mode aliasing check in math/se3.hpp. It stays a
# warning here, and an error in the Release build.
export ASAN_OPTIONS=detect_leaks=1:halt_on_error=1
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
t0=$(date +%s)
cmake --preset asan -S "$root" -B "$build"
t1=$(date +%s)
cmake --build "$build" -j "$jobs"
t2=$(date +%s)
ctest --test-dir "$build" --output-on-failure -j "$jobs"
t3=$(date +%s)
echo "run-sanitizers: configure $((t1 - t0)) s, build $((t2 - t1)) s, ctest $((t3 - t2)) s, total $((t3 - t0)) s"
