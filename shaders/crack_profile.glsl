// bark/dressing/crack_profile.cpp's CrackProfile::at in GLSL: the deepest V-profile among the
// crack segments whose half-width reaches a point (Spicker 2014 sec. 4.2: ψ = D·(w − d)/w),
// with the same noise, shoulder and detail. The segments sit in a shader storage buffer with
// a uniform grid over them (each segment listed in every cell its box ± the reach touches),
// so a point visits the segments of its own cell, as the C++ does.
// Not ported: the C++ limits the depth to 45 % of the mesh's thickness under the point (a ray
// cast); on trunks and branches thicker than 2.2 × the crack depth it never binds.

struct CrackSegment {
  vec4 a;  // xyz, half-width at a
  vec4 b;  // xyz, half-width at b
  vec4 c;  // chain coordinate, 0, 0, 0
};
layout(std430, binding = 0) readonly buffer CrackSegments { CrackSegment segments[]; };
layout(std430, binding = 1) readonly buffer CrackCells { uint cell_start[]; };  // #cells + 1
layout(std430, binding = 2) readonly buffer CrackItems { uint cell_items[]; };

uniform vec3 crack_grid_origin;
uniform float crack_grid_cell;
uniform ivec3 crack_grid_dims;
uniform uint crack_seed;
// width noise, depth noise scale, wall noise, wall size, max depth, depth per width
uniform float crack_noise, crack_wall_noise, crack_wall_size, crack_max_depth, crack_depth_per_width;
uniform float crack_shoulder, crack_shoulder_width, crack_detail, crack_detail_size;

struct CrackSample {
  float depth;     // metres below the surface
  float relative;  // depth / max depth in [0, 1]
  float mask;      // 1 inside a crack's width
  float chain;     // the nearest crack chain's coordinate
};

const float kCrackNoiseFrequency = 60.0;

int crack_cell(vec3 p) {
  const vec3 g = floor((p - crack_grid_origin) / crack_grid_cell);
  if (any(lessThan(g, vec3(0))) || any(greaterThanEqual(g, vec3(crack_grid_dims)))) return -1;
  const ivec3 i = ivec3(g);
  return (i.z * crack_grid_dims.y + i.y) * crack_grid_dims.x + i.x;
}

CrackSample crack_at(vec3 p, vec3 n) {
  CrackSample s = CrackSample(0.0, 0.0, 0.0, 0.0);
  float outside = 1.0 / 0.0;
  const int cell = crack_cell(p);
  // The noise only matters near a segment: far from every crack (an empty cell) the result is
  // the C++'s without evaluating it (llvmpipe runs this stage on one thread).
  if (cell >= 0 && cell_start[cell + 1] > cell_start[cell]) {
    const float mod_w = 1.0 + crack_noise * fbm(p * kCrackNoiseFrequency, crack_seed, 3);
    float mod_d = 1.0 + crack_noise * fbm(p * kCrackNoiseFrequency, crack_seed + 101u, 3);
    if (crack_wall_noise > 0.0) mod_d *= 1.0 + crack_wall_noise * fbm(p / crack_wall_size, crack_seed + 202u, 4);
    for (uint k = cell_start[cell]; k < cell_start[cell + 1]; ++k) {
      const CrackSegment g = segments[cell_items[k]];
      const vec3 ab = g.b.xyz - g.a.xyz;
      const float len2 = dot(ab, ab);
      const float t = len2 > 0.0 ? clamp(dot(p - g.a.xyz, ab) / len2, 0.0, 1.0) : 0.0;
      vec3 off = p - (g.a.xyz + t * ab);
      off -= dot(off, n) * n;  // distance across the surface
      const float d = length(off);
      const float w = ((1.0 - t) * g.a.w + t * g.b.w) * mod_w;
      if (d - w < outside) {
        outside = d - w;
        s.chain = g.c.x;
      }
      if (d >= w) continue;
      const float depth = min(crack_max_depth, crack_depth_per_width * w) * mod_d * (1.0 - d / w);
      if (depth > s.depth) s.depth = depth;
      s.mask = 1.0;
    }
  }
  s.relative = crack_max_depth > 0.0 ? clamp(s.depth / crack_max_depth, 0.0, 1.0) : 0.0;
  if (crack_shoulder > 0.0 && crack_shoulder_width > 0.0 && !isinf(outside)) {
    const float t = clamp(outside / crack_shoulder_width, 0.0, 1.0);
    s.depth += crack_shoulder * crack_max_depth * (1.0 - t) * (1.0 - t);
  }
  if (crack_detail > 0.0) s.depth += crack_detail * crack_max_depth * fbm(p / crack_detail_size, crack_seed + 303u, 4);
  return s;
}
