// bark/dressing/bark_tints.cpp in GLSL: the stress bark's per-crack tint (a palette sorted by
// luminance, looked up by the crack chain's coordinate) and per-plate tint (a Voronoi
// partition of space warped by noise, each plate picking a palette entry by the hash of its
// cell). Compiled in only for bark with tints (BARK_TINTS).

uniform vec3 ridge_tints[64], fissure_tints[64];
uniform int ridge_tint_count, fissure_tint_count;
uniform float tint_size;  // plate cells (m)
uniform uint tint_seed;   // the plates' seed

// TintPalette::at on the fissure palette (uniform arrays are read in place: passing one to a
// function would copy it).
vec3 fissure_palette_at(float t) {
  const int n = fissure_tint_count;
  if (n == 0) return vec3(1.0);
  const float x = clamp(t * float(n) - 0.5, 0.0, float(n - 1));
  const int i = min(n - 1, int(x)), j = min(n - 1, i + 1);
  return mix(fissure_tints[i], fissure_tints[j], x - float(i));
}

// TintPalette::pick on the ridge palette.
vec3 ridge_palette_pick(float t) {
  const int n = ridge_tint_count;
  if (n == 0) return vec3(1.0);
  return ridge_tints[min(n - 1, int(clamp(t, 0.0, 1.0) * float(n)))];
}

// One plate's site and coordinate (the cell's hash, as bark/dressing/bark_tints.cpp builds it).
vec3 plate_site(ivec3 cell, uint hxy, out float coordinate) {
  const uint h = hash_combine(hxy, uint(cell.z));
  const uint j = hash_u32(h ^ 0x2545f491u);
  coordinate = float(h >> 8) * (1.0 / 16777216.0);
  return vec3(cell) + (vec3(uvec3(j, j >> 10, j >> 20) & 1023u) + 0.5) / 1024.0;
}

// Two passes over the 27 cells (the nearest distance, then the blend), so nothing is kept in
// an array: llvmpipe spills indexed arrays to memory.
vec3 plate_tint(vec3 p) {
  if (ridge_tint_count == 0) return vec3(1.0);
  vec3 q = p / tint_size;
  q += 0.4 * vec3(fbm(q, tint_seed + 11u, 1), fbm(q, tint_seed + 12u, 1), fbm(q, tint_seed + 13u, 1));
  const ivec3 c = ivec3(floor(q));
  float nearest = 1.0 / 0.0, second = 1.0 / 0.0, coordinate, nearest_coordinate = 0.5;
  for (int x = -1; x <= 1; ++x) {
    const uint hx = hash_combine(tint_seed, uint(c.x + x));
    for (int y = -1; y <= 1; ++y) {
      const uint hxy = hash_combine(hx, uint(c.y + y));
      for (int z = -1; z <= 1; ++z) {
        const float d = length(plate_site(c + ivec3(x, y, z), hxy, coordinate) - q);
        if (d < nearest) {
          second = nearest;
          nearest = d;
          nearest_coordinate = coordinate;
        } else {
          second = min(second, d);
        }
      }
    }
  }
  // Inside a plate (most of the surface) no other site is within the band: its tint alone.
  if (second - nearest >= 0.15) return ridge_palette_pick(nearest_coordinate);
  vec3 sum = vec3(0.0);
  float total = 0.0;
  for (int x = -1; x <= 1; ++x) {
    const uint hx = hash_combine(tint_seed, uint(c.x + x));
    for (int y = -1; y <= 1; ++y) {
      const uint hxy = hash_combine(hx, uint(c.y + y));
      for (int z = -1; z <= 1; ++z) {
        const float t = (length(plate_site(c + ivec3(x, y, z), hxy, coordinate) - q) - nearest) / 0.15;
        if (t >= 1.0) continue;
        const float w = 1.0 - t * t * (3.0 - 2.0 * t);
        sum += w * ridge_palette_pick(coordinate);
        total += w;
      }
    }
  }
  return sum / total;
}
