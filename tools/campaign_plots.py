#!/usr/bin/python3
"""Figures of a Monte Carlo campaign (issue 18), from adcs-sim montecarlo's outputs in OUT_DIR:

  NAME-montecarlo-band-SERIES.png   percentile envelopes of a kept time series over the runs
                                    (NAME-montecarlo-series.h5: bands 0-100, 1-99, 5-95, 25-75 %
                                    and the median)
  NAME-montecarlo-hist.png          histograms of the metrics over the ok runs (NAME-montecarlo.csv),
                                    one panel per metric (at most 12), p5 / median / p95 marked

Usage: /usr/bin/python3 tools/campaign_plots.py OUT_DIR [NAME ...]   (default: every campaign)
Imported by tools/plot.py, which calls campaign_figures() for each NAME-montecarlo.json.
"""
import csv
import json
import math
import os
import sys

MAX_HIST = 12


def campaign_names(out_dir):
    return sorted(f[:-len("-montecarlo.json")] for f in os.listdir(out_dir) if f.endswith("-montecarlo.json"))


def _band_figure(h5, series, out_path, title):
    import matplotlib.pyplot as plt
    g = h5[series]
    t = g["t"][()]
    p = g["percentiles"][()]
    levels = list(g["levels"][()])
    runs = int(g.attrs["runs"])
    idx = {round(float(l), 6): i for i, l in enumerate(levels)}
    fig, ax = plt.subplots(figsize=(8, 4.5))
    for (lo, hi), alpha in (((0.0, 100.0), 0.15), ((1.0, 99.0), 0.25), ((5.0, 95.0), 0.35), ((25.0, 75.0), 0.5)):
        ax.fill_between(t, p[idx[lo]], p[idx[hi]], color="tab:blue", alpha=alpha, linewidth=0,
                        label=f"{lo:g}-{hi:g} %")
    ax.plot(t, p[idx[50.0]], color="tab:blue", linewidth=1.2, label="median")
    ax.set_xlabel("t [s]")
    ax.set_ylabel(series)
    if (p[idx[100.0]] > 0).all() and (p[idx[0.0]] > 0).all():
        ax.set_yscale("log")
    ax.set_title(f"{title}: {series} over {runs} runs")
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(out_path, dpi=110)
    plt.close(fig)


def _metric_columns(csv_path, meta):
    with open(csv_path, newline="") as f:
        rows = list(csv.DictReader(f))
    names = [m for m in (meta.get("metrics") or {}).keys()]
    cols = {}
    for m in names:
        vals = []
        for r in rows:
            if r.get("status") != "ok":
                continue
            try:
                v = float(r.get(m, ""))
            except ValueError:
                continue
            if math.isfinite(v):
                vals.append(v)
        if vals and max(vals) > min(vals):  # a constant metric has no histogram to show
            cols[m] = vals
    return cols


def _hist_figure(cols, out_path, title, runs):
    import matplotlib.pyplot as plt
    import numpy as np
    names = list(cols)[:MAX_HIST]
    n = len(names)
    ncol = 3 if n > 4 else 2 if n > 1 else 1
    nrow = (n + ncol - 1) // ncol
    fig, axes = plt.subplots(nrow, ncol, figsize=(4.2 * ncol, 2.8 * nrow), squeeze=False)
    for k, m in enumerate(names):
        ax = axes[k // ncol][k % ncol]
        v = np.array(cols[m])
        ax.hist(v, bins=min(40, max(5, int(math.sqrt(len(v))))), color="tab:gray")
        for q, style in ((5, ":"), (50, "-"), (95, ":")):
            ax.axvline(np.percentile(v, q), color="tab:red", linestyle=style, linewidth=1)
        ax.set_title(m, fontsize=8)
        ax.tick_params(labelsize=7)
    for k in range(n, nrow * ncol):
        axes[k // ncol][k % ncol].axis("off")
    fig.suptitle(f"{title}: metrics over {runs} runs (red: p5, median, p95)", fontsize=10)
    fig.tight_layout()
    fig.savefig(out_path, dpi=100)
    plt.close(fig)


def campaign_figures(out_dir, name):
    """Draws NAME's campaign figures; returns the written paths."""
    import matplotlib
    matplotlib.use("Agg")
    stem = os.path.join(out_dir, f"{name}-montecarlo")
    with open(stem + ".json") as f:
        meta = json.load(f)
    written = []
    h5_name = meta.get("series_file")
    if h5_name:
        import h5py
        with h5py.File(os.path.join(out_dir, h5_name), "r") as h5:
            for s in meta.get("series") or []:
                out = f"{stem}-band-{s}.png"
                _band_figure(h5, s, out, name)
                written.append(out)
    if os.path.exists(stem + ".csv"):
        cols = _metric_columns(stem + ".csv", meta)
        if cols:
            out = f"{stem}-hist.png"
            _hist_figure(cols, out, name, (meta.get("counts") or {}).get("ok", "?"))
            written.append(out)
    return written


def main(argv):
    if len(argv) < 2 or argv[1] in ("-h", "--help"):
        print(__doc__.strip())
        return 0 if len(argv) >= 2 else 2
    out_dir = argv[1]
    for name in argv[2:] or campaign_names(out_dir):
        for p in campaign_figures(out_dir, name):
            print(p)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
