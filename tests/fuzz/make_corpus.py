#!/usr/bin/python3
"""Writes the committed seed corpus of the libFuzzer harnesses (tests/fuzz/corpus/<fuzzer>/).

Each file is a hand-made input in the byte format of tests/fuzz/fuzz_common.hpp: a nominal run,
a NaN case, an Inf case and a few edge cases (huge values, MRP norm > 1, gimbal lock, warm starts,
saturated readings) per controller/estimator. Deterministic: rerun after changing the format and
commit the result.   usage: /usr/bin/python3 tests/fuzz/make_corpus.py
"""
import os
import shutil
import struct

HERE = os.path.dirname(os.path.abspath(__file__))
OUT = os.path.join(HERE, "corpus")

# Selector bytes of fuzz::kSpecials (keep in step with fuzz_common.hpp).
S = {"zero": 0, "nzero": 1, "nan": 2, "inf": 3, "ninf": 4, "denorm": 5, "ndenorm": 6,
     "maxsub": 7, "minnorm": 8, "big": 9, "nbig": 10, "max": 11, "nmax": 12, "tiny": 13,
     "one": 14, "none": 15, "two": 16, "half": 17, "e154": 18, "e155": 19, "em154": 20,
     "halfpi": 21, "nhalfpi": 22, "pi": 23, "e-8": 24, "ne-8": 25, "e8": 26, "nnan": 27,
     "snan": 28, "e-12": 29, "hundred": 30, "nhundred": 31}
NUM_SPECIALS = 32
EXPONENTS = [-12, -9, -6, -4, -3, -2, -1, 0, 1, 2, 3, 6]
RAW = 248


def sp(name):
    """A special value."""
    return bytes([S[name]])


def sc(x, exp):
    """x * 10^exp with x in [-1, 1) quantised to int16 / 32768."""
    e = EXPONENTS.index(exp)
    m = max(-32768, min(32767, int(round(x * 32768))))
    return bytes([NUM_SPECIALS + e]) + struct.pack("<h", m)


def raw(x):
    return bytes([RAW]) + struct.pack("<d", x)


def zero_vec():
    return b"\x00"


def bcast(v):
    return b"\x01" + v


def full(*vals):
    return b"\x02" + b"".join(vals)


def u8(*b):
    return bytes(b)


def zeros(n):
    return b"\x00" * n


