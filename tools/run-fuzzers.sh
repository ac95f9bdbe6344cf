#!/usr/bin/env bash
# Builds the libFuzzer harnesses (tests/fuzz, clang++-14, ASan + UBSan) and runs each one for a
# fixed number of inputs from its committed seed corpus, deterministically (-seed=1). Fails
# (non-zero exit) on any crash, sanitizer report, leak, timeout or FUZZ_CHECK; the input that did
# it is kept as BUILD_DIR/artifacts/<fuzzer>-crash-* (replay: BUILD_DIR/<fuzzer> FILE).
# New inputs found during the run go to a temporary directory, never into the repository.
#
# Usage: tools/run-fuzzers.sh [BUILD_DIR] [RUNS]
#   BUILD_DIR  default build-fuzz
#   RUNS       inputs per fuzzer; default 200000, except fuzz_seed004 (see below). A RUNS given
#              here applies to every fuzzer.
# fuzz_seed004 drives the 27-state drag-free ESKF (18 + 9 blocks, an 18x18 eigen-decomposition
# whenever a covariance leaves the PSD cone): ~0.75 ms per input under ASan (1300 exec/s), so
# 200000 inputs would take ~150 s; its default, 80000 (~60 s), keeps it with the others.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build=${1:-"$root/build-fuzz"}
runs_all=${2:-}
jobs=$(nproc 2>/dev/null || echo 2)
fuzzers=(fuzz_seed001 fuzz_seed002 fuzz_seed003 fuzz_seed004)
default_runs() {
  case "$1" in
    fuzz_seed004) echo 80000 ;;
    *) echo 200000 ;;
  esac
}

command -v clang++-14 >/dev/null || { echo "run-fuzzers: clang++-14 missing (tools/setup-deps.sh)" >&2; exit 1; }
t0=$(date +%s)
cmake -S "$root/tests/fuzz" -B "$build" -G Ninja -DCMAKE_CXX_COMPILER=clang++-14 >/dev/null
cmake --build "$build" -j "$jobs"
t1=$(date +%s)
echo "run-fuzzers: build $((t1 - t0)) s"

mkdir -p "$build/artifacts" "$build/logs"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
export ASAN_OPTIONS=detect_leaks=1:halt_on_error=1
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
failed=()
for f in "${fuzzers[@]}"; do
  runs=${runs_all:-$(default_runs "$f")}
  seeds="$root/tests/fuzz/corpus/$f"
  [ -d "$seeds" ] || { echo "run-fuzzers: no corpus $seeds" >&2; exit 1; }
  mkdir -p "$work/$f"
  log="$build/logs/$f.log"
  s=$(date +%s)
  # First directory: where libFuzzer writes new inputs (temporary); second: the committed seeds,
  # only read. -timeout: a hang of one input fails the run.
  if "$build/$f" -runs="$runs" -seed=1 -max_len=4096 -timeout=25 -print_final_stats=1 \
       -artifact_prefix="$build/artifacts/$f-" "$work/$f" "$seeds" >"$log" 2>&1; then
    status=ok
  else
    status=FAILED
    failed+=("$f")
  fi
  e=$(date +%s)
  echo "run-fuzzers: $f $runs runs: $status in $((e - s)) s ($(grep -m1 -o 'stat::average_exec_per_sec: *[0-9]*' "$log" | grep -o '[0-9]*$' || echo '?') exec/s)"
  if [ "$status" != ok ]; then
    grep -E "FUZZ_CHECK|runtime error|ERROR: |SUMMARY|Test unit written" "$log" | head -20 >&2 || true
  fi
done
echo "run-fuzzers: total $(( $(date +%s) - t0 )) s"
if [ ${#failed[@]} -ne 0 ]; then
  echo "run-fuzzers: FAILED: ${failed[*]} (logs in $build/logs, inputs in $build/artifacts)" >&2
  exit 1
fi
echo "run-fuzzers: ${#fuzzers[@]} passed, 0 failed"
