#!/usr/bin/python3
"""Draw the plots of `adcs-sim run` outputs.

usage: plot.py OUT_DIR [NAME ...]

For each OUT_DIR/NAME.json (every *.json except *-montecarlo.json when no NAME is given)
read the CSV it names (default OUT_DIR/NAME.csv, format in docs/CONTRACTS.md) and draw
each entry of its "plots" list to OUT_DIR/<file> (PNG, 8x4.5 in, 150 dpi).

Plot spec keys (all but "file" optional):
  file     output PNG name inside OUT_DIR
  title    plot title (default: file name)
  x        x column (default "t"); x label "t [s]" from the CSV units line
  xlabel   overrides the x label
  y        list of y columns (or one name)
  ylabel   y label
  logy     log y axis;  logx: log x axis
  kind     "psd": log-log axes (spectra); x/y usually come from "csv"
           "points": markers only, no lines (sparse columns, NaN where there is no event)
  csv      read columns from this other CSV in OUT_DIR instead of the scenario's CSV
  fill     [["lo_col", "hi_col"], ...] shaded bands (e.g. prescribed-performance funnels);
           an entry may also be {"lo": ..., "hi": ..., "label": ...}
  hline    [value, "label"] or a list of them: horizontal reference lines

A JSON without "plots" (or with an empty list) gets default plots: one PNG per group of
columns sharing a prefix before a trailing _<digit> (sigma_BN_1..3 -> NAME-sigma_BN.png).

Missing columns are warned about on stderr and skipped. Prints one line per PNG written.
Exits 1 if some input could not be read (the other inputs are still processed), 2 on usage
errors, 0 otherwise. Run with /usr/bin/python3 (needs Debian's numpy and matplotlib).
"""

import json
import math
import os
import re
import sys

import campaign_plots  # tools/campaign_plots.py: Monte Carlo figures

PROG = "plot.py"
FIGSIZE = (8.0, 4.5)
DPI = 150


class InputError(Exception):
    """An input file that cannot be read or parsed."""


def warn(msg):
    print(f"{PROG}: warning: {msg}", file=sys.stderr)


def error(msg):
    print(f"{PROG}: error: {msg}", file=sys.stderr)


# --------------------------------------------------------------------------- CSV


def _split_top_level(text):
    """Split on commas that are not inside [...] (units such as [N, m] stay whole)."""
    parts, depth, cur = [], 0, []
    for ch in text:
        if ch == "[":
            depth += 1
        elif ch == "]" and depth > 0:
            depth -= 1
        if ch == "," and depth == 0:
            parts.append("".join(cur))
            cur = []
        else:
            cur.append(ch)
    parts.append("".join(cur))
    return [p.strip() for p in parts]


_UNIT_RE = re.compile(r"^(.*?)\s*\[(.*)\]\s*$")


def parse_units_line(line, names):
    """'# units: t [s], sigma_BN_1 [-]' -> {"t": "s", "sigma_BN_1": "-"}."""
    body = line.lstrip("#").strip()
    if body.lower().startswith("units:"):
        body = body[len("units:"):]
    entries = [e for e in _split_top_level(body) if e]
    units = {}
    parsed = []
    for e in entries:
        m = _UNIT_RE.match(e)
        parsed.append((m.group(1).strip(), m.group(2).strip()) if m else (e, ""))
    # Prefer matching by name; fall back to position.
    for name, unit in parsed:
        if name:
            units[name] = unit
    if len(parsed) == len(names):
        for col, (_, unit) in zip(names, parsed):
            units.setdefault(col, unit)
    return units


