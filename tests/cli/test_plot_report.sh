#!/usr/bin/env bash
# Tests tools/plot.py and tools/report.py on synthetic scenario outputs (no adcs-sim needed).
# usage: test_plot_report.sh [REPO_ROOT]   (default: two levels above this script)
# Prints "ok" and exits 0 on success; exits non-zero on the first failure.
set -euo pipefail

ROOT="${1:-$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)}"
PY=/usr/bin/python3
PLOT="$ROOT/tools/plot.py"
REPORT="$ROOT/tools/report.py"

fail() { echo "FAIL: $*" >&2; exit 1; }

[ -x "$PY" ] || fail "$PY not found"
"$PY" -c 'import matplotlib, numpy' 2>/dev/null \
  || fail "$PY cannot import matplotlib/numpy (run tools/setup-deps.sh)"
[ -f "$PLOT" ] || fail "missing $PLOT"
[ -f "$REPORT" ] || fail "missing $REPORT"

TMP="$(mktemp -d)"
trap 'rm -rf "$TMP"' EXIT
export MPLCONFIGDIR="$TMP/mplconfig"
D="$TMP/out"
mkdir -p "$D"

# ---- synthetic outputs -------------------------------------------------------------
"$PY" - "$D" <<'EOF'
import json, math, os, sys
d = sys.argv[1]

def write_csv(path, cols, units, rows):
    with open(path, "w") as f:
        f.write("# units: " + ", ".join(f"{c} [{u}]" for c, u in zip(cols, units)) + "\n")
        f.write(",".join(cols) + "\n")
        for r in rows:
            f.write(",".join("%.9g" % v for v in r) + "\n")

cols = ["t", "sigma_BN_1", "sigma_BN_2", "sigma_BN_3", "omega_BN_1", "omega_BN_2",
        "omega_BN_3", "err_norm", "funnel_lo", "funnel_hi"]
units = ["s", "-", "-", "-", "rad/s", "rad/s", "rad/s", "-", "-", "-"]
rows = []
for k in range(401):
    t = 0.1 * k
    e = math.exp(-t / 8.0)
    s = [0.3 * e * math.cos(0.5 * t), -0.2 * e * math.sin(0.4 * t), 0.1 * e]
    w = [-0.05 * e * math.sin(0.5 * t), 0.03 * e * math.cos(0.4 * t), -0.0125 * e]
    n = math.sqrt(sum(v * v for v in s)) + 1e-6
    rho = 0.5 * math.exp(-t / 6.0) + 0.01
    rows.append([t] + s + w + [n, -rho, rho])
write_csv(os.path.join(d, "demo.csv"), cols, units, rows)

frows = []
for k in range(1, 200):
    f = 0.01 * k
    frows.append([f, 1e-4 / (1.0 + (f / 0.2) ** 2)])
write_csv(os.path.join(d, "demo-psd.csv"), ["f", "psd_sigma"], ["Hz", "1/Hz"], frows)

demo = {
    "scenario": "demo", "seed": 7, "description": "Synthetic plot/report test | pipes ok",
    "parameters": {
        "J": {"value": [[10.0, 0.0], [0.0, 12.5]], "unit": "kg m^2", "source": "assumed"},
        "dt": {"value": 0.1, "unit": "s", "source": "seed 002 Table 1"},
        "law": {"value": "pd", "unit": "", "source": "assumed: not in the paper"}},
    "metrics": {"settling_time": 31.234567891, "rms_sigma": 1.23456789e-5, "nan_metric": None},
    "claims": [
        {"kind": "check", "claim": "energy decreases", "paper_value": "-",
         "ours": "|dV| = 1e-9", "holds": True},
        {"kind": "paper", "claim": "settles within 30 s", "paper_value": "30 s",
         "ours": "31.2 s", "paper_verdict": "partly", "criterion": "<= 30 s (spec)",
         "criterion_holds": False, "holds": False, "note": "one axis only"}],
    "plots": [
        {"file": "demo-attitude.png", "title": "Attitude error in the funnel", "x": "t",
         "y": ["sigma_BN_1", "sigma_BN_2", "sigma_BN_3", "no_such_column"],
         "ylabel": "sigma_BN [-]", "logy": False,
         "fill": [["funnel_lo", "funnel_hi"]], "hline": [[0.0, "zero"]]},
        {"file": "demo-norm.png", "title": "Attitude error norm", "x": "t",
         "y": ["err_norm"], "ylabel": "|sigma| [-]", "logy": True,
         "hline": [0.01, "requirement"]},
        {"file": "demo-psd.png", "title": "PSD of sigma", "kind": "psd", "csv": "demo-psd.csv",
         "x": "f", "y": ["psd_sigma"], "ylabel": "PSD [1/Hz]"}],
    "csv": "demo.csv"}
with open(os.path.join(d, "demo.json"), "w") as f:
    json.dump(demo, f, indent=1)

# No "plots": defaults grouped by prefix.
write_csv(os.path.join(d, "noplots.csv"), cols, units, rows)
with open(os.path.join(d, "noplots.json"), "w") as f:
    json.dump({"scenario": "noplots", "seed": 0, "parameters": {}, "metrics": {"a": 1},
               "claims": [], "csv": "noplots.csv"}, f)

