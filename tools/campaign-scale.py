#!/usr/bin/python3
"""Speed and scale of adcs-sim's Monte Carlo campaigns (issue 18), measured, not asserted:

  1. runs per minute on this machine's cores for rigid-rw-mrp-pd and hybrid-adaptive (--jobs N);
  2. the speed-up of --jobs N over --jobs 1 on the same campaign (goal: >= 1.8x on 2 cores);
  3. a large campaign of the 12U cubesat file (default 10,000 runs): wall time, peak memory of
     the process (it must not grow with the number of runs beyond a few hundred bytes a run:
     compared with a campaign of a tenth of the size) and the size of its outputs.

Usage: /usr/bin/python3 tools/campaign-scale.py [--sim build/src/adcs-sim] [--runs 10000]
       [--out /tmp/adcs-scale] [--skip-large] [--skip-speed] [--speed SCENARIO=RUNS ...]
       [--jobs N] [--repeat R]
Prints a Markdown table; every number comes with the command that produced it, and the load
average before and after (a speed-up measured while other work shares the cores is not one:
--repeat keeps the fastest of R timings of each command).
"""
import argparse
import os
import shutil
import subprocess
import sys
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
CUBESAT = os.path.join(ROOT, "examples", "vehicles", "cubesat-12u.toml")
CUBESAT_DISPERSIONS = ["--disperse", "spacecraft.J_kgm2=inertia(0.1, 1)",
                       "--disperse", "wheels.axes_B=axes(0.5)",
                       "--disperse", "sensors.gyro.arw_rad_sqrt_s=rel_uniform(0.5)",
                       "--disperse", "sensors.star_tracker.dropout_probability=uniform(0, 0.2)"]


def timed(cmd):
    """(wall seconds, peak RSS in MiB) of one command, which must succeed."""
    start = time.monotonic()
    p = subprocess.Popen(cmd, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
    _, status, usage = os.wait4(p.pid, 0)
    wall = time.monotonic() - start
    err = p.stderr.read().decode(errors="replace")
    p.stderr.close()
    if os.waitstatus_to_exitcode(status) != 0:
        sys.exit(f"campaign-scale: failed ({os.waitstatus_to_exitcode(status)}): {' '.join(cmd)}\n{err[-2000:]}")
    return wall, usage.ru_maxrss / 1024.0


def size_mib(d, prefix):
    total = sum(os.path.getsize(os.path.join(d, f)) for f in os.listdir(d) if f.startswith(prefix))
    return total / (1024.0 * 1024.0)


def campaign(sim, out, target, runs, jobs, extra=()):
    shutil.rmtree(out, ignore_errors=True)
    cmd = [sim, "montecarlo", target, "--runs", str(runs), "--seed0", "1", "--jobs", str(jobs), "--out", out, *extra]
    wall, rss = timed(cmd)
    return wall, rss, " ".join(c if " " not in c else f"'{c}'" for c in cmd)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--sim", default=os.path.join(ROOT, "build", "src", "adcs-sim"))
    ap.add_argument("--runs", type=int, default=10000, help="runs of the large cubesat campaign")
    ap.add_argument("--out", default="/tmp/adcs-scale")
    ap.add_argument("--skip-large", action="store_true")
    ap.add_argument("--skip-speed", action="store_true")
    # hybrid-adaptive's runs take ~5 s each: 8 of them give each of 2 workers 4, so one slow
    # run does not decide the speed-up as it does with 4.
    ap.add_argument("--speed", action="append", metavar="SCENARIO=RUNS",
                    help="a speed campaign (repeatable; default rigid-rw-mrp-pd=40 and hybrid-adaptive=8)")
    ap.add_argument("--jobs", type=int, default=os.cpu_count() or 1, help="the parallel side (default: all cores)")
    ap.add_argument("--repeat", type=int, default=1, help="time each speed command R times, keep the fastest")
    a = ap.parse_args()
    cores = os.cpu_count() or 1
    jobs = a.jobs
    speed = []
    for spec in a.speed or ["rigid-rw-mrp-pd=40", "hybrid-adaptive=8"]:
        name, _, runs = spec.partition("=")
        if not name or not runs.isdigit() or int(runs) < 1:
            ap.error(f"--speed {spec}: expected SCENARIO=RUNS")
        speed.append((name, int(runs)))
    rows = [("load average (1, 5, 15 min) at the start", " ".join(f"{x:.2f}" for x in os.getloadavg()), "uptime")]
    for name, runs in ([] if a.skip_speed else speed):
        w1 = wn = float("inf")
        for _ in range(max(1, a.repeat)):
            w, _, c1 = campaign(a.sim, f"{a.out}/{name}-j1", name, runs, 1)
            w1 = min(w1, w)
            w, _, cn = campaign(a.sim, f"{a.out}/{name}-jn", name, runs, jobs)
            wn = min(wn, w)
        rows.append((f"{name}: runs per minute, --jobs 1", f"{60 * runs / w1:.1f}", c1))
        rows.append((f"{name}: runs per minute, --jobs {jobs}", f"{60 * runs / wn:.1f}", cn))
        rows.append((f"{name}: speed-up --jobs {jobs} / --jobs 1", f"{w1 / wn:.2f}x",
                     "the two commands above" + (f", fastest of {a.repeat} each" if a.repeat > 1 else "")))
    if not a.skip_large:
        small = max(1, a.runs // 10)
        ws, rs, cs = campaign(a.sim, f"{a.out}/cubesat-small", CUBESAT, small, jobs, CUBESAT_DISPERSIONS + ["--series", "att_err_deg"])
        wl, rl, cl = campaign(a.sim, f"{a.out}/cubesat-large", CUBESAT, a.runs, jobs, CUBESAT_DISPERSIONS + ["--series", "att_err_deg"])
        rows.append((f"cubesat-12u.toml, {small} runs: wall time", f"{ws:.0f} s", cs))
        rows.append((f"cubesat-12u.toml, {small} runs: peak memory", f"{rs:.1f} MiB", "same"))
        rows.append((f"cubesat-12u.toml, {a.runs} runs: wall time", f"{wl:.0f} s ({60 * a.runs / wl:.0f} runs/min)", cl))
        rows.append((f"cubesat-12u.toml, {a.runs} runs: peak memory", f"{rl:.1f} MiB", "same"))
        if a.runs > small:
            rows.append(("cubesat-12u.toml: peak memory per run", f"{(rl - rs) * 1024 / (a.runs - small):.2f} KiB",
                         f"(peak at {a.runs} - peak at {small}) / {a.runs - small}"))
        rows.append((f"cubesat-12u.toml, {a.runs} runs: outputs", f"{size_mib(f'{a.out}/cubesat-large', 'cubesat-12u-montecarlo'):.1f} MiB",
                     f"du of {a.out}/cubesat-large/cubesat-12u-montecarlo*"))
    rows.append(("load average (1, 5, 15 min) at the end", " ".join(f"{x:.2f}" for x in os.getloadavg()), "uptime"))
    print(f"| measure ({cores} cores) | value | command |")
    print("|---|---|---|")
    for what, value, cmd in rows:
        print(f"| {what} | {value} | `{cmd}` |")


if __name__ == "__main__":
    main()
