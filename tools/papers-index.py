#!/usr/bin/env python3
"""Check and update docs/PAPERS.md, the index from the seed papers' equations to the code.

Format of docs/PAPERS.md (all this script reads):
  * A paper's section starts with a level-2 heading naming it, "## Seed 004 - ..."; any other
    level-2 heading ends it. Each table row in it is one equation or algorithm:
        | eq. (27) | what it is | where | notes |      or      | Algorithm 1 | ... |
  * The "where" cell (the third) holds links [path:LINE](../path#LLINE), path relative to the
    repository root, the main place first; or the words "not implemented: <reason>".
  * A link must land on a line carrying the row's tag. For eq. (N) of seed S: "seed S eq. (N)",
    or a list or range covering N: "seed S eqs. (M), (N)", "seed S eqs. (M)-(K)" (en dash too).
    For Algorithm N: the words "Algorithm N" (the seed is the section's).
  * "(untagged)" in the where cell exempts its first link (that code line has no tag yet). These
    rows are listed, generated, between the markers <!-- to-tag:begin --> and <!-- to-tag:end -->.

--check (default): exit 1, one line per problem: a link that does not resolve or whose line lacks
  the tag; an equation listed twice in a section; a row linking one line twice, or with neither a
  link nor "not implemented"; a tag in include/adcs or src (*.hpp, *.h, *.cpp) naming an equation
  that has no row, or naming it singly (not in a range) while its row says "not implemented"; an
  (untagged) row whose line now has the tag; a stale to-tag list.
--update: move each link whose line lost its tag to another line of the same file carrying it:
  single or list tags before ranges, then the nearest, then the earlier; a row's links stay
  distinct and in order. A move onto a range tag is flagged "check" (the equation's own tag may be
  gone, leaving only a file summary). An (untagged) row whose file now names the equation singly
  or in a list gets that line and loses its mark. Regenerate the to-tag list. Print each change;
  exit 1 if a tag is gone from its file (that row is left alone).
--root DIR: another checkout (default: the directory above this script's).
"""
import argparse
import re
import sys
from pathlib import Path

DOC = "docs/PAPERS.md"
SOURCES, EXTS = ("include/adcs", "src"), {".hpp", ".h", ".cpp"}
ITEM = r"\(\d+\)(?:\s*[-–]\s*\(\d+\))?"
TAG = re.compile(rf"seed (\d{{3}}) eqs?\.\s*({ITEM}(?:\s*,\s*{ITEM})*)", re.I)
PAIR = re.compile(r"\((\d+)\)(?:\s*[-–]\s*\((\d+)\))?")
ALG_TAG = re.compile(r"seed (\d{3})\s+(?:§\S+\s+)?Algorithm (\d+)", re.I)
LINK = re.compile(r"\[([^\]\s]+?):(\d+)\]\(\.\./([^)#\s]+)#L(\d+)\)")
HEAD = re.compile(r"##\s.*?\bseed (\d{3})\b", re.I)
KEY = re.compile(r"(?:eq\.\s*\((\d+)\)|Algorithm (\d+))$")
CELL = re.compile(r"(?<!\\)\|")
BEGIN, END, UNTAGGED = "<!-- to-tag:begin -->", "<!-- to-tag:end -->", "(untagged)"


def tags(line):
    """[(seed, {numbers}, is_range)] for the equation tags on one source line."""
    out = []
    for m in TAG.finditer(line):
        pairs = PAIR.findall(m.group(2))
        out.append((m.group(1), {n for a, b in pairs for n in range(int(a), int(b or a) + 1)}, any(b for _, b in pairs)))
    return out


def grade(line, row):
    """0: the line lacks the row's tag; 1: names it singly or in a list (or Algorithm N); 2: in a range only."""
    if row.kind == "alg":
        return int(re.search(rf"\bAlgorithm {row.n}(?!\d|\.\d)", line) is not None)
    found = [rng for s, nums, rng in tags(line) if s == row.seed and row.n in nums]
    return 0 if not found else 2 if all(found) else 1


def nearest(lines, row, ln, singly=False, taken=()):
    """The line carrying the row's tag, not taken: single/list before range, then nearest ln, then earlier."""
    found = [(g, abs(i - ln), i) for i, text in enumerate(lines, 1)
             if (g := grade(text, row)) and not (singly and g == 2) and i not in taken]
    return min(found)[2] if found else None


