#pragma once
// Portable, bit-reproducible pseudo-random numbers for Monte Carlo runs and noise models.
//
// Why our own: the std:: distributions (normal_distribution, uniform_real_distribution) are not
// specified algorithmically, so libstdc++, libc++ and MSVC give different numbers for the same
// engine and seed, and a scenario's "seed 7" would mean different runs on different machines.
//
// Determinism: every output is a fixed function of the seed, computed with integer operations,
// IEEE-754 double +, -, *, / and sqrt (all correctly rounded), and frexp/ldexp (exact). The
// logarithm the normal draws need is implemented here (portable_log) instead of calling std::log,
// whose last bit differs between C libraries. The results are therefore identical on every
// platform with IEEE-754 binary64 arithmetic in round-to-nearest, provided the compiler does not
// fuse a*b+c into an FMA across statements: GCC in ISO mode (-std=c++17, as this project builds)
// and Clang's default (-ffp-contract=on, which fuses only within one expression) are fine, and
// the multiply-adds below are split into separate statements for that reason; do not build this
// with -ffp-contract=fast, -ffast-math or x87 (use SSE2) arithmetic.
//
// Generator: xoshiro256** 1.0 (Blackman & Vigna, https://prng.di.unimi.it/xoshiro256starstar.c),
// state seeded from a 64-bit seed with splitmix64 (the seeding the authors recommend).
#include <cmath>
#include <cstdint>

#include "adcs/core/types.hpp"

namespace adcs::sim {

namespace detail {

//! a * b, then + c, as two roundings (never an FMA: see the header comment).
inline double mul_then_add(double a, double b, double c) noexcept {
  const double product = a * b;
  return product + c;
}

//! Natural logarithm from basic IEEE operations only, for x > 0 finite (NaN otherwise, -inf at 0).
//! x = 2^e m with m in [sqrt(1/2), sqrt(2)); ln m = 2 artanh(s), s = (m-1)/(m+1), |s| < 0.172,
//! summed to s^23 (next term < 1e-19 relative); ln 2 split in a high part with trailing zero bits
//! (e * ln2_hi is exact for |e| < 2^11) and a low part. Error about 1 ulp.
inline double portable_log(double x) noexcept {
  if (!(x > 0.0) || !std::isfinite(x)) {
    if (x == 0.0) return -HUGE_VAL;
    return x == HUGE_VAL ? x : std::nan("");
  }
  int e = 0;
  double m = std::frexp(x, &e);  // x = m 2^e, m in [0.5, 1)
  if (m < 0.70710678118654752440) {
    m = 2.0 * m;
    e -= 1;
  }
  const double f = m - 1.0;   // exact (Sterbenz)
  const double s = f / (2.0 + f);
  const double z = s * s;
  // 2 (s + s^3/3 + ... + s^23/23) = 2 s (1 + z/3 + z^2/5 + ... + z^11/23), Horner in z.
  double p = 1.0 / 23.0;
  for (int k = 10; k >= 0; --k) p = mul_then_add(p, z, 1.0 / (2.0 * k + 1.0));
  const double log_m = 2.0 * s * p;
  constexpr double kLn2Hi = 6.93147180369123816490e-01;  // fdlibm's ln2_hi
  constexpr double kLn2Lo = 1.90821492927058770002e-10;  // ln 2 - ln2_hi
  const double de = static_cast<double>(e);
  const double low = mul_then_add(de, kLn2Lo, log_m);
  return mul_then_add(de, kLn2Hi, low);
}

}  // namespace detail

//! xoshiro256** generator with uniform, normal and unit-vector draws. Same seed, same numbers,
//! on every platform (see the header comment). Copyable: a copy continues the same stream.
class Rng {
 public:
  explicit Rng(std::uint64_t seed) noexcept { this->seed(seed); }

  //! Restarts the stream: state = four successive splitmix64 outputs from `seed`.
  void seed(std::uint64_t seed) noexcept {
    std::uint64_t sm = seed;
    for (std::uint64_t& word : s_) word = splitmix64(sm);
    has_spare_normal_ = false;
  }

  //! Next raw 64-bit output of xoshiro256**.
  std::uint64_t next_u64() noexcept {
    const std::uint64_t result = rotl(s_[1] * 5u, 7) * 9u;
    const std::uint64_t t = s_[1] << 17;
    s_[2] ^= s_[0];
    s_[3] ^= s_[1];
    s_[1] ^= s_[2];
    s_[0] ^= s_[3];
    s_[2] ^= t;
    s_[3] = rotl(s_[3], 45);
    return result;
  }

  //! Uniform on [0, 1) with 53 random bits: (next_u64() >> 11) * 2^-53 (exact).
  double uniform01() noexcept {
    return static_cast<double>(next_u64() >> 11) * 0x1.0p-53;
  }

  //! Uniform on [a, b): a + (b - a) u (b itself may come out through rounding).
  double uniform(double a, double b) noexcept { return detail::mul_then_add(b - a, uniform01(), a); }

  //! Standard normal N(0, 1), Marsaglia's polar method. Draws come in pairs: every other call
  //! returns the cached second value of the pair.
  double normal() noexcept {
    if (has_spare_normal_) {
      has_spare_normal_ = false;
      return spare_normal_;
    }
    double u = 0.0;
    double v = 0.0;
    double s = 0.0;
    do {
      u = 2.0 * uniform01() - 1.0;  // exact: uniform01() is a multiple of 2^-53
      v = 2.0 * uniform01() - 1.0;
      const double uu = u * u;
      s = detail::mul_then_add(v, v, uu);
    } while (s >= 1.0 || s == 0.0);
    const double factor = std::sqrt(-2.0 * detail::portable_log(s) / s);
    spare_normal_ = v * factor;
    has_spare_normal_ = true;
    return u * factor;
  }

  //! N(mean, stddev^2).
  double normal(double mean, double stddev) noexcept {
    return detail::mul_then_add(stddev, normal(), mean);
  }

  //! Uniformly distributed unit vector on the sphere, Marsaglia (1972): (u, v) uniform in the unit
  //! disc, s = u^2 + v^2, direction (2u sqrt(1-s), 2v sqrt(1-s), 1 - 2s).
  adcs::Vec3 unit_vector3() noexcept {
    double u = 0.0;
    double v = 0.0;
    double s = 0.0;
    do {
      u = 2.0 * uniform01() - 1.0;
      v = 2.0 * uniform01() - 1.0;
      const double uu = u * u;
      s = detail::mul_then_add(v, v, uu);
    } while (s >= 1.0);
    const double r = 2.0 * std::sqrt(1.0 - s);
    return adcs::Vec3(u * r, v * r, 1.0 - 2.0 * s);
  }

 private:
  static std::uint64_t rotl(std::uint64_t x, int k) noexcept { return (x << k) | (x >> (64 - k)); }

  static std::uint64_t splitmix64(std::uint64_t& state) noexcept {
    std::uint64_t z = (state += 0x9e3779b97f4a7c15u);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9u;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebu;
    return z ^ (z >> 31);
  }

  std::uint64_t s_[4] = {};
  double spare_normal_ = 0.0;
  bool has_spare_normal_ = false;
};

}  // namespace adcs::sim
