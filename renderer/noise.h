// Seeded 3D gradient noise (Perlin 2002, "Improving Noise") and fractal sums of it.
#pragma once

#include <cstdint>

#include "renderer/math.h"

namespace phellem {

float gradient_noise(const Vec3f& p, uint32_t seed);                // in about [-1, 1]
float fbm(const Vec3f& p, uint32_t seed, int octaves, float gain = 0.5f);  // in about [-1, 1]

}  // namespace phellem