class Row:
    def __init__(self, seed, kind, n, ln, line):
        self.seed, self.kind, self.n, self.ln, self.line = seed, kind, n, ln, line
        bars = [m.start() for m in CELL.finditer(line)]
        self.span = (bars[2] + 1, bars[3]) if len(bars) >= 4 else (len(line), len(line))
        self.where = line[self.span[0]:self.span[1]]
        self.label = f"seed {seed} " + (f"eq. ({n})" if kind == "eq" else f"Algorithm {n}")


def parse(doc_lines):
    rows, problems, seed = [], [], None
    for ln, line in enumerate(doc_lines, 1):
        if line.startswith("## "):
            seed = (HEAD.match(line) or [None, None])[1]
        if seed is None or not line.lstrip().startswith("|"):
            continue
        first = CELL.split(line.strip())[1].strip()
        if m := KEY.match(first):
            rows.append(Row(seed, "eq" if m.group(1) else "alg", int(m.group(1) or m.group(2)), ln, line))
        elif re.match(r"(eqs?\b|Alg)", first, re.I):
            problems.append(f"{DOC}:{ln}: cannot read the row key {first!r} (want 'eq. (N)' or 'Algorithm N')")
    return rows, problems


def read(root, rel, cache={}):
    if (root, rel) not in cache:
        path = root / rel
        cache[root, rel] = path.read_text(encoding="utf-8").splitlines() if path.is_file() else None
    return cache[root, rel]


def to_tag_list(rows):
    firsts = [(r, LINK.search(r.where)) for r in rows if UNTAGGED in r.where]
    return [f"- `{r.label}`: {m.group(0)}" for r, m in firsts if m]


def markers(doc_lines):
    return (doc_lines.index(BEGIN), doc_lines.index(END)) if BEGIN in doc_lines and END in doc_lines else None


def resolve(root, r, problems):
    """The row's links, {link index: line} (valid ones kept, stale ones relocated) and the stale
    indices. Stale links are relocated in line order, away from the row's other lines."""
    links, untagged = list(enumerate(LINK.finditer(r.where))), UNTAGGED in r.where
    stale, new_ln = [], {}
    for j, m in links:
        rel, ln, lines = m.group(3), int(m.group(4)), read(root, m.group(3))
        if lines is None:
            problems.append(f"{r.label}: {rel} does not exist (row left unchanged)")
        elif (j or not untagged) and 1 <= ln <= len(lines) and grade(lines[ln - 1], r):
            new_ln[j] = ln
        else:
            stale.append((ln, j, rel, lines))
    for ln, j, rel, lines in sorted(stale):
        taken = {new_ln[k] for k, m in links if k in new_ln and m.group(3) == rel}
        if new := nearest(lines, r, ln, singly=(j == 0 and untagged), taken=taken):
            new_ln[j] = new
        elif not (j == 0 and untagged):
            problems.append(f"{r.label}: the tag is gone from {rel} (row left unchanged)")
    return links, new_ln, [j for _, j, _, _ in stale]