class Table:
    """Columns of one CSV file: names, units and float arrays."""

    def __init__(self, path):
        import numpy as np

        self.path = path
        try:
            with open(path, "r", encoding="utf-8") as f:
                lines = f.read().splitlines()
        except OSError as e:
            raise InputError(f"cannot read {path}: {e.strerror or e}") from e
        except UnicodeDecodeError as e:
            raise InputError(f"cannot read {path}: not UTF-8 text") from e
        idx = 0
        units_line = None
        while idx < len(lines) and lines[idx].lstrip().startswith("#"):
            if units_line is None and "units" in lines[idx].lower():
                units_line = lines[idx]
            idx += 1
        if idx >= len(lines):
            raise InputError(f"{path}: no column-name line")
        self.names = [n.strip() for n in lines[idx].split(",")]
        if not any(self.names):
            raise InputError(f"{path}: empty column-name line")
        idx += 1
        self.units = parse_units_line(units_line, self.names) if units_line else {}
        rows = []
        ncol = len(self.names)
        for lineno, raw in enumerate(lines[idx:], start=idx + 1):
            s = raw.strip()
            if not s or s.startswith("#"):
                continue
            fields = s.split(",")
            if len(fields) != ncol:
                raise InputError(
                    f"{path}:{lineno}: {len(fields)} fields, expected {ncol}")
            row = []
            for fld in fields:
                fld = fld.strip()
                if fld == "" or fld.lower() in ("nan", "-nan", "null", "none"):
                    row.append(math.nan)
                    continue
                try:
                    row.append(float(fld))
                except ValueError as e:
                    raise InputError(f"{path}:{lineno}: not a number: {fld!r}") from e
            rows.append(row)
        data = np.array(rows, dtype=float).reshape(len(rows), ncol)
        self.columns = {}
        for i, n in enumerate(self.names):
            self.columns.setdefault(n, data[:, i])
        self.nrows = len(rows)

    def has(self, name):
        return name in self.columns

    def label(self, name):
        unit = self.units.get(name, "")
        return f"{name} [{unit}]" if unit else name


def read_header(path):
    """(names, units) of a CSV from its first lines only (cheap; used by report.py)."""
    try:
        with open(path, "r", encoding="utf-8") as f:
            units_line = None
            for line in f:
                if line.lstrip().startswith("#"):
                    if units_line is None and "units" in line.lower():
                        units_line = line
                    continue
                names = [n.strip() for n in line.strip().split(",")]
                return names, (parse_units_line(units_line, names) if units_line else {})
    except (OSError, UnicodeDecodeError) as e:
        raise InputError(f"cannot read {path}: {e}") from e
    raise InputError(f"{path}: no column-name line")


# ------------------------------------------------------------------ plot specs

_GROUP_RE = re.compile(r"^(.+?)_(\d+)$")


def _safe_file_part(s):
    return re.sub(r"[^A-Za-z0-9_.+-]+", "_", s).strip("_") or "col"


def default_specs(name, names, units, x="t"):
    """One spec per group of columns sharing a prefix before a trailing _<digit>."""
    groups = {}
    order = []
    for col in names:
        if not col or col == x:
            continue
        m = _GROUP_RE.match(col)
        key = m.group(1) if m else col
        if key not in groups:
            groups[key] = []
            order.append(key)
        groups[key].append(col)
    specs = []
    used_files = set()
    for key in order:
        cols = groups[key]
        col_units = []
        for c in cols:
            u = units.get(c, "")
            if u not in col_units:
                col_units.append(u)
        col_units = [u for u in col_units if u]
        ylabel = f"{key} [{', '.join(col_units)}]" if col_units else key
        fname = f"{name}-{_safe_file_part(key)}.png"
        n = 2
        while fname in used_files:
            fname = f"{name}-{_safe_file_part(key)}-{n}.png"
            n += 1
        used_files.add(fname)
        specs.append({"file": fname, "title": f"{name}: {key}", "x": x,
                      "y": cols, "ylabel": ylabel, "logy": False})
    return specs


def csv_name_for(name, meta):
    c = meta.get("csv") if isinstance(meta, dict) else None
    return c if isinstance(c, str) and c else f"{name}.csv"


def specs_for(out_dir, name, meta):
    """The plot specs of one scenario JSON: its "plots", or the defaults from its CSV header.

    Raises InputError if defaults are needed and the CSV header cannot be read.
    """
    plots = meta.get("plots") if isinstance(meta, dict) else None
    if isinstance(plots, list) and plots:
        return [p for p in plots if isinstance(p, dict)]
    names, units = read_header(os.path.join(out_dir, csv_name_for(name, meta)))
    return default_specs(name, names, units)


def _as_list(v):
    if v is None:
        return []
    if isinstance(v, (list, tuple)):
        return list(v)
    return [v]


