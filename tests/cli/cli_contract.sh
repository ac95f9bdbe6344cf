#!/usr/bin/env bash
# The user's contract of adcs-sim (docs/ARCHITECTURE.md), end to end.
# usage: cli_contract.sh PATH/TO/adcs-sim
# Prints "ok" and exits 0 on success; exits 1 on the first failure.
set -uo pipefail

SIM="${1:?usage: cli_contract.sh PATH/TO/adcs-sim}"
PY=/usr/bin/python3
SCENARIOS=(rigid-rw-torquefree rigid-rw-mrp-pd)
QUICK=(--set duration_s=2)

TMP="$(mktemp -d)"
trap 'rm -rf "$TMP"' EXIT
cd "$TMP" || exit 1

fail() { echo "FAIL: $*" >&2; exit 1; }
n=0
fresh() { n=$((n + 1)); dir="$TMP/out$n"; }  # sets $dir (a path that does not exist)

# Runs adcs-sim; stdout -> $TMP/stdout, stderr -> $TMP/stderr, status -> $rc.
sim() { "$SIM" "$@" >"$TMP/stdout" 2>"$TMP/stderr"; rc=$?; }
show() { echo "--- stdout:"; tail -5 "$TMP/stdout"; echo "--- stderr:"; cat "$TMP/stderr"; } >&2

# A bad command line: exit 2, exactly one stderr line "adcs-sim: error: ...", no files.
expect_usage_error() {
  local what="$1"; shift
  local dir; fresh
  sim "$@" --out "$dir"
  [ "$rc" -eq 2 ] || { show; fail "$what: exit status $rc, want 2 (adcs-sim $*)"; }
  [ "$(wc -l <"$TMP/stderr")" -eq 1 ] || { show; fail "$what: stderr is not exactly one line"; }
  grep -q '^adcs-sim: error: ' "$TMP/stderr" || { show; fail "$what: stderr lacks 'adcs-sim: error: '"; }
  if [ -e "$dir" ] && [ -n "$(ls -A "$dir")" ]; then
    ls -la "$dir" >&2; fail "$what: files written to $dir"
  fi
}

# ---- help, list ---------------------------------------------------------------------------
sim help
[ "$rc" -eq 0 ] && grep -q '^usage: adcs-sim' "$TMP/stdout" || { show; fail "help"; }
sim --help
[ "$rc" -eq 0 ] || fail "--help: exit $rc"

sim list
[ "$rc" -eq 0 ] || { show; fail "list: exit $rc"; }
[ "$(grep -c . "$TMP/stdout")" -ge 2 ] || { show; fail "list: fewer than 2 scenarios"; }
cp "$TMP/stdout" "$TMP/list"
for s in "${SCENARIOS[@]}"; do
  grep -qx -- "$s" "$TMP/list" || fail "list: '$s' missing"
done

# ---- run ----------------------------------------------------------------------------------
for s in "${SCENARIOS[@]}"; do
  sim describe "$s"
  [ "$rc" -eq 0 ] || { show; fail "describe $s: exit $rc"; }
  grep -q 'duration_s' "$TMP/stdout" && grep -q 'control_period_s' "$TMP/stdout" \
    || { show; fail "describe $s: duration_s/control_period_s missing"; }

  fresh
  sim run "$s" "${QUICK[@]}" --seed 3 --out "$dir"
  [ "$rc" -eq 0 ] || { show; fail "run $s: exit $rc"; }
  [ -s "$dir/$s.csv" ] || fail "run $s: no $s.csv"
  [ -s "$dir/$s.json" ] || fail "run $s: no $s.json"
  [ "$(ls -A "$dir" | wc -l)" -eq 2 ] || { ls -A "$dir" >&2; fail "run $s: extra files"; }
  head -1 "$dir/$s.csv" | grep -q '^# units: ' || fail "run $s: CSV lacks the '# units:' line"
  tail -n 1 "$TMP/stdout" | "$PY" -c '
import json, math, sys
name = sys.argv[1]
d = json.loads(sys.stdin.read())
assert isinstance(d, dict), "not an object"
assert set(d) == {"scenario", "seed", "metrics"}, sorted(d)
assert d["scenario"] == name, d["scenario"]
assert d["seed"] == 3, d["seed"]
assert isinstance(d["metrics"], dict) and d["metrics"], "no metrics"
for k, v in d["metrics"].items():
    assert v is None or (isinstance(v, (int, float)) and math.isfinite(v)), (k, v)
