#!/usr/bin/python3
"""Deterministic instructions per step of every controller/estimator, by valgrind's callgrind.

usage: tools/callgrind-counts.py [--stepcount PATH] [--steps N] [--write JSON] [--check JSON]

Runs build/bench/adcs-stepcount --each N NAME... under
  valgrind --tool=callgrind --toggle-collect='*adcs_counted_steps*'
                            --dump-after='*adcs_count_region_end*'
for every step fixture (bench/step_fixtures.hpp, the same code adcs-bench times), so only the N
steps are counted (not construction, warm-up or start-up), and prints instructions per step.
All fixtures run in one process, each freshly constructed, and callgrind dumps after each
counted region: one valgrind start-up (~0.6 s) instead of one per fixture and run.
  --write JSON  also writes the counts (this is how bench/callgrind-counts.json is made);
  --check JSON  runs every fixture twice (a fresh one each time) and fails (exit 1) unless both
                runs give the same count
                (determinism) and no count exceeds 1.25x the committed one (a regression gate:
                the counts depend on the compiler and Eigen version, so they are compared with a
                margin, not for equality). This is the ctest test `step_instruction_counts`.
Exit status 0 ok, 1 check failed, 2 usage / tool errors.
"""

import argparse
import json
import os
import re
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
REGRESSION_MARGIN = 1.25


def build_compiler(stepcount):
    """The C++ compiler that built adcs-stepcount (its tree's CMakeCache.txt), e.g. 'Debian clang
    version 14.0.6'; the counts depend on it."""
    d = os.path.dirname(os.path.abspath(stepcount))
    while d != os.path.dirname(d):
        cache = os.path.join(d, "CMakeCache.txt")
        if os.path.exists(cache):
            with open(cache, encoding="utf-8") as f:
                for line in f:
                    if line.startswith("CMAKE_CXX_COMPILER:"):
                        cxx = line.split("=", 1)[1].strip()
                        return subprocess.run([cxx, "--version"], stdout=subprocess.PIPE,
                                              text=True).stdout.splitlines()[0]
        d = os.path.dirname(d)
    raise RuntimeError(f"no CMakeCache.txt above {stepcount}: which compiler built it?")


def count_each(stepcount, names, steps):
    """Instructions per step of each fixture in `names` (a name may repeat), in order."""
    with tempfile.TemporaryDirectory() as tmp:
        out = os.path.join(tmp, "callgrind.out")
        cmd = ["valgrind", "--tool=callgrind", "--toggle-collect=*adcs_counted_steps*",
               "--dump-after=*adcs_count_region_end*", f"--callgrind-out-file={out}",
               stepcount, "--each", str(steps)] + list(names)
        run = subprocess.run(cmd, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
        if run.returncode != 0:
            raise RuntimeError(f"{' '.join(cmd[:8])} ... failed:\n{run.stderr[-2000:]}")
        counts = []
        # One dump per counted region, numbered from 1 in the order they ran; the last file
        # (`out` itself, at exit) holds what ran after the last region: nothing is collected there.
        for k in range(1, len(names) + 1):
            path = f"{out}.{k}"
            total = None
            if os.path.exists(path):
                with open(path, encoding="utf-8") as f:
                    for line in f:
                        m = re.match(r"^(?:totals|summary):\s+(\d+)", line)
                        if m:
                            total = int(m.group(1))
                            break
            if total is None:
                raise RuntimeError(f"no instruction total for region {k} ({names[k - 1]}) in {path}")
            counts.append(total / steps)
        return counts


def main(argv):
    ap = argparse.ArgumentParser(prog="callgrind-counts.py", description=__doc__.split("\n")[0])
    ap.add_argument("--stepcount", default=os.path.join(ROOT, "build", "bench", "adcs-stepcount"))
    ap.add_argument("--steps", type=int, default=200)
    ap.add_argument("--write")
    ap.add_argument("--check")
    args = ap.parse_args(argv[1:])
    if args.steps < 1:
        print("callgrind-counts: --steps must be >= 1", file=sys.stderr)
        return 2
    try:
        names = subprocess.run([args.stepcount, "--list"], stdout=subprocess.PIPE, text=True,
                               check=True).stdout.split()
    except (OSError, subprocess.CalledProcessError) as e:
        print(f"callgrind-counts: cannot run {args.stepcount}: {e}", file=sys.stderr)
        return 2
    committed = {}
    if args.check:
        try:
            with open(args.check, encoding="utf-8") as f:
                committed = json.load(f)["instructions_per_step"]
        except (OSError, ValueError, KeyError) as e:
            print(f"callgrind-counts: cannot read {args.check}: {e}", file=sys.stderr)
            return 2

    counts, failed = {}, False
    try:
        runs = count_each(args.stepcount, [n for n in names for _ in range(2 if args.check else 1)],
                          args.steps)
    except (OSError, RuntimeError) as e:
        print(f"callgrind-counts: {e}", file=sys.stderr)
        return 2
    for i, name in enumerate(names):
        n = runs[2 * i] if args.check else runs[i]
        counts[name] = n
        line = f"{name:<28} {n:10.1f} instructions/step"
        if args.check:
            again = runs[2 * i + 1]
            ref = committed.get(name)
            ok = again == n and ref is not None and n <= REGRESSION_MARGIN * ref
            failed = failed or not ok
            line = (f"{'PASS' if ok else 'FAIL'}  {line}  (second run {again:.1f}; committed "
                    f"{'none' if ref is None else f'{ref:.1f}'}, limit x{REGRESSION_MARGIN})")
        print(line)
    if args.write:
        doc = {"about": "instructions per step() on x86-64 (valgrind callgrind, Ir), generated by "
                        "tools/callgrind-counts.py --write; only the counted steps, see its docstring",
               "steps_per_fixture": args.steps,
               "compiler": build_compiler(args.stepcount),
               "instructions_per_step": {k: round(v, 1) for k, v in counts.items()}}
        with open(args.write, "w", encoding="utf-8") as f:
            json.dump(doc, f, indent=2)
            f.write("\n")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