def _hlines(v):
    """hline: 0.1 | [0.1, "label"] | [[0.1, "a"], [0.2, "b"]] | [{"value":..,"label":..}]."""
    out = []
    if v is None:
        return out
    if isinstance(v, (int, float)) and not isinstance(v, bool):
        return [(float(v), None)]
    if isinstance(v, dict):
        v = [v]
    if isinstance(v, list) and v and isinstance(v[0], (int, float)) \
            and not isinstance(v[0], bool):
        v = [v]
    for item in v if isinstance(v, list) else []:
        if isinstance(item, dict) and isinstance(item.get("value"), (int, float)):
            out.append((float(item["value"]), item.get("label")))
        elif isinstance(item, (int, float)) and not isinstance(item, bool):
            out.append((float(item), None))
        elif isinstance(item, list) and item and isinstance(item[0], (int, float)):
            out.append((float(item[0]), str(item[1]) if len(item) > 1 else None))
        else:
            warn(f"ignoring malformed hline entry {item!r}")
    return out


def _fills(v):
    out = []
    for item in _as_list(v):
        if isinstance(item, dict) and "lo" in item and "hi" in item:
            out.append((str(item["lo"]), str(item["hi"]), item.get("label")))
        elif isinstance(item, (list, tuple)) and len(item) >= 2:
            out.append((str(item[0]), str(item[1]), str(item[2]) if len(item) > 2 else None))
        else:
            warn(f"ignoring malformed fill entry {item!r}")
    return out


# ---------------------------------------------------------------------- drawing