' "$s" || { show; fail "run $s: last stdout line is not the summary JSON"; }
  "$PY" -c '
import json, sys
path, name = sys.argv[1], sys.argv[2]
with open(path) as f:
    d = json.load(f)
for k in ("scenario", "seed", "description", "parameters", "metrics", "claims", "plots", "csv"):
    assert k in d, k
assert d["scenario"] == name and d["seed"] == 3 and d["csv"] == name + ".csv"
p = d["parameters"]
for k in ("duration_s", "control_period_s"):
    assert k in p and set(("value", "unit", "source")) <= set(p[k]), k
assert p["duration_s"]["value"] == 2, p["duration_s"]
for v in p.values():
    assert isinstance(v["source"], str) and v["source"], v
for c in d["claims"]:
    assert c["kind"] in ("paper", "check") and c["holds"] in (True, False, None), c
    assert c["criterion_holds"] == c["holds"], c
    assert c["paper_verdict"] in ("reproduced", "partly", "not reproduced", None), c
    assert c["kind"] == "paper" or c["paper_verdict"] is None, c
for q in d["plots"]:
    assert isinstance(q["file"], str) and isinstance(q["y"], list), q
' "$dir/$s.json" "$s" || fail "run $s: $s.json does not follow docs/CONTRACTS.md"
done

# ---- bad command lines: exit 2, one stderr line, nothing written ----------------------------
S="${SCENARIOS[1]}"
# A fixed-size vector parameter of $S (from describe), to test size and bracket errors.
sim describe "$S"
vec_line="$(grep -E '^  [A-Za-z0-9_.]+ += .*\(a vector of [0-9]+ numbers\)$' "$TMP/stdout" | head -1)"
expect_usage_error "unknown scenario" run no-such-scenario "${QUICK[@]}"
expect_usage_error "unknown key" run "$S" "${QUICK[@]}" --set no_such_key=1
expect_usage_error "number given abc" run "$S" --set duration_s=abc
expect_usage_error "number given 1,2" run "$S" --set duration_s=1,2
expect_usage_error "number given [1,2" run "$S" --set 'duration_s=[1,2'
expect_usage_error "number given nan" run "$S" --set duration_s=nan
expect_usage_error "number given inf" run "$S" --set duration_s=inf
expect_usage_error "trailing garbage" run "$S" --set duration_s=2x
expect_usage_error "empty value" run "$S" --set duration_s=
expect_usage_error "--set without =" run "$S" --set duration_s
expect_usage_error "duplicate --seed" run "$S" "${QUICK[@]}" --seed 1 --seed 2
expect_usage_error "negative seed" run "$S" "${QUICK[@]}" --seed -1
expect_usage_error "unknown option" run "$S" "${QUICK[@]}" --frobnicate 1
expect_usage_error "no scenario" run
expect_usage_error "unknown command" frobnicate
if [ -n "$vec_line" ]; then
  key="$(echo "$vec_line" | awk '{print $1}')"
  size="$(echo "$vec_line" | sed -E 's/.*a vector of ([0-9]+) numbers.*/\1/')"
  long="[$(seq -s, 1 $((size + 1)))]"
  expect_usage_error "wrong vector size ($key=$long)" run "$S" "${QUICK[@]}" --set "$key=$long"
  expect_usage_error "unterminated vector" run "$S" "${QUICK[@]}" --set "$key=[1,2"
  expect_usage_error "empty element" run "$S" "${QUICK[@]}" --set "$key=[1,,2]"
  expect_usage_error "vector given a number" run "$S" "${QUICK[@]}" --set "$key=1"
else
  echo "note: $S has no fixed-size vector parameter; vector checks skipped" >&2
fi
# Values whose derived quantities make no sense are refused before running (issue 15).
expect_usage_error "duration_s=1e300 (step count overflows)" run "$S" --set duration_s=1e300
expect_usage_error "more than 1e8 steps" run "$S" --set duration_s=1e8
expect_usage_error "rtol=0" run "$S" "${QUICK[@]}" --set rtol=0
expect_usage_error "atol=-1" run "$S" "${QUICK[@]}" --set atol=-1
expect_usage_error "montecarlo rtol=0" montecarlo "$S" --runs 2 --set rtol=0
expect_usage_error "--progress with a value" run "$S" "${QUICK[@]}" --progress=1
expect_usage_error "montecarlo without --runs" montecarlo "$S" "${QUICK[@]}"
expect_usage_error "montecarlo unknown key" montecarlo "$S" --runs 2 --set no_such_key=1

