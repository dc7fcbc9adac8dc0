// bark/dressing/field_bark_surface.cpp's bilinear FieldBarkSurface lookups in GLSL: texel
// centres at (i + ½) / width, u wraps (cyclic strips), v clamps. Texels are fetched and
// blended by hand (texelFetch, an explicit LOD 0), as the C++ does, not by the sampler.
uniform sampler2D field_depth_mask;  // R: depth (m), G: fracture coverage
uniform sampler2D field_albedo;      // RGB: dressed albedo (depth darkening included)
uniform float field_max_depth;

struct FieldSample {
  float depth, mask, relative;
  vec3 albedo;
};

FieldSample field_at(vec2 uv) {
  const ivec2 size = textureSize(field_depth_mask, 0);
  const float x = (uv.x - floor(uv.x)) * float(size.x) - 0.5, y = clamp(uv.y, 0.0, 1.0) * float(size.y) - 0.5;
  const float fx = floor(x), fy = floor(y);
  const float tx = x - fx, ty = y - fy;
  // (fx mod width + width) mod width as the C++, without GLSL's % of a negative operand
  // (undefined: llvmpipe gave the wrong column left of the first texel centre, at u = 0).
  const int ix = int(fx);
  const int x0 = ix >= 0 ? ix % size.x : size.x - 1 - (-(ix + 1)) % size.x, x1 = (x0 + 1) % size.x;
  const int y0 = clamp(int(fy), 0, size.y - 1), y1 = clamp(int(fy) + 1, 0, size.y - 1);
  const vec4 a = texelFetch(field_depth_mask, ivec2(x0, y0), 0), b = texelFetch(field_depth_mask, ivec2(x1, y0), 0);
  const vec4 c = texelFetch(field_depth_mask, ivec2(x0, y1), 0), d = texelFetch(field_depth_mask, ivec2(x1, y1), 0);
  const vec4 v = (a * (1.0 - tx) + b * tx) * (1.0 - ty) + (c * (1.0 - tx) + d * tx) * ty;
  const vec4 ca = texelFetch(field_albedo, ivec2(x0, y0), 0), cb = texelFetch(field_albedo, ivec2(x1, y0), 0);
  const vec4 cc = texelFetch(field_albedo, ivec2(x0, y1), 0), cd = texelFetch(field_albedo, ivec2(x1, y1), 0);
  const vec4 col = (ca * (1.0 - tx) + cb * tx) * (1.0 - ty) + (cc * (1.0 - tx) + cd * tx) * ty;
  FieldSample s;
  s.depth = v.x;
  s.mask = v.y;
  s.relative = clamp(v.x / field_max_depth, 0.0, 1.0);
  s.albedo = col.rgb;
  return s;
}
