#pragma once
// Shared decoding and checks of the libFuzzer harnesses (tests/fuzz/fuzz_seed00*.cpp).
//
// Byte format (tests/fuzz/make_corpus.py writes the same one; keep the two in step):
//   value():   one selector byte s
//                s <  kNumSpecials        -> kSpecials[s] (0, NaN, ±Inf, denormals, 1e300, ...)
//                s >= 248                 -> the next 8 bytes as a raw little-endian double
//                otherwise                -> (int16 from the next 2 bytes LE) / 32768 * 10^e,
//                                            e = kExponents[(s - kNumSpecials) % kNumExponents]
//   vec<N>():  one mode byte m: m % 8 == 0 -> zero vector (no more bytes),
//                               m % 8 == 1 -> one value() broadcast to all N components,
//                               otherwise  -> N value()s
// Exhausted input reads as zero bytes, so a short file decodes to the nominal (zero-offset)
// operating point and every harness adds the decoded values to a nominal state.
//
// Checks abort through FUZZ_CHECK (message + __builtin_trap), which libFuzzer reports as a crash
// and keeps the input; gtest is not used here.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <limits>

#include "adcs/core/failure_policy.hpp"
#include "adcs/core/status.hpp"
#include "adcs/core/types.hpp"

#define FUZZ_CHECK(cond, msg)                                                             \
  do {                                                                                    \
    if (!(cond)) {                                                                        \
      std::fprintf(stderr, "FUZZ_CHECK failed at %s:%d: %s [%s]\n", __FILE__, __LINE__,   \
                   (msg), #cond);                                                         \
      __builtin_trap();                                                                   \
    }                                                                                     \
  } while (0)

//! A harness's entry point: ADCS_FUZZ_ENTRY(fuzz_seed001) { ... } defines adcs_fuzz_seed001().
//! The five harnesses are compiled in one unit (they instantiate the same controllers), and each
//! fuzzer's LLVMFuzzerTestOneInput (fuzz_main.cpp) calls its own (tests/fuzz/CMakeLists.txt).
#define ADCS_FUZZ_ENTRY(name) extern "C" int adcs_##name(const std::uint8_t* data, std::size_t size)

namespace fuzz {

inline constexpr double kInf = std::numeric_limits<double>::infinity();
inline constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

//! Edge values, index = selector byte. Order is part of the corpus format (make_corpus.py).
inline constexpr double kSpecials[] = {
    0.0,                                          // 0  nominal (and what exhausted input reads)
    -0.0,                                         // 1
    kNaN,                                         // 2
    kInf,                                         // 3
    -kInf,                                        // 4
    std::numeric_limits<double>::denorm_min(),    // 5  smallest subnormal
    -std::numeric_limits<double>::denorm_min(),   // 6
    2.2250738585072009e-308,                      // 7  largest subnormal
    std::numeric_limits<double>::min(),           // 8  smallest normal
    1e300,                                        // 9
    -1e300,                                       // 10
    std::numeric_limits<double>::max(),           // 11
    -std::numeric_limits<double>::max(),          // 12
    1e-300,                                       // 13
    1.0,                                          // 14
    -1.0,                                         // 15
    2.0,                                          // 16 an MRP component giving |σ| > 1
    0.5,                                          // 17
    1e154,                                        // 18 squares to ~1e308
    1e155,                                        // 19 squares to Inf
    1e-154,                                       // 20
    1.5707963267948966,                           // 21 π/2 (Euler gimbal lock)
    -1.5707963267948966,                          // 22
    3.141592653589793,                            // 23 π
    1e-8,                                         // 24
    -1e-8,                                        // 25
    1e8,                                          // 26
    -std::numeric_limits<double>::quiet_NaN(),    // 27 NaN with the sign bit
    std::numeric_limits<double>::signaling_NaN(), // 28
    1e-12,                                        // 29
    100.0,                                        // 30
    -100.0,                                       // 31
};
inline constexpr int kNumSpecials = static_cast<int>(sizeof(kSpecials) / sizeof(kSpecials[0]));
inline constexpr int kExponents[] = {-12, -9, -6, -4, -3, -2, -1, 0, 1, 2, 3, 6};
inline constexpr int kNumExponents = static_cast<int>(sizeof(kExponents) / sizeof(kExponents[0]));
inline constexpr int kRawSelector = 248;

class Reader {
 public:
  Reader(const std::uint8_t* data, std::size_t size) noexcept : d_(data), n_(size) {}
  std::size_t remaining() const noexcept { return n_ - i_; }
  bool empty() const noexcept { return i_ >= n_; }

  std::uint8_t u8() noexcept { return i_ < n_ ? d_[i_++] : 0; }

  double value() noexcept {
    const int s = u8();
    if (s < kNumSpecials) return kSpecials[s];
    if (s >= kRawSelector) {
      std::uint8_t b[8];
      for (auto& x : b) x = u8();
      std::uint64_t bits = 0;
      for (int k = 7; k >= 0; --k) bits = (bits << 8) | b[k];
      double v;
      std::memcpy(&v, &bits, sizeof v);
      return v;
    }
    const int e = kExponents[(s - kNumSpecials) % kNumExponents];
    const std::uint16_t lo = u8(), hi = u8();
    const auto m = static_cast<std::int16_t>(static_cast<std::uint16_t>(lo | (hi << 8)));
    return static_cast<double>(m) / 32768.0 * std::pow(10.0, e);
  }

  template <int N>
  adcs::Vec<N> vec() noexcept {
    const int mode = u8() % 8;
    adcs::Vec<N> v = adcs::Vec<N>::Zero();
    if (mode == 0) return v;
    if (mode == 1) return adcs::Vec<N>::Constant(value());
    for (int i = 0; i < N; ++i) v(i) = value();
    return v;
  }

 private:
  const std::uint8_t* d_;
  std::size_t n_;
  std::size_t i_ = 0;
};

//! Status histogram per harness target, printed at exit when ADCS_FUZZ_STATS is set (shows that
//! a corpus reaches applied steps as well as each rejection, docs/FUZZING.md).
class Stats {
 public:
  static constexpr int kTargets = 8, kStatuses = 10;
  static Stats& instance() noexcept {
    static Stats s;
    return s;
  }
  void count(int target, adcs::Status s) noexcept {
    const int i = static_cast<int>(s);
    if (target >= 0 && target < kTargets && i < kStatuses) ++n_[target][i];
  }
  void name(int target, const char* n) noexcept {
    if (target >= 0 && target < kTargets) names_[target] = n;
  }
  ~Stats() {
    if (!std::getenv("ADCS_FUZZ_STATS")) return;
    for (int t = 0; t < kTargets; ++t) {
      if (!names_[t]) continue;
      std::fprintf(stderr, "stats %-22s", names_[t]);
      for (int i = 0; i < kStatuses; ++i)
        if (n_[t][i]) std::fprintf(stderr, " %s=%lu", adcs::to_string(static_cast<adcs::Status>(i)), n_[t][i]);
      std::fprintf(stderr, "\n");
    }
  }

 private:
  unsigned long n_[kTargets][kStatuses] = {};
  const char* names_[kTargets] = {};
};
//! Records one step's status for target `t` named `name`.
inline void stat(int t, const char* name, adcs::Status s) noexcept {
  Stats::instance().name(t, name);
  Stats::instance().count(t, s);
}

//! Bitwise equality (NaN payloads and ±0 included): "untouched" means not written at all.
template <class A>
bool same_bits(const A& a, const A& b) noexcept {
  return std::memcmp(&a, &b, sizeof(A)) == 0;
}
template <class Derived>
bool same_bits_mat(const Eigen::DenseBase<Derived>& a, const Eigen::DenseBase<Derived>& b) noexcept {
  return std::memcmp(a.derived().data(), b.derived().data(),
                     sizeof(typename Derived::Scalar) * static_cast<std::size_t>(a.size())) == 0;
}

inline bool finite(double x) noexcept { return std::isfinite(x); }
template <class Derived>
bool finite(const Eigen::DenseBase<Derived>& x) noexcept {
  for (Eigen::Index i = 0; i < x.size(); ++i)
    if (!std::isfinite(x.derived().data()[i])) return false;
  return true;
}

//! The statuses a step() documents as "result applied" (possibly degraded); every other status
//! promises "nothing applied": outputs held, state untouched (core/status.hpp).
inline bool applied(adcs::Status s) noexcept { return adcs::usable(s); }

//! The command a rejected step must output (core/failure_policy.hpp): every bit zero under
//! safe_command, the last good command bit for bit under hold_last.
template <class M>
bool is_failure_command(adcs::FailurePolicy policy, const M& out, const M& last_good) noexcept {
  if (policy == adcs::FailurePolicy::hold_last) return same_bits_mat(out, last_good);
  for (Eigen::Index i = 0; i < out.size(); ++i)
    if (!(out(i) == 0.0)) return false;
  return true;
}

//! Checks shared by every step: finite output, non_finite_input exactly when an input was
//! non-finite, and (caller's part) state untouched unless applied.
inline void check_status_vs_input(adcs::Status s, bool input_finite, const char* who) noexcept {
  if (!input_finite) FUZZ_CHECK(s == adcs::Status::non_finite_input, who);
}

}  // namespace fuzz
