#!/usr/bin/env python3
"""Fail if a software-double routine is reachable from given entry points of an ARM object/ELF.

Usage: check-float-calls.py OBJDUMP FILE ROOT [ROOT ...]

Reads `OBJDUMP -dr FILE` (an object built with -ffunction-sections, or a linked ELF), builds the
call graph from branch instructions (bl/b.w/blx <sym>) and call relocations (R_ARM_THM_CALL,
R_ARM_THM_JUMP24, R_ARM_CALL, R_ARM_JUMP24), and walks it from each ROOT. On a Cortex-M4F
(single-precision FPU) any double arithmetic becomes a call to a run-time helper, so a float
step that reaches one of them is not single precision. Forbidden: the AEABI double helpers
(__aeabi_dadd, __aeabi_dmul, ..., and the conversions __aeabi_f2d, __aeabi_i2d, __aeabi_d2f, ...),
libgcc's double helpers (__adddf3, __muldf3, ...), and the double libm functions (sin, cos, sqrt,
...; their float versions sinf, cosf, sqrtf are fine). Prints each path from a root to a forbidden
routine and exits 1; exits 0 when there is none.
"""
import re
import subprocess
import sys
from collections import deque

LIBM_DOUBLE = {
    "sin", "cos", "tan", "asin", "acos", "atan", "atan2", "sinh", "cosh", "tanh", "exp", "exp2",
    "expm1", "log", "log2", "log10", "log1p", "pow", "sqrt", "cbrt", "hypot", "fmod", "remainder",
    "floor", "ceil", "round", "trunc", "fabs", "ldexp", "frexp", "modf", "fmin", "fmax", "erf", "erfc",
}
AEABI_DOUBLE = re.compile(r"^__aeabi_(d[a-z0-9]+|[a-z0-9]*2d)$")
LIBGCC_DOUBLE = re.compile(r"^__[a-z]+df[0-9]?$|^__[a-z]+2df$|^__[a-z]+df[a-z0-9]+$")


def forbidden(sym):
    return sym in LIBM_DOUBLE or AEABI_DOUBLE.match(sym) or LIBGCC_DOUBLE.match(sym)


def call_graph(objdump, path):
    out = subprocess.run([objdump, "-dr", "--no-show-raw-insn", path], check=True,
                         capture_output=True, text=True).stdout
    graph, current = {}, None
    head = re.compile(r"^[0-9a-f]+ <([^>]+)>:$")
    branch = re.compile(r"\b(bl|blx|b\.w|b)\s+[0-9a-f]+ <([^>+]+)(\+0x[0-9a-f]+)?>")
    reloc = re.compile(r"R_ARM_(THM_CALL|THM_JUMP24|THM_JUMP19|CALL|JUMP24)\s+(\S+)")
    for line in out.splitlines():
        m = head.match(line.strip())
        if m:
            current = m.group(1)
            graph.setdefault(current, set())
            continue
        if current is None:
            continue
        m = reloc.search(line)
        if m:
            graph[current].add(m.group(2))
            continue
        m = branch.search(line)
        if m and m.group(2) != current:
            graph[current].add(m.group(2))
    return graph


def main():
    if len(sys.argv) < 4:
        print(__doc__)
        return 2
    objdump, path, roots = sys.argv[1], sys.argv[2], sys.argv[3:]
    graph = call_graph(objdump, path)
    bad = 0
    for root in roots:
        if root not in graph:
            print(f"check-float-calls: entry point {root} not found in {path}")
            bad += 1
            continue
        parent, queue, seen = {root: None}, deque([root]), {root}
        reached, found = 0, 0
        while queue:
            f = queue.popleft()
            reached += 1
            for g in sorted(graph.get(f, ())):
                if g in seen:
                    continue
                seen.add(g)
                parent[g] = f
                if forbidden(g):
                    chain, x = [], g
                    while x is not None:
                        chain.append(x)
                        x = parent[x]
                    print(f"FAIL {root}: reaches {g} via " + " <- ".join(chain))
                    found += 1
                else:
                    queue.append(g)
        bad += found
        print(f"{root}: {reached} functions reachable, "
              f"{'no double routine' if found == 0 else f'{found} double routines reachable'}")
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
