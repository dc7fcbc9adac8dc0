// util/hash.h and util/noise.h in GLSL, operation for operation, so the preview displaces by
// the same noise as the path tracer (tests/preview/test_preview_displacement.cpp holds them equal).

uint hash_u32(uint x) {  // Wellons' lowbias32
  x ^= x >> 16;
  x *= 0x7feb352du;
  x ^= x >> 15;
  x *= 0x846ca68bu;
  x ^= x >> 16;
  return x;
}

uint hash_combine(uint seed, uint v) { return hash_u32(seed ^ (v + 0x9e3779b9u + (seed << 6) + (seed >> 2))); }

float noise_fade(float t) { return t * t * t * (t * (t * 6.0 - 15.0) + 10.0); }

const vec3 kGradients[12] = vec3[12](vec3(1, 1, 0), vec3(-1, 1, 0), vec3(1, -1, 0), vec3(-1, -1, 0), vec3(1, 0, 1),
                                     vec3(-1, 0, 1), vec3(1, 0, -1), vec3(-1, 0, -1), vec3(0, 1, 1), vec3(0, -1, 1),
                                     vec3(0, 1, -1), vec3(0, -1, -1));

float noise_grad(uint h, float x, float y, float z) {
  uint hi, lo;
  umulExtended(h, 12u, hi, lo);  // (h · 12) >> 32: uniform in [0, 12)
  const vec3 g = kGradients[hi];
  return g.x * x + g.y * y + g.z * z;
}

float gradient_noise(vec3 p, uint seed) {
  const vec3 f = floor(p);
  const ivec3 i = ivec3(f);
  const float x = p.x - f.x, y = p.y - f.y, z = p.z - f.z;
  uint hx[2] = uint[2](hash_combine(seed, uint(i.x)), hash_combine(seed, uint(i.x + 1)));
  uint h[8];  // [a][b][c] at a·4 + b·2 + c
  for (int a = 0; a < 2; ++a)
    for (int b = 0; b < 2; ++b) {
      const uint hxy = hash_combine(hx[a], uint(i.y + b));
      for (int c = 0; c < 2; ++c) h[a * 4 + b * 2 + c] = hash_combine(hxy, uint(i.z + c));
    }
  const float u = noise_fade(x), v = noise_fade(y), w = noise_fade(z);
  const float x00 = mix_exact(u, noise_grad(h[0], x, y, z), noise_grad(h[4], x - 1.0, y, z));
  const float x10 = mix_exact(u, noise_grad(h[2], x, y - 1.0, z), noise_grad(h[6], x - 1.0, y - 1.0, z));
  const float x01 = mix_exact(u, noise_grad(h[1], x, y, z - 1.0), noise_grad(h[5], x - 1.0, y, z - 1.0));
  const float x11 = mix_exact(u, noise_grad(h[3], x, y - 1.0, z - 1.0), noise_grad(h[7], x - 1.0, y - 1.0, z - 1.0));
  return mix_exact(w, mix_exact(v, x00, x10), mix_exact(v, x01, x11));
}

// fbm at footprint 0 (every band weight 1): Σ ampᵢ · noise(p · 2.03ⁱ) / Σ ampᵢ.
float fbm(vec3 p, uint seed, int octaves) {
  float sum = 0.0, amp = 1.0, norm = 0.0;
  vec3 q = p;
  for (int i = 0; i < octaves; ++i) {
    sum += amp * gradient_noise(q, hash_combine(seed, uint(i)));
    norm += amp;
    amp *= 0.5;
    q *= 2.03;
  }
  return sum / norm;
}
