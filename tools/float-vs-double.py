#!/usr/bin/python3
"""Runs paper scenarios with their flight components in double and in float (issue 19) and prints
the float/double table: every metric side by side, and every claim's two verdicts (whether the
paper's own number is reproduced, and whether our documented criterion holds) in each scalar.

usage: tools/float-vs-double.py [--sim PATH] [--out DIR] [--set KEY=VALUE]... SCENARIO...
  --sim  the adcs-sim executable (default: build/src/adcs-sim)
  --out  where the runs' JSON and CSV go (default: a temporary directory)
  --set  passed to both runs (e.g. duration_s=100)
The plant integrates in double in both runs (`--set scalar=float` changes the flight components
only); the table is markdown, ready for a note or docs/TARGET.md.
"""
import argparse
import json
import os
import subprocess
import sys
import tempfile


def run(sim, scenario, scalar, out, sets):
    d = os.path.join(out, f"{scenario}-{scalar}")
    cmd = [sim, "run", scenario, "--set", f"scalar={scalar}", "--out", d]
    for s in sets:
        cmd += ["--set", s]
    subprocess.run(cmd, check=True, stdout=subprocess.DEVNULL)
    with open(os.path.join(d, f"{scenario}.json"), encoding="utf-8") as f:
        return json.load(f)


def fmt(x):
    if isinstance(x, bool) or x is None:
        return str(x)
    if isinstance(x, (int, float)):
        if x == 0 or (abs(x) >= 1e-3 and abs(x) < 1e5):
            return f"{x:.4g}"
        return f"{x:.3e}"
    return str(x)


def verdict(c):
    crit = c.get("criterion_holds")
    return f"{c.get('paper_verdict', '-')} / {'holds' if crit else ('fails' if crit is False else '-')}"


def main():
    ap = argparse.ArgumentParser(prog="float-vs-double.py", description=__doc__.split("\n")[0])
    ap.add_argument("--sim", default=os.path.join("build", "src", "adcs-sim"))
    ap.add_argument("--out", default=None)
    ap.add_argument("--set", action="append", default=[], dest="sets")
    ap.add_argument("scenarios", nargs="+")
    a = ap.parse_args()
    out = a.out or tempfile.mkdtemp(prefix="float-vs-double-")
    failed = False
    for sc in a.scenarios:
        d = run(a.sim, sc, "double", out, a.sets)
        f = run(a.sim, sc, "float", out, a.sets)
        print(f"\n### {sc}\n")
        print("| metric | double | float |")
        print("|---|---|---|")
        for k, v in d["metrics"].items():
            print(f"| {k} | {fmt(v)} | {fmt(f['metrics'].get(k))} |")
        fc = {c["claim"]: c for c in f.get("claims", [])}
        if d.get("claims"):
            print("\n| claim | double: paper / criterion | float: paper / criterion | float: ours |")
            print("|---|---|---|---|")
            for c in d["claims"]:
                g = fc.get(c["claim"], {})
                print(f"| {c['claim']} | {verdict(c)} | {verdict(g)} | {g.get('ours', '-')} |")
                if c.get("holds") and not g.get("holds"):
                    failed = True
    print(f"\n(runs in {out})")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