# A Monte Carlo campaign's summary (no CSV or envelopes here, so no campaign figures).
with open(os.path.join(d, "demo-montecarlo.json"), "w") as f:
    json.dump({"scenario": "demo", "runs": 3, "seed0": 1, "counts": {"ok": 3, "invalid": 0, "failed": 0},
               "metrics": {"err": {"count": 3, "nonfinite": 0, "min": 0.1, "p1": 0.1, "p5": 0.1, "median": 0.2,
                                   "p95": 0.5, "p99": 0.5, "max": 0.5, "mean": 0.27, "std": 0.2}},
               "claims": [{"kind": "check", "claim": "err small", "held": 2, "failed": 1, "summary": "held in 2 / 3"}],
               "worst_runs": {"metric": "err", "runs": [{"run": 2, "value": 0.5, "command": "adcs-sim run demo --seed 9"}]},
               "failed_runs": []}, f)
EOF

is_png() {  # non-empty file starting with the 8-byte PNG signature
  [ -s "$1" ] || return 1
  [ "$(head -c 8 "$1" | od -An -tx1 | tr -d ' \n')" = "89504e470d0a1a0a" ]
}

# ---- plot.py -------------------------------------------------------------------------
"$PY" "$PLOT" "$D" >"$TMP/plot.out" 2>"$TMP/plot.err" \
  || { cat "$TMP/plot.err" >&2; fail "plot.py exited non-zero"; }
for f in demo-attitude.png demo-norm.png demo-psd.png \
         noplots-sigma_BN.png noplots-omega_BN.png noplots-err_norm.png; do
  is_png "$D/$f" || fail "$f missing or not a PNG"
  grep -qF "$D/$f" "$TMP/plot.out" || fail "plot.py did not report $f"
done
[ "$(wc -l <"$TMP/plot.out")" -eq 8 ] \
  || fail "expected 8 PNG lines from plot.py, got: $(cat "$TMP/plot.out")"
grep -q "no_such_column" "$TMP/plot.err" || fail "no warning for the missing column"
ls "$D" | grep -q montecarlo.png && fail "montecarlo JSON was plotted"

# Explicit NAME selects one scenario.
rm -f "$D/demo-norm.png"
"$PY" "$PLOT" "$D" demo >"$TMP/one.out" 2>/dev/null || fail "plot.py OUT_DIR demo exited non-zero"
grep -q "demo-norm.png" "$TMP/one.out" || fail "plot.py OUT_DIR demo did not write demo-norm.png"
grep -q "noplots" "$TMP/one.out" && fail "plot.py OUT_DIR demo plotted another scenario"
is_png "$D/demo-norm.png" || fail "demo-norm.png not regenerated"

# Unreadable input -> non-zero exit; other inputs still processed.
mkdir -p "$TMP/bad"
cp "$D/noplots.json" "$D/noplots.csv" "$TMP/bad/"
echo '{not json' >"$TMP/bad/broken.json"
if "$PY" "$PLOT" "$TMP/bad" >"$TMP/bad.out" 2>/dev/null; then
  fail "plot.py exited 0 on an unreadable JSON"
fi
is_png "$TMP/bad/noplots-sigma_BN.png" || fail "plot.py stopped at the unreadable JSON"

# ---- report.py -----------------------------------------------------------------------
"$PY" "$REPORT" "$D" >/dev/null || fail "report.py exited non-zero"
R="$D/REPORT.md"
[ -s "$R" ] || fail "REPORT.md missing"
need() { grep -qF -- "$1" "$R" || fail "REPORT.md lacks: $1"; }
need "| paper claim | the paper's own value | ours | paper verdict | our criterion (source) | criterion holds? |"
need "## Paper claims"
need "## Harness checks"
need "| demo | settles within 30 s (one axis only) | 30 s | 31.2 s | **partly** | <= 30 s (spec) | **NO** |"
need "| demo | energy decreases | - | \\|dV\\| = 1e-9 | yes |"
need "**Summary: paper: 0 reproduced, 1 partly, 0 not reproduced (of 1 paper claims); criteria: 2 claims, 1 hold, 1 do not.**"
need "| metric | value |"
need "| settling_time | 31.2346 |"
need "| rms_sigma | 1.23457e-05 |"
need "| nan_metric | n/a |"
need "- seed: 7"
need '`dt` = 0.1 s'
need '`J` = [[10, 0], [0, 12.5]] kg m^2'
need "![Attitude error in the funnel](demo-attitude.png)"
need "![PSD of sigma](demo-psd.png)"
need "](noplots-sigma_BN.png)"
need "Synthetic plot/report test | pipes ok"
need "## Campaigns"
need "| err small | held in 2 / 3 |"
need "| err | 0.1 | 0.1 | 0.1 | 0.2 | 0.5 | 0.5 | 0.5 | 0.27 | 0.2 | 0 |"
need "- run 2: 0.5 — \`adcs-sim run demo --seed 9\`"

# Deterministic: a second run gives the same file.
cp "$R" "$TMP/REPORT.first"
"$PY" "$REPORT" "$D" >/dev/null
cmp -s "$R" "$TMP/REPORT.first" || fail "REPORT.md differs between two runs"

# --check: 1 with the false claim, 0 once it is gone.
set +e
"$PY" "$REPORT" --check "$D" >/dev/null 2>&1; rc=$?
set -e
[ "$rc" -eq 1 ] || fail "report.py --check exited $rc with a false claim (expected 1)"

"$PY" - "$D/demo.json" <<'EOF'
import json, sys
p = sys.argv[1]
m = json.load(open(p))
m["claims"] = [c for c in m["claims"] if c.get("criterion_holds", c["holds"]) is not False]
json.dump(m, open(p, "w"))
EOF
"$PY" "$REPORT" --check "$D" >/dev/null || fail "report.py --check exited non-zero with no false claim"
need "(of 0 paper claims); criteria: 1 claims, 1 hold, 0 do not"
need "No paper scenarios are registered yet"

echo ok
