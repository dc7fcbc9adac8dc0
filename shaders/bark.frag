// Shading of the preview (Spicker 2014 ch. 4's fragment stage): normals from the displaced
// surface (screen-space derivatives of the displaced position, carried from the flat facet
// onto the smooth interpolated normal, as the path tracer's dicer does), the bark's colour — the
// material's base colour darkened with crack depth and blended into the fissure colour, or a
// strip field's dressed albedo — lit by a sun and a sky ambient term. Also writes the crack
// mask and the distance from the camera (the path tracer's `crack` and `depth` AOVs).
in vec3 te_base;
in vec3 te_world;
in vec4 te_attributes;
in vec3 te_flat;
in vec3 te_normal;

layout(location = 0) out vec4 out_color;
layout(location = 1) out vec4 out_aov;  // R: crack mask, G: normalized crack depth, B: distance, A: 1

uniform vec3 camera_position;
uniform vec3 base_color;
uniform vec3 ridge_color, fissure_color;
uniform int colored;             // stress bark with a photo's colours
uniform float darkening;         // albedo × (1 − darkening × depth)
uniform int show_darkening;      // key toggle
uniform int show_mask;           // key toggle: paint the crack mask
uniform vec3 sun_direction;      // towards the sun
uniform vec3 sun_color, sky_color, ground_color;

void main() {
  const vec3 to_eye = camera_position - te_world;
  vec3 smooth_n = normalize(te_normal);
  if (dot(smooth_n, to_eye) < 0.0) smooth_n = -smooth_n;
  vec3 displaced_n = normalize(cross(dFdx(te_world), dFdy(te_world)));
  vec3 flat_n = normalize(cross(dFdx(te_flat), dFdy(te_flat)));
  if (dot(displaced_n, smooth_n) < 0.0) displaced_n = -displaced_n;
  if (dot(flat_n, smooth_n) < 0.0) flat_n = -flat_n;
  const vec3 carried = displaced_n - flat_n + smooth_n;
  const vec3 n = dot(carried, carried) > 1e-12 ? normalize(carried) : smooth_n;
  float mask = 0.0, depth = 0.0;
  vec3 albedo = base_color;
  if (BARK_KIND == 1) {  // CrackBarkSurface::shade
    depth = te_attributes.x;
    mask = te_attributes.y;
#if BARK_TINTS
    const vec3 ridge_tint = plate_tint(te_base), fissure_tint = fissure_palette_at(te_attributes.z);
#else
    const vec3 ridge_tint = vec3(1.0), fissure_tint = vec3(1.0);
#endif
    if (colored != 0)
      albedo = mix(ridge_color * ridge_tint, fissure_color * fissure_tint, mask);
    else
      albedo *= mix(ridge_tint, fissure_tint, mask);
    if (show_darkening != 0) albedo *= 1.0 - darkening * depth;
  } else if (BARK_KIND == 2) {
    const FieldSample f = field_at(te_attributes.xy);
    depth = f.relative;
    mask = f.mask;
    albedo = f.albedo;
  }
  if (show_mask != 0) albedo = mix(albedo, vec3(0.9, 0.2, 0.1), mask);
  const float sun = max(dot(n, normalize(sun_direction)), 0.0);
  const vec3 ambient = mix(ground_color, sky_color, 0.5 + 0.5 * n.y);
  const vec3 linear = albedo * (sun * sun_color + ambient);
  // The display transform: sRGB's encoding (the path tracer's PNG goes through OCIO's sRGB view).
  const vec3 c = clamp(linear, 0.0, 1.0);
  const vec3 srgb = mix(12.92 * c, 1.055 * pow(c, vec3(1.0 / 2.4)) - 0.055, step(0.0031308, c));
  out_color = vec4(srgb, 1.0);
  out_aov = vec4(mask, depth, length(to_eye), 1.0);
}
