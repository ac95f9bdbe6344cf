#!/usr/bin/python3
"""Search seed 001's unreported parameters for a non-adaptive baseline of the paper's order.

usage: calibrate-seed001.py [--sim PATH] [--out CSV] [--quick]

Seed 001 omits the body inertia J, the rotor momentum h_cw, the deviation draw and the wheel
bias. Its non-adaptive baseline reaches "0.3 rad order" (R1) and "1e-3 rad/s order" (R2); ours,
on the spec's A-REF choice, 8.35e-4 rad and 3.95e-5 rad/s. This tool runs
`adcs-sim run hybrid-nonadaptive` over a grid of those four unreported choices, within what the
paper states (deviations within +-0.05 per element, its gains and poles, which are never
changed), and writes one CSV row per point: the choices, the baseline's steady errors (window
200-800 s), and the decades from R1/R2's orders. Issue 16; the grid and its result are
committed as docs/data/seed001-calibration-grid.csv and summarised in docs/DECISIONS.md.

Grid (the spec's A-REF is J_scale 1, h_cw 10 N m s, deviation D1, bias 0):
  h_cw_Nms   5, 10, 20, 40              rotor momentum per CMG
  J_scale    1, 0.5, 0.25               body inertia diag(120, 100, 80) kg m^2 times this
  deviation  D1 (seed 0), a Mode A draw (--seed 1)
  bias       0, 50, 150 rad/s           wheel bias unknown to the controller (A-BIAS: H_I_n = zero)
72 runs of 800 s at 1 ms, about 3 s each on one core.
"""
import csv
import itertools
import json
import math
import os
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
J0 = (120.0, 100.0, 80.0)


def run(sim, h, js, seed, bias):
    args = [sim, "run", "hybrid-nonadaptive", "--out", "/tmp/calibrate-seed001",
            "--set", f"h_cw_Nms={h}",
            "--set", "J_s_diag_kgm2=[" + ",".join(f"{j * js:g}" for j in J0) + "]"]
    if seed:
        args += ["--seed", str(seed)]
    if bias:
        args += ["--set", f"Omega_w0_rad_s={bias}", "--set", "H_I_n=zero"]
    p = subprocess.run(args, capture_output=True, text=True)
    if p.returncode != 0:
        return None, p.stderr.strip().splitlines()[-1] if p.stderr.strip() else f"exit {p.returncode}"
    return json.loads(p.stdout.strip().splitlines()[-1])["metrics"], ""


def decades(x, order):
    return math.log10(x / order) if x and x > 0 and math.isfinite(x) else float("nan")


def main(argv):
    sim = os.path.join(ROOT, "build", "src", "adcs-sim")
    out = os.path.join(ROOT, "docs", "data", "seed001-calibration-grid.csv")
    quick = "--quick" in argv
    if "--sim" in argv:
        sim = argv[argv.index("--sim") + 1]
    if "--out" in argv:
        out = argv[argv.index("--out") + 1]
    hs = (10, 40) if quick else (5, 10, 20, 40)
    jss = (1.0, 0.25) if quick else (1.0, 0.5, 0.25)
    seeds = (0,) if quick else (0, 1)
    biases = (0, 150) if quick else (0, 50, 150)
    rows = []
    for h, js, seed, bias in itertools.product(hs, jss, seeds, biases):
        m, err = run(sim, h, js, seed, bias)
        e = m["euler_err_ss_max_rad"] if m else float("nan")
        w = m["rate_err_ss_max_rad_s"] if m else float("nan")
        rows.append({"h_cw_Nms": h, "J_scale": js, "deviation": "D1" if seed == 0 else f"modeA-seed{seed}",
                     "wheel_bias_rad_s": bias, "euler_err_ss_max_rad": e, "rate_err_ss_max_rad_s": w,
                     "decades_from_R1_0.3rad": decades(e, 0.3), "decades_from_R2_1e-3rad_s": decades(w, 1e-3),
                     "error": err})
        print(f"h {h:>3} J x{js:<5} dev {rows[-1]['deviation']:<11} bias {bias:>3}: "
              f"{e:.3g} rad, {w:.3g} rad/s {err}", flush=True)
    os.makedirs(os.path.dirname(out), exist_ok=True)
    with open(out, "w", newline="") as f:
        wr = csv.DictWriter(f, fieldnames=list(rows[0].keys()), lineterminator="\n")
        wr.writeheader()
        for r in rows:
            wr.writerow({k: (f"{v:.6g}" if isinstance(v, float) else v) for k, v in r.items()})
    print(out)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
