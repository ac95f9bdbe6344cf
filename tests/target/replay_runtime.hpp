#pragma once
// The replay driver shared by the host and the Cortex-M7 (QEMU mps2-an500) builds of every replay
// program (docs/TARGET.md). A System (replay_system.hpp) wraps one flight controller/estimator;
// the driver feeds it a recorded input sequence (generated at build time by record_inputs.cpp),
// one row per step(), and prints every output with a hexadecimal float ("%a" form), one line per
// step, so that the two builds can be compared to the last bit (run_replay_check.cmake).
//
// Output format (one text line each, parsed by replay_compare.cpp and tools/target-costs.py):
//   # adcs-replay <name> steps=<N> width=<W> period=<T [s]> mode=<replay|cost>
//   # columns <name>:<scale> ...        scale 0 = exact (status codes, counters)
//   <k> <value> ...                      exact columns as integers, the others as %a hex floats
//   # done steps=<N>
// Cost mode (argument "cost", target only, QEMU -icount shift=0) adds "# tick_check ...",
// "# calibration ...", "# stages <name> ..." and " icount=<n> direct=<m>" at the end of each step
// line: n = instructions of the step() call (CostMeter below), m = the same call read directly off
// SysTick, quantised to 40 instructions (a cross-check of n). A System whose step() has stages
// (replay_system.hpp: kCostStages = N > 1) adds " prefix=<c1>,...,<c(N-1)>" after direct=: ci =
// instructions of its first i stages alone (step_stages(i, row)), measured like n; stage i costs
// ci - c(i-1) (c0 = 0), the last stage n - c(N-1).
//
// The hex float is formatted here, not by printf: newlib-nano's printf has no %a, and printing
// the same digits with the same code on both sides leaves the comparison to the numbers alone.
// On the host, self_check_hexfloat() proves this formatter equals glibc's "%a".
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <type_traits>
#include <utility>

#include "adcs/core/status.hpp"
#include "replay_system.hpp"

