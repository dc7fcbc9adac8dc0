// Seeded noise, one family for every model and the renderer: 3D gradient noise (Perlin 2002,
// "Improving Noise") and fractal sums of it, and tileable 2D value noise.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "util/math.h"

namespace phellem {

float gradient_noise(const Vec3f& p, uint32_t seed);                       // in about [-1, 1]
float fbm(const Vec3f& p, uint32_t seed, int octaves, float gain = 0.5f);  // in about [-1, 1]
// fbm band-limited to a filter width of `footprint` lattice cells (of the first octave):
// octaves finer than the Nyquist limit are faded out and replaced by their mean, 0
// ("clamping", Ebert et al., Texturing & Modeling, ch. 2) and not evaluated at all.
float fbm_filtered(const Vec3f& p, uint32_t seed, int octaves, float footprint, float gain = 0.5f);
// Weight of a noise band whose lattice cell spans `footprint` filter widths: 1 below a
// quarter cell, 0 from half a cell (Nyquist) on, linear between.
inline float band_weight(float footprint) { return std::clamp(2.0f - 4.0f * footprint, 0.0f, 1.0f); }

// 2D value noise in [0, 1] on a unit lattice, smoothstep-interpolated; the lattice wraps after
// `nx` × `ny` cells when those are non-zero (tileable bark dressing). Inline: each caller
// compiles it with its own options.
// The lattice value at (x, y): a 64-bit hash of the wrapped cell and the seed.
inline float lattice_hash01(int64_t x, int64_t y, uint32_t seed, int64_t nx, int64_t ny) {
  if (nx > 0) x = ((x % nx) + nx) % nx;
  if (ny > 0) y = ((y % ny) + ny) % ny;
  uint64_t h = uint64_t(x) * 0x9e3779b97f4a7c15ULL ^ (uint64_t(y) + 0x632be59bd9b4e019ULL) * 0xc2b2ae3d27d4eb4fULL ^ seed;
  h ^= h >> 31;
  h *= 0xbf58476d1ce4e5b9ULL;
  h ^= h >> 29;
  return float(h >> 40) * (1.0f / 16777216.0f);
}

inline float tileable_value_noise(double x, double y, uint32_t seed, int64_t nx, int64_t ny) {
  const double fx = std::floor(x), fy = std::floor(y);
  const int64_t ix = int64_t(fx), iy = int64_t(fy);
  double tx = x - fx, ty = y - fy;
  tx = tx * tx * (3 - 2 * tx);
  ty = ty * ty * (3 - 2 * ty);
  const float a = lattice_hash01(ix, iy, seed, nx, ny), b = lattice_hash01(ix + 1, iy, seed, nx, ny);
  const float c = lattice_hash01(ix, iy + 1, seed, nx, ny), d = lattice_hash01(ix + 1, iy + 1, seed, nx, ny);
  return float((a * (1 - tx) + b * tx) * (1 - ty) + (c * (1 - tx) + d * tx) * ty);
}

}  // namespace phellem
