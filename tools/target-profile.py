#!/usr/bin/env python3
"""Instructions per function of a replay ELF on the emulated Cortex-M (a flat profile).

usage: tools/target-profile.py ELF [--machine mps2-an500] [--steps 100] [--subtract K] [--top 40]
                               [--callers 20] [--mix] [--expect NAME ...]

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
copies into those calls. --mix adds each function's instructions by class (floating-point
arithmetic, multiply-accumulate, division, loads and stores, moves, integer work, branches): the
arithmetic is the algorithm's own work, the rest what the implementation adds to it.
--subtract K runs a second replay of K steps and prints the difference, per step of the
N − K steps: the step's own figures, without the construction and start-up (the harness's
per-step reading and writing stay in; they are the replay::* and _fwrite_r lines).

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

    blocks = {}  # host address -> (instructions, function, Counter of instruction classes)
    per_function = collections.Counter()
    mem_by_caller = collections.Counter()
    mix = collections.defaultdict(collections.Counter)  # function -> instruction class -> executed
    counting, n, first_pc, last, classes = False, 0, None, None, None
    for line in stream:
        if line.startswith("IN:"):
            counting, n, first_pc, classes = True, 0, None, collections.Counter()
        elif counting and line.startswith("0x"):
            if first_pc is None:
                first_pc = int(line.split(":", 1)[0], 16)
            n += 1
            classes[instruction_class(line)] += 1
        elif line.startswith("Trace"):
            m = TRACE.match(line)
            if not m:
                continue
            host = m.group(1)
            if counting:  # the first execution of the block just listed
                blocks[host] = (n, function(first_pc if first_pc is not None else int(m.group(2), 16)), classes)
                counting = False
            if host not in blocks:
                continue
            k, f, cls = blocks[host]
            per_function[f] += k
            mix[f].update(cls)
            if f in MEM:
                mem_by_caller[(f, last)] += k
            else:
                last = f
    return per_function, mem_by_caller, mix


# Instruction classes of --mix, from the mnemonic in QEMU's in_asm listing
# ("0x000000a0:  3b01       subs     r3, #1"). The floating-point arithmetic is the algorithm's own
# work, which no rearrangement of the code removes; everything else (loads and stores, register
# moves, loop control) is what an implementation adds to it. GCC emits VMLA/VMLS even with
# -ffp-contract=off (they round after the multiply: the same bits as a multiply and an add), so a
# multiply-accumulate is one instruction and two operations; it has its own class.
FP_LOAD_STORE = ("vldr", "vstr", "vldm", "vstm", "vpush", "vpop")
FP_MAC = ("vmla", "vmls", "vnmla", "vnmls", "vfma", "vfms", "vfnma", "vfnms")
FP_ARITH = ("vadd", "vsub", "vmul", "vnmul")
FP_DIV = ("vdiv", "vsqrt")
ASM = re.compile(r"0x[0-9a-f]+:\s+[0-9a-f]{4}(?: [0-9a-f]{4})?\s+(\S+)")


def instruction_class(line):
    m = ASM.match(line)  # the mnemonic follows one (Thumb-16) or two (Thumb-32) encoding halves
    op = m.group(1) if m else ""
    if op.startswith("v"):
        base, _, kind = op.partition(".")
        width = " f32" if kind == "f32" else " f64"
        if base.startswith(FP_LOAD_STORE):
            return "fp load/store"
        if base in FP_MAC:
            return "fp multiply-accumulate" + width
        if base in FP_ARITH:
            return "fp add/sub/mul" + width
        if base in FP_DIV:
            return "fp div/sqrt" + width
        if base.startswith(("vmov", "vsel")):
            return "fp move/select"
        return "fp other (cmp, abs, neg, cvt, vmrs)"
    if op.startswith(("ldr", "ldm", "pop", "str", "stm", "push")):
        return "integer load/store"
    if op.startswith(("b", "cb", "tb", "it")) and not op.startswith(("bic", "bfc", "bfi")):
        return "branch"
    return "integer other"


def print_mix(per_function, mix, top, steps):
    """Per step, by instruction class: all functions, then each of the top ones."""
    names = sorted({c for m in mix.values() for c in m})
    total = collections.Counter()
    for m in mix.values():
        total.update(m)
    print("# instruction mix per step (all functions, harness included)")
    for c in names:
        print(f"{total[c] / steps:12.0f}  {c}")
    print("# instruction mix per step of the listed functions: " + " | ".join(names))
    for f, _ in per_function.most_common(top):
        print(" ".join(f"{mix[f][c] / steps:7.0f}" for c in names) + f"  {f}")


def run(qemu, elf, machine, steps, syms):
    """The profile of one replay of `steps` steps: (per function, memcpy/memset by caller, mix)."""
    cmd = [qemu, "-M", machine, "-nographic", "-monitor", "none", "-serial", "none",
           "-semihosting-config", "enable=on,target=native", "-kernel", elf,
           "-append", f"steps={steps}", "-d", "exec,nochain,in_asm", "-D", "/dev/stdout"]
    with subprocess.Popen(cmd, stdout=subprocess.PIPE, stderr=subprocess.DEVNULL, text=True) as p:
        result = profile(p.stdout, syms)
    if p.returncode != 0:
        sys.exit(f"target-profile: QEMU exited with {p.returncode}")
    return result


def subtract(a, b):
    """a − b for the three counters of run(); the mix per function."""
    per_function = collections.Counter(a[0])
    per_function.subtract(b[0])
    mem = collections.Counter(a[1])
    mem.subtract(b[1])
    mix = collections.defaultdict(collections.Counter)
    for f, m in a[2].items():
        mix[f].update(m)
        mix[f].subtract(b[2].get(f, collections.Counter()))
    return per_function, mem, mix


def main():
    ap = argparse.ArgumentParser(prog="target-profile.py", description=__doc__.split("\n")[0])
    ap.add_argument("elf")
    ap.add_argument("--machine", default="mps2-an500", help="mps2-an500 (Cortex-M7) or mps2-an386 (M4F)")
    ap.add_argument("--steps", type=int, default=100, help="replay steps (default 100)")
    ap.add_argument("--subtract", type=int, default=0, metavar="K",
                    help="also run K < steps steps and print the difference: the steps' own figures, "
                         "construction and start-up left out")
    ap.add_argument("--top", type=int, default=40, help="functions to list")
    ap.add_argument("--callers", type=int, default=20, help="memcpy/memset callers to list")
    ap.add_argument("--mix", action="store_true",
                    help="also print each listed function's instructions by class (fp arithmetic, loads, ...)")
    ap.add_argument("--expect", action="append", default=[],
                    help="fail unless a listed function's name contains this (repeatable; ctest)")
    args = ap.parse_args()
    qemu = shutil.which("qemu-system-arm")
    if not qemu or not shutil.which("arm-none-eabi-nm"):
        sys.exit("qemu-system-arm and arm-none-eabi binutils are needed: run tools/setup-deps.sh")
    if args.steps < 1 or not 0 <= args.subtract < args.steps:
        sys.exit("target-profile: --steps must be >= 1 and 0 <= --subtract < --steps")
    syms = symbols(args.elf)
    per_function, mem_by_caller, mix = run(qemu, args.elf, args.machine, args.steps, syms)
    steps, what = args.steps, "replay steps (harness and construction included)"
    if args.subtract:
        per_function, mem_by_caller, mix = subtract((per_function, mem_by_caller, mix),
                                                    run(qemu, args.elf, args.machine, args.subtract, syms))
        steps, what = args.steps - args.subtract, (f"replay steps: {args.steps} steps minus {args.subtract} "
                                                    "(harness included, construction not)")
    # With --subtract, what ran as often in both replays (construction, start-up) is 0: left out.
    per_function = collections.Counter({f: c for f, c in per_function.items() if c != 0})
    mem_by_caller = collections.Counter({k: c for k, c in mem_by_caller.items() if c != 0})
    total = sum(per_function.values())
    if total <= 0:
        sys.exit("target-profile: no executed blocks in QEMU's log (is -d exec supported?)")
    print(f"# {args.elf}: {total} instructions in {steps} {what}; per step = column / {steps}")
    print(f"{'instructions':>12} {'per step':>9} {'share':>6}  function")
    for f, c in per_function.most_common(args.top):
        print(f"{c:12d} {c / steps:9.0f} {100 * c / total:5.1f}%  {f}")
    print(f"# {', '.join(MEM)} by caller")
    for (f, caller), c in mem_by_caller.most_common(args.callers):
        print(f"{c:12d} {c / steps:9.0f}         {f} <- {caller}")
    if args.mix:
        print_mix(per_function, mix, args.top, steps)
    listed = [f for f, _ in per_function.most_common(args.top)]
    missing = [e for e in args.expect if not any(e in f for f in listed)]
    if missing:
        sys.exit(f"target-profile: not among the {args.top} listed functions: {', '.join(missing)}")


if __name__ == "__main__":
    main()
