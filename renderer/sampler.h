// Low-discrepancy sampler: hash-based Owen-scrambled, shuffled Sobol points (Burley 2020,
// "Practical Hash-based Owen Scrambling", JCGT 9(4)). Each sample is a pure function of
// (pixel, sample index, dimension, seed), so images do not depend on the thread count.
#pragma once

#include <cstdint>

#include "util/math.h"

namespace phellem {

class Sampler {
 public:
  Sampler(uint32_t px, uint32_t py, uint32_t sample_index, uint32_t seed) : Sampler(hash_pixel(px, py, seed), sample_index) {}
  // With the pixel's seed hashed once per pixel by the caller (hash_pixel).
  Sampler(uint32_t pixel_seed, uint32_t sample_index);

  // Next 1D / 2D value; each call consumes one 4D Sobol "dimension set".
  float get1d();
  Vec2f get2d();
  // Four decorrelated dimensions from one Owen-scrambled 4D Sobol point.
  Vec4f get4d();

  static uint32_t hash_pixel(uint32_t px, uint32_t py, uint32_t seed);

 private:
  uint32_t pixel_seed_;
  uint32_t reversed_index_;  // sample index with its bits reversed
  uint32_t dimension_set_ = 0;
};

// The raw building blocks (exposed for tests).
uint32_t sobol_u32(uint32_t index, int dim);  // dim ∈ [0, 4)
uint32_t nested_uniform_scramble(uint32_t x, uint32_t seed);

}  // namespace phellem
