#!/usr/bin/python3
"""Summarise `adcs-sim run` outputs in OUT_DIR/REPORT.md.

usage: report.py [--check] OUT_DIR

Reads every OUT_DIR/*.json (format in docs/CONTRACTS.md, "Output files") and writes
OUT_DIR/REPORT.md: a summary line, the paper-claims table ("kind": "paper"), the
harness-checks table ("kind": "check"), then per scenario its metrics, seed, parameters and
plots. The file carries no date, so identical inputs give an identical report.

A paper claim carries two verdicts that are never blurred (issue 16): "paper_verdict"
(reproduced / partly / not reproduced, against the paper's own number, "paper_value") and
"criterion_holds" (our documented "criterion" and its source). The summary counts both.

Exit status: 0; 1 with --check if any claim's criterion does not hold; 2 on usage errors or if a
JSON could not be read (the report is still written, listing the unreadable files).
Run with /usr/bin/python3 (standard library only; uses tools/plot.py to name default plots).
"""

import json
import math
import os
import sys

sys.dont_write_bytecode = True  # keep tools/ free of __pycache__
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import plot  # noqa: E402  (same directory; only its stdlib parts are used here)

PROG = "report.py"
CLAIM_HEADER = ("| scenario | paper claim | the paper's own value | ours | paper verdict "
                "| our criterion (source) | criterion holds? |")
CLAIM_RULE = "|---|---|---|---|---|---|---|"
# Harness checks are ours, not a paper's: no paper verdict.
CHECK_HEADER = "| scenario | check | required | ours | holds? |"
CHECK_RULE = "|---|---|---|---|---|"
VERDICTS = ("reproduced", "partly", "not reproduced")


def warn(msg):
    print(f"{PROG}: warning: {msg}", file=sys.stderr)


def fmt_num(v):
    if isinstance(v, bool):
        return "true" if v else "false"
    if isinstance(v, int):
        return str(v)
    if isinstance(v, float):
        if math.isnan(v):
            return "nan"
        return "%.6g" % v
    return str(v)


def fmt_value(v):
    """Parameter/metric value: numbers %.6g, lists [a, b], nested lists [[..], [..]]."""
    if v is None:
        return "n/a"
    if isinstance(v, (list, tuple)):
        return "[" + ", ".join(fmt_value(x) for x in v) + "]"
    if isinstance(v, dict):
        return "{" + ", ".join(f"{k}: {fmt_value(x)}" for k, x in v.items()) + "}"
    return fmt_num(v)


def cell(v):
    """Text safe inside a markdown table cell."""
    if v is None:
        s = ""
    elif isinstance(v, str):
        s = v
    else:
        s = fmt_value(v)
    s = " ".join(s.split())
    return s.replace("|", "\\|")


def criterion_of(c):
    """criterion_holds, falling back to holds (outputs written before issue 16)."""
    return c["criterion_holds"] if "criterion_holds" in c else c.get("holds")


def holds_text(h):
    if h is True:
        return "yes"
    if h is False:
        return "**NO**"
    return "n/a"


def verdict_text(v):
    if v == "reproduced":
        return "reproduced"
    if v in ("partly", "not reproduced"):
        return f"**{v}**"
    return "not judged"


def md_alt(s):
    return " ".join(str(s).split()).replace("[", "(").replace("]", ")")


class Scenario:
    def __init__(self, stem, meta):
        self.stem = stem
        self.meta = meta
        sc = meta.get("scenario")
        self.name = sc if isinstance(sc, str) and sc else stem

    def claims(self, kind):
        out = []
        for c in self.meta.get("claims") or []:
            if isinstance(c, dict) and c.get("kind") == kind:
                out.append(c)
        return out

    def all_claims(self):
        return [c for c in (self.meta.get("claims") or []) if isinstance(c, dict)]


def load(out_dir):
    scenarios, unreadable = [], []
    def order(fn):  # NAME-montecarlo.json right after NAME.json
        stem = fn[:-len(".json")]
        mc = stem.endswith("-montecarlo")
        return (stem[:-len("-montecarlo")] if mc else stem, mc)

    for fn in sorted((f for f in os.listdir(out_dir) if f.endswith(".json")), key=order):
        path = os.path.join(out_dir, fn)
        try:
            meta = plot.load_json(path)
        except plot.InputError as e:
            print(f"{PROG}: error: {e}", file=sys.stderr)
            unreadable.append((fn, str(e)))
            continue
        claims = meta.get("claims")
        if claims is not None and not isinstance(claims, list):
            warn(f"{fn}: \"claims\" is not a list; ignored")
            meta["claims"] = []
        scenarios.append(Scenario(fn[:-len(".json")], meta))
    return scenarios, unreadable


