// Seeded 3D gradient noise (Perlin 2002, "Improving Noise") and fractal sums of it.
#pragma once

#include <cstdint>

#include "util/math.h"

namespace phellem {

float gradient_noise(const Vec3f& p, uint32_t seed);                // in about [-1, 1]
float fbm(const Vec3f& p, uint32_t seed, int octaves, float gain = 0.5f);  // in about [-1, 1]
// fbm band-limited to a filter width of `footprint` lattice cells (of the first octave):
// octaves finer than the Nyquist limit are faded out and replaced by their mean, 0
// ("clamping", Ebert et al., Texturing & Modeling, ch. 2) and not evaluated at all.
float fbm_filtered(const Vec3f& p, uint32_t seed, int octaves, float footprint, float gain = 0.5f);
// Weight of a noise band whose lattice cell spans `footprint` filter widths: 1 below a
// quarter cell, 0 from half a cell (Nyquist) on, linear between.
inline float band_weight(float footprint) { return std::clamp(2.0f - 4.0f * footprint, 0.0f, 1.0f); }

}  // namespace phellem