# --seed draws are in the JSON (issue 15): $S starts from a drawn attitude, not the declared one.
fresh
sim run "$S" "${QUICK[@]}" --seed 3 --out "$dir"
[ "$rc" -eq 0 ] || { show; fail "seed 3 run: exit $rc"; }
"$PY" -c '
import json, sys
p = json.load(open(sys.argv[1]))["parameters"]["sigma0_BN"]
assert p["value"] != [0, 0, 0] and p["source"].startswith("drawn from --seed 3"), p
assert p["declared"] == [0, 0, 0], p
' "$dir/$S.json" || fail "seed 3 run: the drawn sigma0_BN is not in $S.json"
[ ! -s "$TMP/stderr" ] || { show; fail "run without --progress wrote to stderr"; }
before="$(cat "$TMP/stdout")"
sim run "$S" "${QUICK[@]}" --seed 3 --out "$dir" --progress
[ "$rc" -eq 0 ] || { show; fail "--progress run: exit $rc"; }
[ "$(cat "$TMP/stdout")" = "$before" ] || { show; fail "--progress changed stdout"; }
grep -q "^adcs-sim: $S: done, t = 2 / 2 s, wall " "$TMP/stderr" || { show; fail "--progress: no final line"; }

# A failed run leaves an earlier output untouched.
fresh
sim run "$S" "${QUICK[@]}" --out "$dir"
[ "$rc" -eq 0 ] || { show; fail "rerun setup"; }
before="$(cat "$dir/$S.json")"
sim run "$S" --set duration_s=abc --out "$dir"
[ "$rc" -eq 2 ] || fail "rerun: exit $rc"
[ "$(cat "$dir/$S.json")" = "$before" ] || fail "a failed run changed $S.json"
[ "$(ls -A "$dir" | wc -l)" -eq 2 ] || { ls -A "$dir" >&2; fail "a failed run left files"; }

# ---- montecarlo ---------------------------------------------------------------------------
fresh
sim montecarlo "$S" --runs 3 --seed0 5 "${QUICK[@]}" --out "$dir"
[ "$rc" -eq 0 ] || { show; fail "montecarlo: exit $rc"; }
mc="$dir/$S-montecarlo.csv"
[ -s "$mc" ] || fail "montecarlo: no $S-montecarlo.csv"
[ -s "$dir/$S-montecarlo.json" ] || fail "montecarlo: no $S-montecarlo.json"
[ ! -e "$dir/$S.csv" ] || fail "montecarlo wrote a per-run time series"
grep -q '^\[3/3 runs\] 0 invalid, 0 failed' "$TMP/stderr" \
  || { show; fail "montecarlo: no progress lines on stderr"; }
"$PY" -c '
import csv, sys
rows = list(csv.reader(open(sys.argv[1])))
assert rows[0][0] == "run" and rows[0][-3:] == ["status", "seed", "error"], rows[0]
assert len(rows) == 4, "want a header and 3 rows, got %d lines" % len(rows)
assert [r[0] for r in rows[1:]] == ["0", "1", "2"], [r[0] for r in rows[1:]]
for r in rows[1:]:
    assert len(r) == len(rows[0]) and r[-3] == "ok", r
    [float(x) for x in r[1:-3]]
' "$mc" || fail "montecarlo: bad $mc"
tail -n 1 "$TMP/stdout" | "$PY" -c '
import json, sys
d = json.loads(sys.stdin.read())
assert d["scenario"] == sys.argv[1] and d["runs"] == 3 and d["seed0"] == 5, d
assert d["metrics"], "no metrics"
for k, v in d["metrics"].items():
    assert {"min", "median", "max"} <= set(v), (k, v)
    if None not in (v["min"], v["median"], v["max"]):
        assert v["min"] <= v["median"] <= v["max"], (k, v)
' "$S" || { show; fail "montecarlo: last stdout line is not the summary JSON"; }
"$PY" -c '
import json, sys
d = json.load(open(sys.argv[1]))
assert d["runs"] == 3 and d["seed0"] == 5 and "parameters" in d and "metrics" in d, d.keys()
' "$dir/$S-montecarlo.json" || fail "montecarlo: bad $S-montecarlo.json"

echo ok