namespace replay {

//! Appends x in the C99 "%a" form glibc prints ("0x1.8p+1", "-0x0p+0", "0x0.0000000000001p-1022",
//! "inf", "-nan"); returns the new end. Needs 32 bytes.
inline char* put_hexfloat(char* p, double x) {
  std::uint64_t bits;
  std::memcpy(&bits, &x, sizeof bits);
  const bool neg = (bits >> 63) != 0;
  const int biased = static_cast<int>((bits >> 52) & 0x7FF);
  std::uint64_t mant = bits & ((std::uint64_t{1} << 52) - 1);
  if (neg) *p++ = '-';
  if (biased == 0x7FF) {
    const char* s = mant ? "nan" : "inf";
    while (*s) *p++ = *s++;
    return p;
  }
  *p++ = '0';
  *p++ = 'x';
  int exponent;
  if (biased == 0) {  // zero or subnormal: glibc prints 0x0.<fraction>p-1022 (0x0p+0 for zero)
    *p++ = '0';
    exponent = mant ? -1022 : 0;
  } else {
    *p++ = '1';
    exponent = biased - 1023;
  }
  if (mant) {
    *p++ = '.';
    int digits = 13;
    while ((mant & 0xF) == 0) {  // strip trailing zero nibbles
      mant >>= 4;
      --digits;
    }
    for (int i = digits - 1; i >= 0; --i) p[i] = "0123456789abcdef"[mant & 0xF], mant >>= 4;
    p += digits;
  }
  *p++ = 'p';
  *p++ = exponent < 0 ? '-' : '+';
  unsigned e = static_cast<unsigned>(exponent < 0 ? -exponent : exponent);
  char tmp[8];
  int n = 0;
  do {
    tmp[n++] = static_cast<char>('0' + e % 10);
    e /= 10;
  } while (e);
  while (n) *p++ = tmp[--n];
  return p;
}

//! Appends a signed decimal integer.
inline char* put_int(char* p, long long v) {
  if (v < 0) {
    *p++ = '-';
    v = -v;
  }
  char tmp[24];
  int n = 0;
  do {
    tmp[n++] = static_cast<char>('0' + v % 10);
    v /= 10;
  } while (v);
  while (n) *p++ = tmp[--n];
  return p;
}

inline char* put_str(char* p, const char* s) {
  while (*s) *p++ = *s++;
  return p;
}

#ifndef ADCS_REPLAY_TARGET
//! Host only: put_hexfloat must print exactly what glibc's "%a" prints (the format the brief
//! and the comparison rely on). Walks normal, subnormal, signed-zero, infinite and NaN values.
inline bool self_check_hexfloat() {
  double probes[] = {0.0, -0.0, 1.0, -1.5, 0.1, 1.0 / 3.0, 2.0, 1e300, -1e-300, 4.9406564584124654e-324,
                     2.2250738585072009e-308, 2.2250738585072014e-308, 1.7976931348623157e308, 123456.789,
                     -6.02214076e23, 1.0 + 2.220446049250313e-16, 0.5, 3.0e-5};
  char mine[40], libc[40];
  for (double x : probes) {
    for (int k = 0; k < 64; ++k) {  // and neighbours with varied trailing nibbles
      *put_hexfloat(mine, x) = '\0';
      std::snprintf(libc, sizeof libc, "%a", x);
      if (std::strcmp(mine, libc) != 0) {
        std::fprintf(stderr, "put_hexfloat(%.17g) = %s, glibc %%a = %s\n", x, mine, libc);
        return false;
      }
      x = x * 1.0000001234567 + 1e-310;
    }
  }
  return true;
}
#endif

// ---------------------------------------------------------------- instruction counting (target)
#ifdef ADCS_REPLAY_TARGET
// SysTick (ARMv7-M ARM B3.3): CSR 0xE000E010, RVR +4, CVR +8; a 24-bit down-counter. On QEMU's
// mps2-an500 it runs from the 25 MHz system clock; with -icount shift=0 every guest instruction
// advances virtual time by exactly 1 ns, so SysTick decrements once per 40 instructions,
// deterministically. tick_check() measures the ratio with a loop of known length instead of
// trusting the constant.
inline volatile std::uint32_t* systick() { return reinterpret_cast<volatile std::uint32_t*>(0xE000E010u); }
inline void systick_start() {
  systick()[0] = 0;          // disable while configuring
  systick()[1] = 0xFFFFFFu;  // reload: full 24-bit range
  systick()[2] = 0;          // any write clears the current value
  systick()[0] = 5;          // ENABLE | CLKSOURCE = processor clock, no interrupt
}
inline std::uint32_t systick_now() { return systick()[2]; }
//! Ticks elapsed from a to b (down-counter, one 24-bit wrap handled: 16.7 M ticks = 671 M
//! instructions, far above any measured region).
inline std::uint32_t ticks_between(std::uint32_t a, std::uint32_t b) { return (a - b) & 0xFFFFFFu; }

//! Runs exactly 1 + 2 n instructions (mov; n x (subs; bne)) and returns the ticks they took.
__attribute__((noinline)) inline std::uint32_t tick_check_loop(std::uint32_t n) {
  std::uint32_t a, b;
  a = systick_now();
  __asm volatile(
      "mov r12, %[n]\n"
      "1: subs r12, r12, #1\n"
      "bne 1b\n" ::[n] "r"(n)
      : "r12", "cc");
  b = systick_now();
  return ticks_between(a, b);
}
#endif

// -------------------------------------------------------------------- Api of a System (cores)
//! The measured call: one System::step() behind a call the compiler cannot see through, used for
//! both the live step and the cost measurement so that they execute the same instructions.
template <class S>
__attribute__((noinline)) void step_on(S& s, const double* row) noexcept {
  s.step(row);
}
//! Same signature, does nothing (one instruction, bx lr): the calibration of the measurement.
template <class S>
__attribute__((noinline)) void step_none(S& s, const double* row) noexcept {
  __asm volatile("" ::"r"(&s), "r"(row) : "memory");
}
//! The first N stages of System::step() alone (cost mode, N < kCostStages): what step_on is to the
//! whole step, with N a constant so that the later stages are compiled out as in a shorter step().
template <class S, int N>
__attribute__((noinline)) void step_prefix_on(S& s, const double* row) noexcept {
  s.step_stages(N, row);
}

//! The stages of System S's step() (replay_system.hpp): S::kCostStages and S::kStageNames when S
//! declares them, else one stage, "step".
template <class S, class = void>
struct StagesOf {
  static constexpr int kCount = 1;
  static constexpr const char* kNames[1] = {"step"};
};
template <class S>
struct StagesOf<S, std::void_t<decltype(S::kCostStages)>> {
  static constexpr int kCount = S::kCostStages;
  static constexpr const char* const* kNames = S::kStageNames;
  static_assert(kCount >= 2 && kCount <= kMaxCostStages, "kCostStages: 2 .. kMaxCostStages");
  static_assert(sizeof(S::kStageNames) / sizeof(S::kStageNames[0]) == static_cast<std::size_t>(kCount),
                "kStageNames needs kCostStages names");
};

#ifdef ADCS_REPLAY_TARGET
//! Instructions of one step_on(sys, row) call, from its first instruction to its return
//! inclusive (System::step inlined; not the caller's bl), measured on a copy so that the live
//! System is stepped once, by the driver, exactly as in the plain replay:
//!   T(R) = instructions of [loop set-up; R x { work = live; barrier; call fn(work, row) }]
//!        = fixed + R x (copy_loop_call + body(fn))
//! Calibration with fn = step_none (body 1: bx lr) at R = 1000 and 3000 gives the per-iteration
//! overhead c = copy_loop_call + 1 (an integer, recovered exactly from the 2000-iteration
//! difference) and the fixed part; then for each row, with fn = step_on and R = kReps:
//!   count = (T(kReps) - fixed) / kReps - c + 1.
//! measure_prefix(n) counts fn = step_prefix_on<S, n> (the first n stages of the step) the same
//! way, on a copy of the same state with the same row.
// Every repetition executes the same instructions (same state, same row); SysTick's quantisation
// (one tick = 40 instructions) leaves +-1 on the count from T(kReps) and +-1 from the fixed
// part's estimate: +-2 instructions per step at most.
template <class S>
struct CostMeter {
  static constexpr int kReps = 40;
  static constexpr int kCal1 = 1000, kCal2 = 3000;
  static inline long long insns_per_tick = 0;
  static inline long long per_iteration = 0;  //!< copy + loop + call + step_none's bx lr
  static inline long long fixed = 0;          //!< loop set-up inside the measured region

