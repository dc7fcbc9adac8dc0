// Integer hashing: every random number in Phellem is a pure function of its inputs.
#pragma once

#include <cstdint>

namespace phellem {

// 32-bit integer finalizer (Wellons' "lowbias32").
inline uint32_t hash_u32(uint32_t x) {
  x ^= x >> 16;
  x *= 0x7feb352dU;
  x ^= x >> 15;
  x *= 0x846ca68bU;
  x ^= x >> 16;
  return x;
}

inline uint32_t hash_combine(uint32_t seed, uint32_t v) { return hash_u32(seed ^ (v + 0x9e3779b9U + (seed << 6) + (seed >> 2))); }

template <typename... Rest>
inline uint32_t hash_all(uint32_t a, Rest... rest) {
  uint32_t h = hash_u32(a);
  ((h = hash_combine(h, static_cast<uint32_t>(rest))), ...);
  return h;
}

inline uint64_t mix64(uint64_t z) {  // splitmix64 finalizer
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}

// A 64-bit seed for code that draws from 32-bit seeds (noise, the pixel sampler, crack
// profiles): the identity below 2^32, so a seed < 2^32 gives the same numbers it always gave;
// above, the high half is hashed into the low one (hash_u32(0) == 0, which keeps the identity).
inline uint32_t fold_seed(uint64_t seed) {
  const uint32_t high = uint32_t(seed >> 32);
  return uint32_t(seed) ^ (high == 0 ? 0u : hash_u32(high));
}

// Uniform float in [0, 1) from the top 24 bits.
inline float u32_to_unit_float(uint32_t x) { return float(x >> 8) * 0x1p-24f; }

}  // namespace phellem
