#!/usr/bin/python3
"""Check every controller/estimator step against its timing budget (bench/budgets.json).

usage: tools/check-budgets.py [--bench PATH] [--budgets PATH] [--repetitions N] [--cpu K|none]

Runs adcs-bench (Google Benchmark) on the budgeted BM_<Name>_Step benchmarks, N repetitions
(default 10), pinned to CPU K with taskset when available (default: the last CPU), and prints one
line per budget:

  PASS|FAIL  BM_<Name>_Step  median <m> ns (budget <b>)  p99 <p> ns (budget <q>)  p99/median <r>  allocs <a>

A budget passes when, over the repetitions,
  - the median of the benchmark's mean step time (Google Benchmark's CPU time: on a shared host
    the wall time also counts other processes' time slices)                    <= median_ns,
  - the median of step_p99_ns (99th percentile of 20,000 individually timed steps) <= p99_ns,
  - p99 <= 2 x the measured median (jitter; the issue's goal), and
  - allocs_per_step == 0 in every repetition.
Exit status: 0 all PASS, 1 any FAIL, 2 usage or benchmark errors. Timings depend on the machine:
the budgets in bench/budgets.json are for the reference machine named there; users copy the file
and set their own flight computer's budgets. Not part of ctest (timings are noisy).
"""

import argparse
import json
import os
import shutil
import statistics
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
UNIT_NS = {"ns": 1.0, "us": 1e3, "ms": 1e6, "s": 1e9}


def main(argv):
    ap = argparse.ArgumentParser(prog="check-budgets.py", description=__doc__.split("\n")[0])
    ap.add_argument("--bench", default=os.path.join(ROOT, "build", "bench", "adcs-bench"))
    ap.add_argument("--budgets", default=os.path.join(ROOT, "bench", "budgets.json"))
    ap.add_argument("--repetitions", type=int, default=10)
    ap.add_argument("--cpu", default=str((os.cpu_count() or 1) - 1),
                    help="CPU to pin the benchmark to with taskset, or 'none'")
    args = ap.parse_args(argv[1:])
    if args.repetitions < 1:
        print("check-budgets: --repetitions must be >= 1", file=sys.stderr)
        return 2
    try:
        with open(args.budgets, encoding="utf-8") as f:
            budgets = json.load(f)["budgets"]
    except (OSError, ValueError, KeyError) as e:
        print(f"check-budgets: cannot read {args.budgets}: {e}", file=sys.stderr)
        return 2
    if not os.access(args.bench, os.X_OK):
        print(f"check-budgets: {args.bench} not found; build it: cmake --build build --target adcs-bench",
              file=sys.stderr)
        return 2

    names = [b["benchmark"] for b in budgets]
    cmd = [args.bench, "--benchmark_filter=^(" + "|".join(names) + ")$",
           f"--benchmark_repetitions={args.repetitions}", "--benchmark_format=json"]
    if args.cpu != "none" and shutil.which("taskset"):
        cmd = ["taskset", "-c", args.cpu] + cmd
    print("check-budgets: " + " ".join(cmd), file=sys.stderr)
    run = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.DEVNULL, text=True)
    if run.returncode != 0:
        print(f"check-budgets: adcs-bench exited with {run.returncode}", file=sys.stderr)
        return 2
    try:
        rows = json.loads(run.stdout)["benchmarks"]
    except (ValueError, KeyError) as e:
        print(f"check-budgets: cannot parse the benchmark output: {e}", file=sys.stderr)
        return 2

    failed = False
    for b in budgets:
        name = b["benchmark"]
        reps = [r for r in rows if r.get("run_name", r["name"]) == name and r.get("run_type") == "iteration"]
        if not reps:
            print(f"FAIL  {name}  not run (no such benchmark)")
            failed = True
            continue
        median = statistics.median(r["cpu_time"] * UNIT_NS[r.get("time_unit", "ns")] for r in reps)
        p99 = statistics.median(r["step_p99_ns"] for r in reps)
        allocs = max(r["allocs_per_step"] for r in reps)
        ok = (median <= b["median_ns"] and p99 <= b["p99_ns"] and p99 <= 2.0 * median and allocs == 0)
        failed = failed or not ok
        print(f"{'PASS' if ok else 'FAIL'}  {name:<36} median {median:8.1f} ns (budget {b['median_ns']:g})"
              f"  p99 {p99:8.1f} ns (budget {b['p99_ns']:g})  p99/median {p99 / median:4.2f}"
              f"  allocs {allocs:g}")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
