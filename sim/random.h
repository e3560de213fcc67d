// Counter-based randomness: every random number is a pure hash of (seed, stream, a, b), so a
// drop's fate never depends on thread count, step order or which other drops exist.
#pragma once

#include <cmath>
#include <cstdint>

namespace raintrace::sim {

/// Independent streams, one per kind of random event.
enum class Stream : std::uint64_t {
  spawn_count = 1,     ///< how many drops enter in a substep (a = substep)
  drop = 2,            ///< a drop's birth properties (a = drop id, b = dimension)
  fill = 3,            ///< the initial fill (a = drop id, b = dimension)
  splash = 4,          ///< crown splashes (a = impact key, b = sim/splash.cpp's dimensions)
  breakup = 5,         ///< fragments of a breaking drop (a = drop id, b = fragment·8 + dimension)
  lightning = 6,       ///< strike times (a = strike number)
  bolt = 7,            ///< a bolt's skeleton (a = strike number, b = counter)
  turbulence = 8,      ///< turbulence modes (a = mode, b = dimension)
  puddles = 9,         ///< the puddle field's cosine terms (a = term, b = dimension)
  ground_count = 10,   ///< impacts sampled in a ground cell (a = cell, b = time slot)
  ground_impact = 11,  ///< one sampled impact (a = cell, b = slot·2^20 + impact·16 + dimension)
  ground_detail = 12,  ///< whether a drop's impact survives the level of detail (a = drop id)
  bolt_kinks = 13,     ///< a bolt channel's fine kinks (a = strike number, b = counter)
};

/// SplitMix64's finaliser: a bijective mix with full avalanche.
constexpr std::uint64_t mix64(std::uint64_t x) {
  x += 0x9e3779b97f4a7c15ULL;
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ULL;
  x = (x ^ (x >> 27)) * 0x94d049bb133111ebULL;
  return x ^ (x >> 31);
}

/// Hash of a counter tuple; chained mixing so that (a, b) and (b, a) differ.
constexpr std::uint64_t hash_key(std::uint64_t seed, Stream stream, std::uint64_t a,
                                 std::uint64_t b = 0) {
  return mix64(mix64(mix64(seed ^ mix64(static_cast<std::uint64_t>(stream))) ^ a) ^ b);
}

/// Uniform in [0, 1) with 53 random bits.
constexpr double to_unit(std::uint64_t h) {
  return static_cast<double>(h >> 11) * (1.0 / 9007199254740992.0);
}

inline double uniform(std::uint64_t seed, Stream stream, std::uint64_t a, std::uint64_t b = 0) {
  return to_unit(hash_key(seed, stream, a, b));
}

/// Exponential with mean 1 (inverse CDF; 1 − u is in (0, 1] so the log is finite).
inline double exponential(std::uint64_t seed, Stream stream, std::uint64_t a, std::uint64_t b = 0) {
  return -std::log(1.0 - uniform(seed, stream, a, b));
}

}  // namespace raintrace::sim