def claims_table(lines, scenarios, kind, empty_note):
    paper = kind == "paper"
    lines.append(CLAIM_HEADER if paper else CHECK_HEADER)
    lines.append(CLAIM_RULE if paper else CHECK_RULE)
    n = 0
    for s in scenarios:
        for c in s.claims(kind):
            claim = c.get("claim")
            if c.get("note"):
                claim = f"{claim} ({c.get('note')})"
            row = [cell(s.name), cell(claim), cell(c.get("paper_value")), cell(c.get("ours"))]
            if paper:
                row += [verdict_text(c.get("paper_verdict")), cell(c.get("criterion")),
                        holds_text(criterion_of(c))]
            else:
                row.append(holds_text(criterion_of(c)))
            lines.append("| " + " | ".join(row) + " |")
            n += 1
    if n == 0:
        lines.append("")
        lines.append(empty_note)
    lines.append("")


def scenario_section(lines, out_dir, s):
    meta = s.meta
    title = s.name if s.name == s.stem else f"{s.name} (`{s.stem}.json`)"
    lines.append(f"### {title}")
    lines.append("")
    desc = meta.get("description")
    if isinstance(desc, str) and desc.strip():
        lines.append(" ".join(desc.split()))
        lines.append("")
    lines.append(f"- seed: {fmt_value(meta.get('seed'))}")
    csv = meta.get("csv")
    if isinstance(csv, str) and csv:
        lines.append(f"- data: [{csv}]({csv})")
    lines.append("")

    metrics = meta.get("metrics")
    lines.append("| metric | value |")
    lines.append("|---|---|")
    if isinstance(metrics, dict) and metrics:
        for k, v in metrics.items():
            lines.append(f"| {cell(k)} | {cell(fmt_value(v))} |")
    else:
        lines.append("| (none) | |")
    lines.append("")

    params = meta.get("parameters")
    if isinstance(params, dict) and params:
        lines.append("Parameters:")
        lines.append("")
        for k, p in params.items():
            if isinstance(p, dict):
                val = fmt_value(p.get("value"))
                unit = p.get("unit")
                unit = f" {unit}" if isinstance(unit, str) and unit not in ("", "-") else ""
                src = p.get("source")
                src = f" ({' '.join(src.split())})" if isinstance(src, str) and src else ""
                lines.append(f"- `{k}` = {val}{unit}{src}")
            else:
                lines.append(f"- `{k}` = {fmt_value(p)}")
        lines.append("")

    # Plots: the JSON's specs, or the defaults tools/plot.py derives from the CSV header.
    specs = []
    try:
        specs = plot.specs_for(out_dir, s.stem, meta)
    except plot.InputError as e:
        if meta.get("plots") or not s.stem.endswith("-montecarlo"):
            warn(f"{s.stem}.json: no plots listed: {e}")
    imgs = []
    for spec in specs:
        fn = spec.get("file")
        if not isinstance(fn, str) or not fn:
            continue
        fn = os.path.basename(fn)
        alt = md_alt(spec.get("title") or fn)
        if os.path.isfile(os.path.join(out_dir, fn)):
            imgs.append(f"![{alt}]({fn})")
        else:
            imgs.append(f"- `{fn}` ({alt}): not generated; run `tools/plot.py`")
    if imgs:
        lines.append("Plots:")
        lines.append("")
        for img in imgs:
            lines.append(img)
            lines.append("")


def campaign_section(lines, out_dir, c):
    """A Monte Carlo campaign (issue 18): counts, per-metric statistics, per-claim pass counts,
    the worst runs with the command that reruns each alone, and the band plots and histograms."""
    m = c.meta
    counts = m.get("counts") or {}
    lines.append(f"### {m.get('scenario', c.stem)}: {m.get('runs')} runs")
    lines.append("")
    lines.append(f"- campaign `{m.get('campaign_id')}`, seed0 {m.get('seed0')}; "
                 f"{counts.get('ok', 0)} ok, {counts.get('invalid', 0)} invalid, {counts.get('failed', 0)} failed")
    for d in m.get("dispersions") or []:
        lines.append(f"- `--disperse {d}`")
    for st in m.get("sets") or []:
        lines.append(f"- `--set {st}`")
    if m.get("csv"):
        lines.append(f"- data: [{m['csv']}]({m['csv']})" + (f", envelopes: `{m['series_file']}`" if m.get("series_file") else ""))
    lines.append("")
    claims = m.get("claims") or []
    if claims:
        lines.append("| claim | over the runs |")
        lines.append("|---|---|")
        for cl in claims:
            lines.append(f"| {cell(cl.get('claim'))} | {cell(cl.get('summary'))} |")
        lines.append("")
    metrics = m.get("metrics") or {}
    if metrics:
        cols = ["min", "p1", "p5", "median", "p95", "p99", "max", "mean", "std"]
        lines.append("| metric | " + " | ".join(cols) + " | non-finite |")
        lines.append("|---|" + "---|" * (len(cols) + 1))
        for k, v in metrics.items():
            if not isinstance(v, dict):
                continue
            lines.append(f"| {cell(k)} | " + " | ".join(cell(fmt_value(v.get(q))) for q in cols) + f" | {v.get('nonfinite', 0)} |")
        lines.append("")
    worst = (m.get("worst_runs") or {})
    if worst.get("runs"):
        lines.append(f"Worst runs by `{worst.get('metric')}` (each reruns alone with its command):")
        lines.append("")
        for w in worst["runs"]:
            lines.append(f"- run {w.get('run')}: {fmt_value(w.get('value'))} — `{w.get('command')}`")
        lines.append("")
    failed = m.get("failed_runs") or []
    if failed:
        lines.append("Invalid and failed runs:")
        lines.append("")
        for f in failed:
            lines.append(f"- run {f.get('run')} ({f.get('status')}): {' '.join(str(f.get('error')).split())} — `{f.get('command')}`")
        lines.append("")
    figs = sorted(fn for fn in os.listdir(out_dir) if fn.startswith(c.stem + "-") and fn.endswith(".png"))
    for fn in figs:
        lines.append(f"![{md_alt(fn)}]({fn})")
        lines.append("")


