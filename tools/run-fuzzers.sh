#!/usr/bin/env bash
# The libFuzzer harnesses alone (tests/fuzz, clang++-14, ASan + UBSan), as a standalone build:
# configures and builds tests/fuzz in BUILD_DIR and runs its ctest tests (label fuzz), each fuzzer
# replaying its committed corpora and then trying a fixed number of new inputs, deterministically
# (-seed=1; the run logic and the per-fuzzer defaults, 20000 new inputs and 8000 for
# fuzz_seed004, live in tests/fuzz/CMakeLists.txt and tests/fuzz/run_fuzzer.cmake). Longer
# campaigns that grow the committed corpus: tools/merge-fuzz-corpus.sh. tools/run-tests.sh does not call
# this: the same tests run inside the ASan build of tools/run-sanitizers.sh (preset asan,
# ADCS_FUZZ=ON). Fails (non-zero exit) on any crash, sanitizer report, leak, timeout or
# FUZZ_CHECK; the input that did it is kept as BUILD_DIR/artifacts/<fuzzer>-crash-* (replay:
# BUILD_DIR/<fuzzer> FILE). New inputs found during a run go to BUILD_DIR/fuzz-work/, never into
# the repository.
#
# Usage: tools/run-fuzzers.sh [BUILD_DIR] [RUNS]
#   BUILD_DIR  default build-fuzz
#   RUNS       new inputs per fuzzer for all four, after the replay (default: the per-fuzzer
#              defaults above)
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build=${1:-"$root/build-fuzz"}
runs=${2:-}
jobs=$(nproc 2>/dev/null || echo 2)

command -v clang++-14 >/dev/null || { echo "run-fuzzers: clang++-14 missing (tools/setup-deps.sh)" >&2; exit 1; }
t0=$(date +%s)
cmake -S "$root/tests/fuzz" -B "$build" -G Ninja -DCMAKE_CXX_COMPILER=clang++-14 "-DADCS_FUZZ_RUNS=$runs" >/dev/null
cmake --build "$build" -j "$jobs"
t1=$(date +%s)
status=0
ctest --test-dir "$build" -L fuzz --output-on-failure -V -j "$jobs" || status=$?
echo "run-fuzzers: build $((t1 - t0)) s, runs $(( $(date +%s) - t1 )) s"
exit "$status"
