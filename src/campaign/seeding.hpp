#pragma once
// Counter-based seeding of Monte Carlo campaigns (issue 18): every random number of run k is a
// fixed function of (seed0, k, the name of what is drawn), never of the order runs are executed
// in, of --jobs or of the shard split. So a run is reproduced alone from (seed0, k), and a
// campaign split over Slurm array tasks gives the same table bit for bit.
//
// The stream seed is a hash of the three: FNV-1a over the name, then splitmix64 finalisers over
// (seed0, k, name hash) — the mixing xoshiro's authors recommend for seeding (sim/random.hpp's
// Rng seeds its state the same way). Distinct names give unrelated streams; neighbouring run
// indices or seed0 values do too (unlike seed0 + k, which makes campaign 1's run 1 campaign 2's
// run 0).
#include <cstdint>
#include <string_view>

#include "sim/random.hpp"

namespace adcs::sim::campaign {

//! splitmix64's output function (Steele, Lea, Flood 2014): a bijective 64-bit mixer.
constexpr std::uint64_t mix64(std::uint64_t z) noexcept {
  z += 0x9e3779b97f4a7c15ULL;
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}

//! FNV-1a, 64 bit, of the bytes of `name`.
constexpr std::uint64_t name_hash(std::string_view name) noexcept {
  std::uint64_t h = 0xcbf29ce484222325ULL;
  for (char c : name) {
    h ^= static_cast<unsigned char>(c);
    h *= 0x100000001b3ULL;
  }
  return h;
}

//! The seed of the stream `name` of run `run` of the campaign seeded `seed0`.
constexpr std::uint64_t stream_seed(std::uint64_t seed0, std::uint64_t run, std::string_view name) noexcept {
  return mix64(mix64(mix64(seed0) ^ run) ^ name_hash(name));
}

//! The generator of that stream.
inline Rng stream(std::uint64_t seed0, std::uint64_t run, std::string_view name) noexcept {
  return Rng(stream_seed(seed0, run, name));
}

//! The scenario seed of run `run` (RunContext::seed: the scenario's own draws, e.g. a random
//! initial attitude). Never 0, which scenarios read as "the declared values, no draw".
constexpr std::uint64_t run_seed(std::uint64_t seed0, std::uint64_t run) noexcept {
  const std::uint64_t s = stream_seed(seed0, run, "run");
  return s == 0 ? 1 : s;
}

}  // namespace adcs::sim::campaign