def build(out_dir):
    everything, unreadable = load(out_dir)
    campaigns = [s for s in everything if s.stem.endswith("-montecarlo")]
    scenarios = [s for s in everything if not s.stem.endswith("-montecarlo")]
    claims = [c for s in scenarios for c in s.all_claims()]
    n = len(claims)
    n_yes = sum(1 for c in claims if criterion_of(c) is True)
    n_no = sum(1 for c in claims if criterion_of(c) is False)
    n_na = n - n_yes - n_no
    paper = [c for c in claims if c.get("kind") == "paper"]
    n_verdict = {v: sum(1 for c in paper if c.get("paper_verdict") == v) for v in VERDICTS}
    n_unjudged = len(paper) - sum(n_verdict.values())

    lines = ["# adcs simulation report", ""]
    lines.append("Generated by `tools/report.py` from the `adcs-sim run NAME --out DIR` outputs "
                 "(`NAME.json`, `NAME.csv`, plots by `tools/plot.py`) in this directory.")
    lines.append("")
    summary = (f"**Summary: paper: {n_verdict['reproduced']} reproduced, {n_verdict['partly']} partly, "
               f"{n_verdict['not reproduced']} not reproduced")
    summary += f", {n_unjudged} not judged" if n_unjudged else ""
    summary += f" (of {len(paper)} paper claims); criteria: {n} claims, {n_yes} hold, {n_no} do not"
    summary += f", {n_na} n/a.**" if n_na else ".**"
    summary += f" Scenarios: {len(scenarios)}." + (f" Campaigns: {len(campaigns)}." if campaigns else "")
    lines.append(summary)
    lines.append("")
    if unreadable:
        lines.append("**Unreadable inputs:**")
        lines.append("")
        for fn, msg in unreadable:
            lines.append(f"- `{fn}`: {' '.join(msg.split())}")
        lines.append("")

    lines.append("## Paper claims")
    lines.append("")
    claims_table(lines, scenarios, "paper",
                 "No paper scenarios are registered yet; the machinery is in place "
                 "(claims with `\"kind\": \"paper\"` appear here).")
    lines.append("## Harness checks")
    lines.append("")
    claims_table(lines, scenarios, "check",
                 "No harness checks reported (claims with `\"kind\": \"check\"` appear here).")
    other = sorted({str(c.get("kind")) for c in claims} - {"paper", "check"})
    if other:
        lines.append(f"Claims of other kinds ({', '.join(other)}) are counted in the summary "
                     "but not tabulated.")
        lines.append("")

    lines.append("## Scenario metrics")
    lines.append("")
    if not scenarios:
        lines.append("No scenario outputs found.")
        lines.append("")
    for s in scenarios:
        scenario_section(lines, out_dir, s)
    if campaigns:
        lines.append("## Campaigns")
        lines.append("")
        for c in campaigns:
            campaign_section(lines, out_dir, c)
    while lines and lines[-1] == "":
        lines.pop()
    return "\n".join(lines) + "\n", n_no, bool(unreadable)


def main(argv):
    args = argv[1:]
    if any(a in ("-h", "--help") for a in args):
        print(__doc__.strip())
        return 0
    check = "--check" in args
    rest = [a for a in args if a != "--check"]
    if len(rest) != 1 or rest[0].startswith("-"):
        print("usage: report.py [--check] OUT_DIR", file=sys.stderr)
        return 2
    out_dir = rest[0]
    if not os.path.isdir(out_dir):
        print(f"{PROG}: error: {out_dir}: not a directory", file=sys.stderr)
        return 2
    text, n_no, bad_input = build(out_dir)
    path = os.path.join(out_dir, "REPORT.md")
    with open(path, "w", encoding="utf-8") as f:
        f.write(text)
    print(path)
    if bad_input:
        return 2
    if check and n_no:
        print(f"{PROG}: {n_no} claim(s) do not hold", file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
