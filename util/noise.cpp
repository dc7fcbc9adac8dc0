#include "util/noise.h"

#include "util/hash.h"

namespace phellem {

namespace {

inline float fade(float t) { return t * t * t * (t * (t * 6 - 15) + 10); }

// The 12 cube-edge gradients of improved Perlin noise, looked up (a switch on random
// hashes mispredicts most of its branches).
constexpr float kGradients[12][3] = {{1, 1, 0},  {-1, 1, 0},  {1, -1, 0}, {-1, -1, 0}, {1, 0, 1},  {-1, 0, 1},
                                     {1, 0, -1}, {-1, 0, -1}, {0, 1, 1},  {0, -1, 1},  {0, 1, -1}, {0, -1, -1}};

inline float grad(uint32_t h, float x, float y, float z) {
  const float* g = kGradients[(uint64_t(h) * 12u) >> 32];  // uniform in [0, 12) without a division
  return g[0] * x + g[1] * y + g[2] * z;
}

}  // namespace

float gradient_noise(const Vec3f& p, uint32_t seed) {
  const float fx = std::floor(p.x()), fy = std::floor(p.y()), fz = std::floor(p.z());
  const int32_t ix = int32_t(fx), iy = int32_t(fy), iz = int32_t(fz);
  const float x = p.x() - fx, y = p.y() - fy, z = p.z() - fz;
  // Lattice hashes built coordinate by coordinate: 2 + 4 + 8 hashes for the 8 corners
  // instead of 4 per corner.
  const uint32_t hx[2] = {hash_combine(seed, uint32_t(ix)), hash_combine(seed, uint32_t(ix + 1))};
  uint32_t hxy[2][2], h[2][2][2];
  for (int a = 0; a < 2; ++a)
    for (int b = 0; b < 2; ++b) {
      hxy[a][b] = hash_combine(hx[a], uint32_t(iy + b));
      for (int c = 0; c < 2; ++c) h[a][b][c] = hash_combine(hxy[a][b], uint32_t(iz + c));
    }
  const float u = fade(x), v = fade(y), w = fade(z);
  auto lerp = [](float t, float a, float b) { return a + t * (b - a); };
  const float x00 = lerp(u, grad(h[0][0][0], x, y, z), grad(h[1][0][0], x - 1, y, z));
  const float x10 = lerp(u, grad(h[0][1][0], x, y - 1, z), grad(h[1][1][0], x - 1, y - 1, z));
  const float x01 = lerp(u, grad(h[0][0][1], x, y, z - 1), grad(h[1][0][1], x - 1, y, z - 1));
  const float x11 = lerp(u, grad(h[0][1][1], x, y - 1, z - 1), grad(h[1][1][1], x - 1, y - 1, z - 1));
  return lerp(w, lerp(v, x00, x10), lerp(v, x01, x11));
}

float fbm(const Vec3f& p, uint32_t seed, int octaves, float gain) { return fbm_filtered(p, seed, octaves, 0.0f, gain); }

float fbm_filtered(const Vec3f& p, uint32_t seed, int octaves, float footprint, float gain) {
  float sum = 0, amp = 1, norm = 0;
  Vec3f q = p;
  for (int i = 0; i < octaves; ++i) {
    const float w = band_weight(footprint);
    if (w > 0) sum += w * amp * gradient_noise(q, hash_combine(seed, uint32_t(i)));
    norm += amp;
    amp *= gain;
    q *= 2.03f;
    footprint *= 2.03f;
  }
  return sum / norm;
}

}  // namespace phellem