CORPUS = {
    # target byte 0 = HybridAdaptive (config: 1 normalized, 2 T_c = 0.1 s, 4 warm start,
    # 8 diagnostics, 16 FDIR mask per step), 1 = steering, 2 = MrpPd + allocator.
    "fuzz_seed001": {
        "hybrid_nominal": u8(0, 0) + zeros(7 * 6),
        "hybrid_normalized_slow_diag": u8(0, 1 | 2 | 8) + full(sc(0.5, -1), sc(-0.3, -1), sc(0.2, -1))
        + full(sc(0.1, -2), sc(0.1, -2), sc(-0.1, -2)) + full(sc(0.5, 0), sc(-0.5, 0), sc(0.25, 0), sc(0, 0))
        + zeros(4) + zeros(7 * 4),
        "hybrid_fdir_gimbal0_failed": u8(0, 16) + u8(0x7e, 0) + zeros(7) + u8(0x7e, 0) + zeros(7)
        + u8(0xff, 1) + zeros(7) + u8(0x00, 0) + zeros(7),
        "hybrid_nan_sigma": u8(0, 0) + zeros(7) + full(sp("nan"), sp("zero"), sp("zero")) + zeros(6) + zeros(7),
        "hybrid_inf_rate": u8(0, 0) + zero_vec() + bcast(sp("inf")) + zeros(5) + zeros(7),
        "hybrid_mrp_norm_gt1_huge_ref": u8(0, 0) + bcast(sp("two")) + zeros(3) + full(sp("big"), sp("zero"), sp("zero"))
        + zeros(2) + zeros(7),
        "hybrid_warm_start_on_ball": u8(0, 4 | 2) + bcast(sp("big")) + bcast(sc(0.35, 0)) * 4 + bcast(sc(0.35, 0)) * 3
        + bcast(sc(0.5, -1)) + zeros(6) + zeros(7),
        "hybrid_warm_start_nan": u8(0, 4) + bcast(sp("nan")) + zeros(7) + zeros(7),
        "steer_nominal": u8(1, 0) + sp("zero") + full(sp("one"), sp("zero"), sp("zero"))
        + full(sp("zero"), sp("one"), sp("zero")) + full(sp("zero"), sp("zero"), sp("one"))
        + bcast(sp("half")) + bcast(sc(0.3, 0)) + full(sp("one"), sp("none"), sp("zero")) + bcast(sp("e-8"))
        + full(sc(0.1, 0), sc(-0.2, 0), sc(0.3, 0)),
        "steer_singular_undamped": u8(1, 1) + sp("zero") + zeros(7) + bcast(sp("one")),
        "steer_masked_huge_v": u8(1, 4) + sp("e-8") + bcast(sp("one")) * 7 + u8(0) + bcast(sp("big")) + u8(0x0f),
        "steer_nan": u8(1, 0) + sp("zero") + full(sp("nan"), sp("zero"), sp("zero")) + zeros(6) + bcast(sp("one")),
        "mrp_pd_nominal": u8(2) + zeros(6 * 4) + full(sc(0.1, -1), sp("zero"), sp("zero")),
        "mrp_pd_nan_inf": u8(2) + full(sp("nan"), sp("zero"), sp("zero")) + zeros(5) + zeros(1)
        + zero_vec() + bcast(sp("inf")) + zeros(4) + zeros(1),
        "mrp_pd_mrp_norm_gt1": u8(2) + bcast(sp("two")) + zeros(5) + bcast(sp("max")),
        "mrp_pd_overflow": u8(2) + zero_vec() + bcast(sp("big")) + zeros(4) + bcast(sp("nmax")),
    },
    # law byte 0 = PpcNeural, 1 = AdaptiveTracking; config: 1 degrees, 2 robust clamp (PPATC),
    # 4 warm start (Ŵ, μ̂), 8 diagnostics, 16 funnel recovery (reopen). Per step: t, angles, ω, ϑ_d,
    # ϑ̇_d, ϑ̈_d offsets.
    "fuzz_seed002": {
        "ppc_nominal": u8(0, 8) + zeros(6 * 8),
        "ppc_degrees_robust": u8(0, 1 | 2) + zeros(6) + sp("zero") + full(sc(0.5, -4), sp("zero"), sp("zero"))
        + zeros(4) + zeros(6 * 3),
        "ppc_funnel_edge_robust": u8(0, 2) + zeros(6) + sp("zero") + full(sc(0.2, -4), sp("zero"), sp("zero"))
        + zeros(4),
        "ppc_funnel_edge_reopen": u8(0, 16 | 8) + zeros(6) + sp("zero") + full(sc(0.2, -4), sp("zero"), sp("zero"))
        + zeros(4) + zeros(6 * 2),
        "ppc_first_error_outside_reopen": u8(0, 16) + sp("zero") + full(sc(0.5, -2), sp("zero"), sp("zero"))
        + zeros(4) + zeros(6 * 2),
        "ppc_nan_angle": u8(0, 0) + zeros(6) + sp("zero") + full(sp("nan"), sp("zero"), sp("zero")) + zeros(4),
        "ppc_inf_time": u8(0, 0) + sp("inf") + zeros(5) + zeros(6),
        "ppc_gimbal_lock": u8(0, 0) + zeros(6) + sp("zero") + full(sp("zero"), sp("halfpi"), sp("zero")) + zeros(4),
        "ppc_overflow_rate": u8(0, 0) + sp("zero") + zero_vec() + bcast(sp("e155")) + zeros(3) + zeros(6 * 2),
        "ppc_warm_start": u8(0, 4) + bcast(sc(0.5, 0)) * 3 + sc(0.3, 0) + zeros(6 * 3),
        "ppc_warm_start_negative_mu": u8(0, 4) + zeros(3) + sp("none") + zeros(6),
        "atc_nominal": u8(1, 8) + zeros(6 * 8),
        "atc_nan_rate": u8(1, 0) + zeros(6) + sp("zero") + zero_vec() + full(sp("zero"), sp("nan"), sp("zero"))
        + zeros(3),
        "atc_huge_reference": u8(1, 1) + sp("zero") + zeros(2) + bcast(sp("big")) + zeros(2) + zeros(6),
    },
    # target 0 = PrescribedTimeSe3, 1 = FtsmcSe3 (config & 3: initial pose, 4: non-orthonormal C),
    # 2 = quantizer (config 4: fuzzed channels, 8: fuzzed limits). Law step: 4 chaser + 6 desired vecs.
    "fuzz_seed003": {
        "ptc_nominal_pose0": u8(0, 0) + zeros(10 * 5),
        "ptc_pose3_perturbed": u8(0, 3) + full(sc(0.1, -1), sp("zero"), sp("zero")) + bcast(sc(0.5, 1))
        + bcast(sc(0.1, -2)) + zeros(1) + zeros(6) + zeros(10 * 3),
        "ptc_nan_rate": u8(0, 1) + zeros(2) + full(sp("nan"), sp("zero"), sp("zero")) + zeros(7),
        "ptc_inf_position": u8(0, 2) + zero_vec() + bcast(sp("inf")) + zeros(8),
        "ptc_huge_rate": u8(0, 0) + zeros(2) + bcast(sp("big")) + zeros(7) + zeros(10),
        "ftsmc_nominal_pose2": u8(1, 2) + zeros(10 * 5),
        "ftsmc_non_orthonormal_C": u8(1, 4) + zero_vec() + bcast(sc(0.5, 0)) + zeros(2) + zeros(3) + zeros(6),
        "ftsmc_inf_desired": u8(1, 0) + zeros(4) + zero_vec() + bcast(sp("ninf")) + zeros(4),
        "ftsmc_inside_earth": u8(1, 0) + zero_vec() + bcast(sc(-0.999, 6)) + zeros(8),
        "quantizer_nominal": u8(2, 0) + full(sc(0.05, 0), sc(-0.3, 0), sc(0.1, -2), sc(0.5, 0), sc(-0.8, 1), sc(0.3, 0))
        + u8(1) + full(sc(0.05, 0), sc(-0.3, 0), sc(0.1, -2), sc(0.5, 0), sc(-0.8, 1), sc(0.3, 0)) + u8(0)
        + bcast(sc(0.7, 0)) + u8(0),
        "quantizer_nan": u8(2, 0) + full(sp("nan"), sp("zero"), sp("zero"), sp("zero"), sp("zero"), sp("zero")) + u8(1)
        + bcast(sp("inf")) + u8(0),
        "quantizer_huge_and_denormal": u8(2, 8) + full(sp("max"), sp("nmax"), sp("denorm"), sp("big"), sp("e-12"), sp("two"))
        + u8(0) + full(sp("one"), sp("zero"), sp("none"), sp("half"), sp("nan"), sp("zero")),
        "quantizer_fuzzed_channels": u8(2, 4) + u8(0) + sp("half") + sc(0.1, -2) + sp("one") + sp("half")
        + u8(0) + sp("nan") + sp("one") + sp("one") + sp("one") + u8(0) + sp("half") + sp("denorm") + sp("big")
        + sp("one") + u8(1) * 3 + bcast(sc(0.3, 0)) + u8(1),
    },
    # target 0 = chain (config: 1 fixed θ, 2 skip mode, 4-16 x law, 32 raw sum, 64 PID k_i,
    # 128 literal fusion); op byte per step: 0 predict, 1 update, 2/3 Alg. 2 predict/update,
    # 4 fuse, 5 ADRC, 6 warm starts. 1 = Eskf<3,1,1,1>, 2 = Pid<3>.
    "fuzz_seed004": {
        "chain_nominal_sample": u8(0, 0) + u8(0) + zeros(2) + u8(2) + zeros(2) + u8(1) + zeros(1)
        + u8(3) + zeros(2) + u8(5) + zeros(3) + u8(4, 1) + u8(0x14, 2) + u8(0x24, 3) + u8(0) + zeros(2),
        "chain_saturated_skip_literal": u8(0, 2 | 128) + u8(3) + sp("one") + sp("zero") + u8(0x13) + sp("none")
        + sp("zero") + u8(4, 1) + u8(0x13) + sp("zero") + sp("zero"),
        "chain_saturated_truncated": u8(0, 1) + u8(2) + zeros(2) + u8(3) + sc(0.1, -4) + sp("zero")
        + u8(3) + sc(-0.1, -4) + sp("zero") + u8(4, 1),
        "chain_pid_baseline_adrc": u8(0, 4 | 64) + u8(5) + bcast(sc(0.1, -3)) + zeros(2) + u8(5) + zeros(3)
        + u8(0x15) + bcast(sp("big")) + zeros(2),
        "chain_nan_measurement": u8(0, 0) + u8(1) + full(*([sp("zero")] * 4 + [sp("nan")] + [sp("zero")] * 4)),
        "chain_inf_input": u8(0, 0) + u8(0) + bcast(sp("inf")) + zeros(1) + u8(2) + sp("ninf") + sp("zero"),
        "chain_warm_start_huge": u8(0, 0) + u8(6) + zeros(1) + sp("big") + u8(0) + zeros(2) + u8(1) + zeros(1)
        + u8(14) + zeros(1) + bcast(sp("max")) + u8(2) + zeros(2),
        "small_eskf_nominal": u8(1, 0) + u8(0) + zeros(2) + u8(1) + zeros(1) + u8(0) + zeros(2) + u8(1)
        + bcast(sc(0.1, -6)),
        "small_eskf_replace_nan": u8(1, 1) + u8(3, 1, 2) + bcast(sp("nan")) + zeros(2) + u8(3, 0, 0) + zeros(3)
        + u8(2) + zeros(1) + bcast(sp("none")) + zeros(2) + u8(1) + zeros(1),
        "pid_nominal": u8(2, 1) + full(sc(0.1, 0), sc(-0.2, 0), sc(0.3, 0)) + zeros(1) + bcast(sc(0.1, -1)) + zeros(1),
        "pid_huge_and_nan": u8(2, 3) + bcast(sp("max")) + zeros(1) + bcast(sp("big")) + zeros(1) + bcast(sp("nan"))
        + zeros(1),
    },
}


def main():
    for fuzzer, files in CORPUS.items():
        d = os.path.join(OUT, fuzzer)
        shutil.rmtree(d, ignore_errors=True)
        os.makedirs(d)
        for name, data in sorted(files.items()):
            with open(os.path.join(d, name), "wb") as f:
                f.write(data)
        print(f"{fuzzer}: {len(files)} files in {os.path.relpath(d, os.path.dirname(os.path.dirname(HERE)))}")


if __name__ == "__main__":
    main()