  __attribute__((noinline)) static std::uint32_t loop_ticks(const S& live, const double* row, int reps,
                                                            void (*fn)(S&, const double*)) {
    S work = live;  // on the stack: the replay's .bss holds the live System only
    const std::uint32_t a = systick_now();
    for (int r = 0; r < reps; ++r) {
      work = live;
      __asm volatile("" ::: "memory");  // the copy is real: step reads work from memory
      fn(work, row);
    }
    const std::uint32_t b = systick_now();
    return ticks_between(a, b);
  }

  static long long div_round(long long n, long long d) { return (n >= 0 ? n + d / 2 : n - d / 2) / d; }

  //! Ratio check and overhead calibration; false unless SysTick counts 1 per 40 instructions
  //! (i.e. QEMU runs with -icount shift=0: 25 MHz SysTick, 1 ns per instruction).
  static bool calibrate(const S& live, const double* row, char* out) {
    systick_start();
    constexpr std::uint32_t kLoop = 200000;
    const std::uint32_t loop_insns = 1 + 2 * kLoop;
    const std::uint32_t t = tick_check_loop(kLoop);
    insns_per_tick = t ? div_round(loop_insns, t) : 0;
    const long long t1 = loop_ticks(live, row, kCal1, step_none<S>) * insns_per_tick;
    const long long t2 = loop_ticks(live, row, kCal2, step_none<S>) * insns_per_tick;
    per_iteration = div_round(t2 - t1, kCal2 - kCal1);
    fixed = t1 - kCal1 * per_iteration;
    char* p = put_str(out, "# tick_check loop_insns=");
    p = put_int(p, loop_insns);
    p = put_str(p, " ticks=");
    p = put_int(p, t);
    p = put_str(p, " insns_per_tick=");
    p = put_int(p, insns_per_tick);
    p = put_str(p, "\n# calibration per_iteration=");
    p = put_int(p, per_iteration);
    p = put_str(p, " fixed=");
    p = put_int(p, fixed);
    p = put_str(p, " step_reps=");
    p = put_int(p, kReps);
    p = put_str(p, " system_bytes=");
    p = put_int(p, static_cast<long long>(sizeof(S)));
    p = put_str(p, "\n");
    *p = '\0';
    return t > 0 && insns_per_tick == 40;
  }