def check(root, doc_lines):
    rows, problems = parse(doc_lines)
    seen = {}
    for r in rows:
        key, links = (r.seed, r.kind, r.n), list(LINK.finditer(r.where))
        if key in seen:
            problems.append(f"{DOC}:{r.ln}: {r.label} listed twice (also line {seen[key]})")
        seen.setdefault(key, r.ln)
        if len({(m.group(3), m.group(4)) for m in links}) < len(links):
            problems.append(f"{DOC}:{r.ln}: {r.label}: two links to the same line")
        if not links and "not implemented" not in r.where:
            problems.append(f"{DOC}:{r.ln}: {r.label}: no file:line link and no 'not implemented'")
        for j, m in enumerate(links):
            rel, ln, lines = m.group(3), int(m.group(4)), read(root, m.group(3))
            where = f"{DOC}:{r.ln}: {r.label}: {rel}:{ln}"
            if (m.group(1), m.group(2)) != (rel, m.group(4)):
                problems.append(f"{where}: link text {m.group(1)}:{m.group(2)} differs from its target")
            if lines is None or not 1 <= ln <= len(lines):
                problems.append(f"{where}: " + ("no such file" if lines is None else f"the file has {len(lines)} lines"))
            elif j == 0 and UNTAGGED in r.where:
                if grade(lines[ln - 1], r) == 1:
                    problems.append(f"{where}: marked (untagged) but the line has the tag (run --update)")
            elif not grade(lines[ln - 1], r):
                moved = resolve(root, r, [])[1].get(j)
                only = " (only a range tag there)" if moved and grade(lines[moved - 1], r) == 2 else ""
                problems.append(f"{where}: the tag moved to line {moved}{only} (run --update)" if moved
                                else f"{where}: the tag is no longer in this file")
    index = {(r.seed, r.kind, r.n): r for r in rows}
    for path in (p for base in SOURCES for p in sorted((root / base).rglob("*")) if p.suffix in EXTS and p.is_file()):
        rel = path.relative_to(root).as_posix()
        for ln, line in enumerate(read(root, rel), 1):
            for seed, nums, rng in tags(line):
                for n in sorted(nums):
                    if (r := index.get((seed, "eq", n))) is None:
                        problems.append(f"{rel}:{ln}: tag 'seed {seed} eq. ({n})' has no row in {DOC}")
                    elif not rng and "not implemented" in r.where:
                        problems.append(f"{rel}:{ln}: tags {r.label} but {DOC}:{r.ln} says not implemented")
            for seed, n in ALG_TAG.findall(line):
                if (seed, "alg", int(n)) not in index:
                    problems.append(f"{rel}:{ln}: tag 'seed {seed} Algorithm {n}' has no row in {DOC}")
    span = markers(doc_lines)
    if span is None:
        problems.append(f"{DOC}: the markers {BEGIN} / {END} are missing")
    elif [x for x in doc_lines[span[0] + 1:span[1]] if x.strip()] != to_tag_list(rows):
        problems.append(f"{DOC}: the to-tag list is not current (run --update)")
    return problems


def update(root, doc_lines):
    rows, problems = parse(doc_lines)
    changes = []
    for r in rows:
        links, new_ln, stale = resolve(root, r, problems)
        where, untagged, said = r.where, UNTAGGED in r.where, []
        for j, m in reversed(links):  # from the right, so the offsets stay valid
            rel, old, n = m.group(3), int(m.group(4)), new_ln.get(j, int(m.group(4)))
            link = f"[{rel}:{n}](../{rel}#L{n})"
            if j in stale and j in new_ln:
                text = read(root, rel)[n - 1]
                note = "  (tagged now: mark dropped)" if j == 0 and untagged else (
                    "  [only a range tag: check]" if grade(text, r) == 2 else "")
                said.insert(0, f"{r.label}: {rel}:{old} -> {rel}:{n}{note}   {text.strip()[:80]}")
            elif link != m.group(0):
                said.insert(0, f"{r.label}: link text {m.group(1)}:{m.group(2)} -> {rel}:{n}")
            where = where[:m.start()] + link + where[m.end():]
        changes += said
        if untagged and 0 in new_ln and 0 in stale:
            where = re.sub(r"\s?\(untagged\)", "", where, count=1)
        doc_lines[r.ln - 1] = r.line[:r.span[0]] + where + r.line[r.span[1]:]
    span, fresh = markers(doc_lines), to_tag_list(parse(doc_lines)[0])
    if span and doc_lines[span[0] + 1:span[1]] != fresh:
        doc_lines[span[0] + 1:span[1]] = fresh
        changes.append("to-tag list regenerated")
    return changes, problems


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    mode = ap.add_mutually_exclusive_group()
    mode.add_argument("--check", action="store_true", help="verify the index (the default)")
    mode.add_argument("--update", action="store_true", help="fix moved line numbers, regenerate the to-tag list")
    ap.add_argument("--root", type=Path, default=Path(__file__).resolve().parent.parent, help="repository root")
    args = ap.parse_args()
    doc = args.root.resolve() / DOC
    if not doc.is_file():
        print(f"papers-index: {doc} not found", file=sys.stderr)
        return 1
    doc_lines = doc.read_text(encoding="utf-8").splitlines()
    if args.update:
        changes, problems = update(args.root.resolve(), doc_lines)
        if changes:
            doc.write_text("\n".join(doc_lines) + "\n", encoding="utf-8")
        print("\n".join(changes) or "papers-index: no changes")
    else:
        problems = check(args.root.resolve(), doc_lines)
        if not problems:
            print(f"papers-index: {DOC} is consistent with the code")
    for p in problems:
        print(f"papers-index: {p}", file=sys.stderr)
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
