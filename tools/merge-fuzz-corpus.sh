#!/usr/bin/env bash
# A fuzzing campaign that grows the committed corpus: each fuzzer of a built tests/fuzz tree runs
# RUNS inputs (default 200000; 80000 for fuzz_seed004) from the committed corpora with -seed=SEED,
# then libFuzzer -merge=1 adds to tests/fuzz/corpus-found/<fuzzer>/ every input of that campaign
# that reaches a coverage feature the committed inputs do not (nothing is removed). Commit the new
# files: every later ctest run replays them (tests/fuzz/run_fuzzer.cmake). A crash stops the
# campaign with the input in BUILD_DIR/artifacts/: fix it and add a regression test first.
#
# Usage: tools/merge-fuzz-corpus.sh BUILD_DIR [RUNS] [SEED]
#   BUILD_DIR  a tree with the fuzzers built: build-asan/tests/fuzz (tools/run-sanitizers.sh) or
#              build-fuzz (tools/run-fuzzers.sh)
#   SEED       libFuzzer -seed (default 1); a new seed explores new mutations
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build=${1:?usage: tools/merge-fuzz-corpus.sh BUILD_DIR [RUNS] [SEED]}
runs=${2:-}
seed=${3:-1}
export ASAN_OPTIONS=detect_leaks=1:halt_on_error=1
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
for f in fuzz_seed001 fuzz_seed002 fuzz_seed003 fuzz_seed004; do
  bin="$build/$f"
  [ -x "$bin" ] || { echo "merge-fuzz-corpus: $bin not built" >&2; exit 1; }
  n=${runs:-200000}
  [ -n "$runs" ] || [ "$f" != fuzz_seed004 ] || n=80000
  hand="$root/tests/fuzz/corpus/$f"
  found="$root/tests/fuzz/corpus-found/$f"
  mkdir -p "$found" "$build/artifacts"
  work=$(mktemp -d)
  merged=$(mktemp -d)
  trap 'rm -rf "$work" "$merged"' EXIT
  "$bin" -runs="$n" -seed="$seed" -max_len=4096 -timeout=25 "-artifact_prefix=$build/artifacts/$f-" \
    "$work" "$hand" "$found" 2>"$work.log" || { tail -40 "$work.log" >&2; exit 1; }
  # The committed inputs first: merge keeps only what adds a feature beyond them.
  cp "$hand"/* "$found"/* "$merged"/ 2>/dev/null || true
  before=$(ls "$merged" | wc -l)
  "$bin" -merge=1 "$merged" "$work" 2>>"$work.log" || { tail -40 "$work.log" >&2; exit 1; }
  added=0
  for x in "$merged"/*; do
    b=$(basename "$x")
    if [ ! -e "$hand/$b" ] && [ ! -e "$found/$b" ]; then cp "$x" "$found/$b"; added=$((added + 1)); fi
  done
  echo "merge-fuzz-corpus: $f: $n inputs (-seed=$seed), $(ls "$work" | wc -l) kept by the run, $added added to corpus-found (committed before: $before)"
  rm -rf "$work" "$merged" "$work.log"
  trap - EXIT
done
