#!/usr/bin/env python3
"""Instructions per function of a replay ELF on the emulated Cortex-M (a flat profile).

usage: tools/target-profile.py ELF [--machine mps2-an500] [--steps 100] [--top 40] [--callers 20]
                               [--expect NAME ...]

Debian's QEMU ships no TCG plugins, so this reads QEMU's own log instead: `-d in_asm` prints each
translated block (its guest instructions) once, `-d exec,nochain` prints every execution of a
block. Instructions per function = sum over blocks of executions x instructions, each block
charged to the function (arm-none-eabi-nm symbol) holding its first instruction; blocks are
identified by their host address, so a block QEMU re-translated with another length counts as
its own. The log is read as a stream (a 100-step seed-004 replay logs ~1 GB; nothing is stored).

The replay is run in its plain mode (`steps=N`, not `cost`), so the profile includes the replay
harness (reading rows, writing outputs: replay::run, *::outputs, _fwrite_r); tools/target-costs.py
gives the step's own totals. memcpy/memset/memmove are also charged to the function that called
them (the last other function executed before them), since GCC turns large struct and array
copies into those calls.

Used for issue 20 (docs/DECISIONS.md, "Speed"): where the seed-004 sample's instructions go on
the M7. Needs qemu-system-arm and arm-none-eabi binutils (tools/setup-deps.sh).
"""
import argparse
import bisect
import collections
import re
import shutil
import subprocess
import sys

MEM = ("memcpy", "memset", "memmove")
TRACE = re.compile(r"Trace \d+: (0x[0-9a-f]+) \[[0-9a-f]+/([0-9a-f]+)/")


def symbols(elf):
    out = subprocess.run(["arm-none-eabi-nm", "-C", "-S", "--defined-only", elf], check=True, text=True,
                         capture_output=True).stdout
    syms = []
    for line in out.splitlines():
        f = line.split(None, 3)
        if len(f) == 4 and f[2] in "tTwW":
            syms.append((int(f[0], 16), int(f[1], 16), f[3]))
    syms.sort()
    return syms


def profile(stream, syms):
    starts = [s[0] for s in syms]
    cache = {}

    def function(pc):
        if pc not in cache:
            i = bisect.bisect_right(starts, pc) - 1
            ok = i >= 0 and pc < syms[i][0] + syms[i][1]
            cache[pc] = syms[i][2] if ok else hex(pc)
        return cache[pc]

    blocks = {}  # host address -> (instructions, function)
    per_function = collections.Counter()
    mem_by_caller = collections.Counter()
    counting, n, first_pc, last = False, 0, None, None
    for line in stream:
        if line.startswith("IN:"):
            counting, n, first_pc = True, 0, None
        elif counting and line.startswith("0x"):
            if first_pc is None:
                first_pc = int(line.split(":", 1)[0], 16)
            n += 1
        elif line.startswith("Trace"):
            m = TRACE.match(line)
            if not m:
                continue
            host = m.group(1)
            if counting:  # the first execution of the block just listed
                blocks[host] = (n, function(first_pc if first_pc is not None else int(m.group(2), 16)))
                counting = False
            if host not in blocks:
                continue
            k, f = blocks[host]
            per_function[f] += k
            if f in MEM:
                mem_by_caller[(f, last)] += k
            else:
                last = f
    return per_function, mem_by_caller


def main():
    ap = argparse.ArgumentParser(prog="target-profile.py", description=__doc__.split("\n")[0])
    ap.add_argument("elf")
    ap.add_argument("--machine", default="mps2-an500", help="mps2-an500 (Cortex-M7) or mps2-an386 (M4F)")
    ap.add_argument("--steps", type=int, default=100, help="replay steps (default 100)")
    ap.add_argument("--top", type=int, default=40, help="functions to list")
    ap.add_argument("--callers", type=int, default=20, help="memcpy/memset callers to list")
    ap.add_argument("--expect", action="append", default=[],
                    help="fail unless a listed function's name contains this (repeatable; ctest)")
    args = ap.parse_args()
    qemu = shutil.which("qemu-system-arm")
    if not qemu or not shutil.which("arm-none-eabi-nm"):
        sys.exit("qemu-system-arm and arm-none-eabi binutils are needed: run tools/setup-deps.sh")
    if args.steps < 1:
        sys.exit("target-profile: --steps must be >= 1")
    syms = symbols(args.elf)
    cmd = [qemu, "-M", args.machine, "-nographic", "-monitor", "none", "-serial", "none",
           "-semihosting-config", "enable=on,target=native", "-kernel", args.elf,
           "-append", f"steps={args.steps}", "-d", "exec,nochain,in_asm", "-D", "/dev/stdout"]
    with subprocess.Popen(cmd, stdout=subprocess.PIPE, stderr=subprocess.DEVNULL, text=True) as p:
        per_function, mem_by_caller = profile(p.stdout, syms)
    if p.returncode != 0:
        sys.exit(f"target-profile: QEMU exited with {p.returncode}")
    total = sum(per_function.values())
    if total == 0:
        sys.exit("target-profile: no executed blocks in QEMU's log (is -d exec supported?)")
    print(f"# {args.elf}: {total} instructions in {args.steps} replay steps (harness included); "
          f"per step = column / {args.steps}")
    print(f"{'instructions':>12} {'per step':>9} {'share':>6}  function")
    for f, c in per_function.most_common(args.top):
        print(f"{c:12d} {c / args.steps:9.0f} {100 * c / total:5.1f}%  {f}")
    print(f"# {', '.join(MEM)} by caller")
    for (f, caller), c in mem_by_caller.most_common(args.callers):
        print(f"{c:12d} {c / args.steps:9.0f}         {f} <- {caller}")
    listed = [f for f, _ in per_function.most_common(args.top)]
    missing = [e for e in args.expect if not any(e in f for f in listed)]
    if missing:
        sys.exit(f"target-profile: not among the {args.top} listed functions: {', '.join(missing)}")


if __name__ == "__main__":
    main()
