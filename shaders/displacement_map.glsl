// An image displacement (`"displacement": {"type": "image", ...}`) in GLSL: scene/displacement.cpp's
// offset scale × (value − midlevel) at texcoord × uv_repeat, the value from
// scene/displacement_map.cpp's sample_displacement_map — texel centres at (i + ½) / width,
// v up (row 0 of the texture is the image's top row, as DisplacementMap stores it), repeat or
// clamp — with the same texel indices and the same blends, fetched by hand (texelFetch at LOD
// 0, never the sampler's filtering). `precise`: no fused multiply-adds, as the C++ is built
// (-ffp-contract=off).
uniform sampler2D displacement_map;  // R32F: the map's values
uniform float displacement_scale;    // metres per unit of value
uniform float displacement_midlevel;
uniform float displacement_uv_repeat;
uniform int displacement_clamp;      // 1: "wrap": "clamp" (edges extend); 0: "repeat"

struct DisplacementTap {
  int i0, i1;
  float t;
};

// The texels either side of x along an axis of n texels, and the weight of the second.
DisplacementTap displacement_tap(float x, int n, bool clamp_edges) {
  precise float f = x * float(n) - 0.5;
  if (clamp_edges) {
    if (f <= 0.0) return DisplacementTap(0, 0, 0.0);
    if (f >= float(n - 1)) return DisplacementTap(n - 1, n - 1, 0.0);
    const int i = int(f);
    precise float t = f - float(i);
    return DisplacementTap(i, i + 1, t);
  }
  const float fl = floor(f);
  const int i = int(fl);
  // ((i mod n) + n) mod n without GLSL's % of a negative operand (undefined).
  const int i0 = i >= 0 ? i % n : n - 1 - (-(i + 1)) % n;
  precise float t = f - fl;
  return DisplacementTap(i0, (i0 + 1) % n, t);
}

float displacement_map_value(vec2 uv) {
  const ivec2 size = textureSize(displacement_map, 0);
  const bool clamp_edges = displacement_clamp != 0;
  precise float flipped = 1.0 - uv.y;
  const DisplacementTap x = displacement_tap(uv.x, size.x, clamp_edges), y = displacement_tap(flipped, size.y, clamp_edges);
  const float a = texelFetch(displacement_map, ivec2(x.i0, y.i0), 0).r, b = texelFetch(displacement_map, ivec2(x.i1, y.i0), 0).r;
  const float c = texelFetch(displacement_map, ivec2(x.i0, y.i1), 0).r, d = texelFetch(displacement_map, ivec2(x.i1, y.i1), 0).r;
  precise float top = a + (b - a) * x.t;
  precise float bottom = c + (d - c) * x.t;
  precise float value = top + (bottom - top) * y.t;
  return value;
}

// The offset along the normal (m) at the surface's texture coordinates.
float image_displacement_at(vec2 texcoord) {
  precise vec2 uv = texcoord * displacement_uv_repeat;
  precise float offset = displacement_scale * (displacement_map_value(uv) - displacement_midlevel);
  return offset;
}
