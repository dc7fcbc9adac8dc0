#include "renderer/sampler.h"

#include <array>

#include "util/hash.h"

namespace phellem {

namespace {

// Sobol generator matrices for the first four dimensions (Joe & Kuo 2008 direction numbers:
// dim 0 the van der Corput sequence, then primitive polynomials x+1, x²+x+1, x³+x+1).
struct SobolMatrices {
  std::array<std::array<uint32_t, 32>, 4> v;
  SobolMatrices() {
    for (int i = 0; i < 32; ++i) v[0][i] = 1u << (31 - i);
    auto build = [&](int d, int s, uint32_t a, std::initializer_list<uint32_t> m_init) {
      std::array<uint32_t, 32> m{};
      int k = 0;
      for (uint32_t mi : m_init) m[k++] = mi;
      for (int i = s; i < 32; ++i) {
        uint32_t x = m[i - s] ^ (m[i - s] << s);
        for (int j = 1; j < s; ++j) x ^= ((a >> (s - 1 - j)) & 1u) * (m[i - j] << j);
        m[i] = x;
      }
      for (int i = 0; i < 32; ++i) v[d][i] = m[i] << (31 - i);
    };
    build(1, 1, 0, {1});
    build(2, 2, 1, {1, 3});
    build(3, 3, 1, {1, 3, 1});
    // Byte tables: the product of a generator matrix with 8 bits of the index at a time.
    // `reversed` works entirely in the bit-reversed domain (Burley 2020, sec. 3): input the
    // reversed index, output the reversed Sobol value, which is what Owen scrambling needs.
    for (int d = 0; d < 4; ++d)
      for (int k = 0; k < 4; ++k)
        for (int b = 0; b < 256; ++b) {
          uint32_t x = 0, xr = 0;
          for (int bit = 0; bit < 8; ++bit)
            if (b & (1 << bit)) {
              x ^= v[d][8 * k + bit];
              xr ^= reverse(v[d][31 - (8 * k + bit)]);
            }
          table[d][k][b] = x;
          reversed[d][k][b] = xr;
        }
  }
  static uint32_t reverse(uint32_t x) {
    x = ((x >> 1) & 0x55555555u) | ((x & 0x55555555u) << 1);
    x = ((x >> 2) & 0x33333333u) | ((x & 0x33333333u) << 2);
    x = ((x >> 4) & 0x0F0F0F0Fu) | ((x & 0x0F0F0F0Fu) << 4);
    return __builtin_bswap32(x);
  }
  std::array<std::array<std::array<uint32_t, 256>, 4>, 4> table, reversed;
};
const SobolMatrices kSobol;

inline uint32_t reverse_bits(uint32_t x) { return SobolMatrices::reverse(x); }

// Reversed Sobol value of the point whose reversed index is r.
inline uint32_t sobol_reversed(uint32_t r, int dim) {
  const auto& t = kSobol.reversed[dim];
  return t[0][r & 0xFF] ^ t[1][(r >> 8) & 0xFF] ^ t[2][(r >> 16) & 0xFF] ^ t[3][r >> 24];
}

// Laine & Karras 2011 style hash that only propagates bits upwards (Burley 2020, listing 2).
inline uint32_t laine_karras_permutation(uint32_t x, uint32_t seed) {
  x += seed;
  x ^= x * 0x6c50b47cu;
  x ^= x * 0xb82f1e52u;
  x ^= x * 0xc7afe638u;
  x ^= x * 0x8d22f6e6u;
  return x;
}

}  // namespace

uint32_t sobol_u32(uint32_t index, int dim) {
  const auto& t = kSobol.table[dim];
  return t[0][index & 0xFF] ^ t[1][(index >> 8) & 0xFF] ^ t[2][(index >> 16) & 0xFF] ^ t[3][index >> 24];
}

uint32_t nested_uniform_scramble(uint32_t x, uint32_t seed) {
  x = reverse_bits(x);
  x = laine_karras_permutation(x, seed);
  return reverse_bits(x);
}

uint32_t Sampler::hash_pixel(uint32_t px, uint32_t py, uint32_t seed) { return hash_all(px, py, seed, 0x5eedu); }

Sampler::Sampler(uint32_t pixel_seed, uint32_t sample_index)
    : pixel_seed_(pixel_seed), reversed_index_(reverse_bits(sample_index)) {}

// Written lane-wise (four dimensions side by side) so that the compiler vectorizes the
// hashing; target_clones adds an AVX2 version (32-bit vector multiplies) chosen at load time.
__attribute__((target_clones("avx2", "default"))) Vec4f Sampler::get4d() {
  const uint32_t set_seed = hash_combine(pixel_seed_, dimension_set_++);
  // Shuffle the sample order per pixel and dimension set (Burley 2020, sec. 4), then
  // Owen-scramble each dimension independently:
  //   x_d = nested_uniform_scramble(sobol(nested_uniform_scramble(index, s)), s_d).
  // Both scrambles reverse, permute and reverse back; staying in the reversed domain between
  // them leaves one reversal per dimension (tests/renderer/test_sampler.cpp checks the identity).
  const uint32_t r = laine_karras_permutation(reversed_index_, set_seed);
  alignas(16) uint32_t x[4];
  for (int d = 0; d < 4; ++d) x[d] = sobol_reversed(r, d);
  for (int d = 0; d < 4; ++d) x[d] = reverse_bits(laine_karras_permutation(x[d], hash_combine(set_seed, uint32_t(d) + 1)));
  // u32_to_unit_float: the top 24 bits, so the result is always < 1.
  return Vec4f(float(x[0] >> 8), float(x[1] >> 8), float(x[2] >> 8), float(x[3] >> 8)) * 0x1p-24f;
}

float Sampler::get1d() { return get4d()[0]; }
Vec2f Sampler::get2d() {
  const Vec4f v = get4d();
  return Vec2f(v[0], v[1]);
}

}  // namespace phellem