def draw(spec, table, out_path, where):
    """Draw one spec from `table` to out_path. Returns True if a PNG was written."""
    import numpy as np
    import matplotlib.pyplot as plt

    xcol = spec.get("x") or "t"
    if not isinstance(xcol, str):
        warn(f"{where}: \"x\" is not a column name; skipped")
        return False
    if not table.has(xcol):
        warn(f"{where}: x column '{xcol}' not in {os.path.basename(table.path)}; skipped")
        return False
    x = table.columns[xcol]
    if table.nrows == 0:
        warn(f"{where}: {os.path.basename(table.path)} has no data rows; empty plot")
    psd = spec.get("kind") == "psd"
    logx = bool(spec.get("logx")) or psd
    logy = bool(spec.get("logy")) or psd

    fig, ax = plt.subplots(figsize=FIGSIZE)
    n_items = 0
    n_data = 0
    # Bands first so that curves are drawn over them.
    for k, (lo, hi, label) in enumerate(_fills(spec.get("fill"))):
        missing = [c for c in (lo, hi) if not table.has(c)]
        if missing:
            warn(f"{where}: fill column(s) {', '.join(missing)} not in "
                 f"{os.path.basename(table.path)}; band skipped")
            continue
        color = f"C{k % 10}"
        ax.fill_between(x, table.columns[lo], table.columns[hi], color=color,
                        alpha=0.18, linewidth=0, label=label or f"{lo} .. {hi}")
        ax.plot(x, table.columns[lo], color=color, lw=0.6, alpha=0.6)
        ax.plot(x, table.columns[hi], color=color, lw=0.6, alpha=0.6)
        n_items += 1
        n_data += 1
    ycols = [str(c) for c in _as_list(spec.get("y"))]
    nfill = n_items
    for k, col in enumerate(ycols):
        if not table.has(col):
            warn(f"{where}: column '{col}' not in {os.path.basename(table.path)}; "
                 "curve skipped")
            continue
        y = table.columns[col]
        if logy:
            y = np.where(y > 0, y, np.nan)
        ci = k + nfill  # beyond 10 curves the colours repeat: vary the line style
        if spec.get("kind") == "points":
            ax.plot(x, y, ls="none", marker=".", ms=3, color=f"C{ci % 10}", label=col)
        else:
            ax.plot(x, y, lw=1.2, color=f"C{ci % 10}", ls=("-", "--", ":", "-.")[(ci // 10) % 4],
                    label=col)
        n_items += 1
        n_data += 1
    if n_data == 0:
        plt.close(fig)
        warn(f"{where}: nothing to draw; {os.path.basename(out_path)} not written")
        return False
    for value, label in _hlines(spec.get("hline")):
        ax.axhline(value, color="0.25", ls="--", lw=0.9,
                   label=label if label else f"{value:g}")
        n_items += 1

    if logx:
        ax.set_xscale("log", nonpositive="mask")
    if logy:
        ax.set_yscale("log", nonpositive="mask")
    ax.set_xlabel(spec.get("xlabel") or table.label(xcol))
    ylabel = spec.get("ylabel")
    if not ylabel and len(ycols) == 1:
        ylabel = table.label(ycols[0])
    if ylabel:
        ax.set_ylabel(str(ylabel))
    ax.set_title(str(spec.get("title") or os.path.splitext(os.path.basename(out_path))[0]))
    ax.grid(True, which="major", alpha=0.45)
    if logx or logy:
        ax.grid(True, which="minor", alpha=0.15)
    if n_items > 8:
        # Many entries: legend outside on the right so it cannot hide data.
        ax.legend(loc="upper left", bbox_to_anchor=(1.01, 1.0), fontsize="small",
                  ncol=1 if n_items <= 16 else 2, frameon=False)
    else:
        ax.legend(loc="best", fontsize="small", framealpha=0.8)
    fig.tight_layout()
    # No volatile metadata: identical inputs give identical files.
    fig.savefig(out_path, dpi=DPI, format="png", metadata={"Software": None})
    plt.close(fig)
    return True


# ------------------------------------------------------------------------- main


def load_json(path):
    try:
        with open(path, "r", encoding="utf-8") as f:
            meta = json.load(f)
    except OSError as e:
        raise InputError(f"cannot read {path}: {e.strerror or e}") from e
    except (ValueError, UnicodeDecodeError) as e:
        raise InputError(f"{path}: invalid JSON: {e}") from e
    if not isinstance(meta, dict):
        raise InputError(f"{path}: top level is not a JSON object")
    return meta


def list_names(out_dir):
    names = []
    for fn in sorted(os.listdir(out_dir)):
        if fn.endswith(".json") and not fn.endswith("-montecarlo.json"):
            names.append(fn[:-len(".json")])
    return names


def process(out_dir, name):
    """Plot one scenario. Returns True if all its inputs were readable."""
    meta = load_json(os.path.join(out_dir, name + ".json"))
    main_csv = csv_name_for(name, meta)
    tables = {}

    def table(fn):
        if fn not in tables:
            tables[fn] = Table(os.path.join(out_dir, fn))
        return tables[fn]

    plots = meta.get("plots")
    if plots is not None and not isinstance(plots, list):
        warn(f"{name}.json: \"plots\" is not a list; using default plots")
        plots = None
    if plots:
        specs = plots
    else:
        t = table(main_csv)
        specs = default_specs(name, t.names, t.units)
    ok = True
    for i, spec in enumerate(specs):
        where = f"{name}.json plots[{i}]"
        if not isinstance(spec, dict):
            warn(f"{where}: not an object; skipped")
            continue
        fn = spec.get("file")
        if not isinstance(fn, str) or not fn:
            fn = f"{name}-{i + 1}.png"
            warn(f"{where}: no \"file\"; writing {fn}")
        if os.path.basename(fn) != fn:
            warn(f"{where}: file {fn!r} is not a plain file name; using its base name")
            fn = os.path.basename(fn)
        src = spec.get("csv") if isinstance(spec.get("csv"), str) else main_csv
        try:
            t = table(src)
        except InputError as e:
            error(f"{where}: {e}")
            ok = False
            continue
        out_path = os.path.join(out_dir, fn)
        if draw(spec, t, out_path, where):
            print(out_path)
            sys.stdout.flush()
    return ok


def main(argv):
    if len(argv) >= 2 and argv[1] in ("-h", "--help"):
        print(__doc__.strip())
        return 0
    if len(argv) < 2:
        print("usage: plot.py OUT_DIR [NAME ...]", file=sys.stderr)
        return 2
    out_dir = argv[1]
    if not os.path.isdir(out_dir):
        error(f"{out_dir}: not a directory")
        return 1
    names = argv[2:]
    if not names:
        names = list_names(out_dir)
        if not names:
            warn(f"no scenario JSON in {out_dir}")
    import matplotlib
    matplotlib.use("Agg")
    status = 0
    for name in names:
        if name.endswith(".json"):
            name = name[:-len(".json")]
        try:
            if name.endswith("-montecarlo"):
                for p in campaign_plots.campaign_figures(out_dir, name[:-len("-montecarlo")]):
                    print(p)
            elif not process(out_dir, name):
                status = 1
        except InputError as e:
            error(str(e))
            status = 1
    if not argv[2:]:  # every campaign too (band plots, histograms: tools/campaign_plots.py)
        for name in campaign_plots.campaign_names(out_dir):
            for p in campaign_plots.campaign_figures(out_dir, name):
                print(p)
    return status


if __name__ == "__main__":
    sys.exit(main(sys.argv))
