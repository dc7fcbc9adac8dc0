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

inline uint32_t hash_combine(uint32_t seed, uint32_t v) {
  return hash_u32(seed ^ (v + 0x9e3779b9U + (seed << 6) + (seed >> 2)));
}

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

// Uniform float in [0, 1) from the top 24 bits.
inline float u32_to_unit_float(uint32_t x) { return float(x >> 8) * 0x1p-24f; }

}  // namespace phellem
