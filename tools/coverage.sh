#!/usr/bin/env bash
# Line coverage of the flight library (include/adcs/) by the whole ctest suite: configures,
# builds and tests the "coverage" preset of CMakePresets.json (g++ --coverage -O0, Debug
# without -g: gcov needs no debug info, and -g made one Eigen-heavy test file 2.6x slower to
# compile; bench and the Cortex-M7 check off), then gcovr 5.2 keeps include/adcs/ only.
#   stdout:                         text report (every header) and the total
#   build-coverage/coverage.txt     the same text report
#   build-coverage/coverage/        HTML report with annotated sources (index.html)
# tests/core/test_instantiate_all.cpp instantiates every class template, so untested members
# count as uncovered lines rather than being left out of the report.
# Usage: tools/coverage.sh [MIN_LINE_PERCENT]   (fails below MIN_LINE_PERCENT if given)
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build="$root/build-coverage"
min=${1:-}
jobs=$(nproc 2>/dev/null || echo 2)

t0=$(date +%s)
cmake --preset coverage -S "$root"
# Counters of an earlier run would be added to this one's.
[ -d "$build" ] && find "$build" -name '*.gcda' -delete
cmake --build --preset coverage -j "$jobs"
t1=$(date +%s)
(cd "$root" && ctest --preset coverage -j "$jobs")
t2=$(date +%s)

rm -rf "$build/coverage" && mkdir -p "$build/coverage"
gcovr_args=(--root "$root" --filter "$root/include/adcs/" -j "$jobs" --print-summary
            --txt "$build/coverage.txt" --html-details "$build/coverage/index.html"
            --html-title "adcs include/adcs line coverage")
[ -n "$min" ] && gcovr_args+=(--fail-under-line "$min")
status=0
gcovr "${gcovr_args[@]}" "$build" || status=$?
cat "$build/coverage.txt"
t3=$(date +%s)
echo "coverage: build $((t1 - t0)) s, ctest $((t2 - t1)) s, gcovr $((t3 - t2)) s, total $((t3 - t0)) s"
echo "coverage: text report $build/coverage.txt, HTML $build/coverage/index.html"
exit "$status"