  static long long measure_fn(const S& live, const double* row, void (*fn)(S&, const double*)) {
    const long long t = loop_ticks(live, row, kReps, fn) * insns_per_tick;
    return div_round(t - fixed, kReps) - per_iteration + 1;
  }
  static long long measure(const S& live, const double* row) { return measure_fn(live, row, step_on<S>); }

  //! Instructions of the first n stages of the step (1 <= n < StagesOf<S>::kCount), else -1.
  static long long measure_prefix(const S& live, const double* row, int n) {
    return measure_prefix_of(live, row, n, std::make_integer_sequence<int, StagesOf<S>::kCount - 1>{});
  }
  template <int... I>
  static long long measure_prefix_of(const S& live, const double* row, int n, std::integer_sequence<int, I...>) {
    using Fn = void (*)(S&, const double*);
    static constexpr Fn kPrefix[] = {nullptr, &step_prefix_on<S, I + 1>...};  // [n]: first n stages
    return n >= 1 && n < StagesOf<S>::kCount ? measure_fn(live, row, kPrefix[n]) : -1;
  }
};
#endif

//! The Api of System S whose live instance is *P (an object with static storage in the core).
template <class S, S* P>
struct ApiOf {
  static adcs::Status init_status() { return P->init_status(); }
  static void step(const double* row) { step_on(*P, row); }
  static void step_part(int part, const double* row) { P->step_part(part, row); }
  static void outputs(double* v) { P->outputs(v); }
  static void command(double* u) { P->command(u); }
#ifdef ADCS_REPLAY_TARGET
  static bool calibrate(const double* row, char* report) { return CostMeter<S>::calibrate(*P, row, report); }
  static long long measure(const double* row) { return CostMeter<S>::measure(*P, row); }
  static long long measure_prefix(int n, const double* row) { return CostMeter<S>::measure_prefix(*P, row, n); }
#endif
  static constexpr Api make() {
    return Api{S::kName, S::kInputWidth, S::kPeriod, S::kColumns,
               static_cast<int>(sizeof(S::kColumns) / sizeof(Column)), S::kCommandSize, S::kParts,
               &init_status, &step, &step_part, &outputs, &command,
               StagesOf<S>::kCount, StagesOf<S>::kNames,
#ifdef ADCS_REPLAY_TARGET
               &calibrate, &measure, &measure_prefix
#else
               nullptr, nullptr, nullptr
#endif
    };
  }
};

// ------------------------------------------------------------------------------------- driver
inline void emit(char* line, char* end) {
  std::fwrite(line, 1, static_cast<std::size_t>(end - line), stdout);
}

//! main() of every replay program. rows: steps x width doubles. Argument "cost" selects cost
//! mode (target only); "steps=K" (1 <= K) replays only the first min(K, steps) rows, which the
//! icount test's second run uses to check determinism on a prefix of 40 of the 400 steps
//! (run_replay_check.cmake). Returns 0, or 2 (construction/usage), 3 (no -icount), 4 (host
//! self-check).
inline int run(const Api& api, int argc, char** argv, const double* rows, int width, int steps) {
  static char line[4096];  // static: not stack
  static double values[128];
  bool cost = false;
  for (int i = 1; i < argc; ++i) {
    if (std::strcmp(argv[i], "cost") == 0) cost = true;
    if (std::strncmp(argv[i], "steps=", 6) == 0) {
      const int k = std::atoi(argv[i] + 6);
      if (k < 1) return 2;
      if (k < steps) steps = k;
    }
  }
#ifndef ADCS_REPLAY_TARGET
  if (!self_check_hexfloat()) return 4;
#endif
  char* p = put_str(line, "# adcs-replay ");
  p = put_str(p, api.name);
  p = put_str(p, " steps=");
  p = put_int(p, steps);
  p = put_str(p, " width=");
  p = put_int(p, api.input_width);
  p = put_str(p, " period=");
  p = put_hexfloat(p, api.period_s);
  p = put_str(p, cost ? " mode=cost\n" : " mode=replay\n");
  emit(line, p);
  p = put_str(line, "# columns k:0x0p+0");
  for (int c = 0; c < api.num_columns; ++c) {
    if (p - line > static_cast<long>(sizeof line) - 120) {  // long header: continue on a new line
      *p++ = '\n';
      emit(line, p);
      p = put_str(line, "# columns+");
    }
    *p++ = ' ';
    p = put_str(p, api.columns[c].name);
    *p++ = ':';
    p = put_hexfloat(p, api.columns[c].scale);
  }
  *p++ = '\n';
  emit(line, p);
  if (width != api.input_width || api.num_columns > 128 || steps < 1) {
    emit(line, put_str(line, "# error: recorded rows do not fit the System\n"));
    return 2;
  }
  if (api.init_status() != adcs::Status::ok) {
    p = put_str(line, "# error: construction failed: ");
    p = put_str(p, adcs::to_string(api.init_status()));
    *p++ = '\n';
    emit(line, p);
    return 2;
  }
  if (cost && !api.calibrate) {
    emit(line, put_str(line, "# error: cost mode needs the target (QEMU -icount shift=0)\n"));
    return 2;
  }
  if (cost && !api.calibrate(rows, line)) {
    std::fputs(line, stdout);
    emit(line, put_str(line, "# error: SysTick does not count 1 per 40 instructions: run QEMU with -icount shift=0\n"));
    return 3;
  }
  if (cost) {
    std::fputs(line, stdout);
    p = put_str(line, "# stages");
    for (int i = 0; i < api.cost_stages; ++i) {
      *p++ = ' ';
      p = put_str(p, api.stage_names[i]);
    }
    *p++ = '\n';
    emit(line, p);
  }
  for (int k = 0; k < steps; ++k) {
    const double* row = rows + static_cast<long>(k) * width;
    long long icount = -1, direct = -1;
    long long prefix[kMaxCostStages] = {};  // [i]: instructions of the first i + 1 stages
#ifdef ADCS_REPLAY_TARGET
    if (cost) {
      icount = api.measure(row);
      for (int i = 0; i + 1 < api.cost_stages; ++i) prefix[i] = api.measure_prefix(i + 1, row);
      const std::uint32_t a = systick_now();
      api.step(row);
      direct = static_cast<long long>(ticks_between(a, systick_now())) * 40;  // quantised cross-check
    } else {
      api.step(row);
    }
#else
    api.step(row);
#endif
    api.outputs(values);
    p = put_int(line, k);
    for (int c = 0; c < api.num_columns; ++c) {
      *p++ = ' ';
      p = api.columns[c].scale == 0.0 ? put_int(p, static_cast<long long>(values[c])) : put_hexfloat(p, values[c]);
    }
    if (icount >= 0) {
      p = put_str(p, " icount=");
      p = put_int(p, icount);
      p = put_str(p, " direct=");
      p = put_int(p, direct);
      for (int i = 0; i + 1 < api.cost_stages; ++i) {
        p = put_str(p, i == 0 ? " prefix=" : ",");
        p = put_int(p, prefix[i]);
      }
    }
    *p++ = '\n';
    emit(line, p);
  }
  p = put_str(line, "# done steps=");
  p = put_int(p, steps);
  *p++ = '\n';
  emit(line, p);
  std::fflush(stdout);
  return 0;
}

}  // namespace replay
