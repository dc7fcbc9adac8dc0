// Displacement of the tessellated surface by the bark (bark/dressing/bark_surface.h): the
// stress model's crack V-profiles or the strip model's FractureField depth, plus an image
// displacement at the interpolated texcoords (IMAGE_DISPLACEMENT, shaders/displacement_map.glsl)
// — the two offsets add, as the path tracer's dicer adds them — along the interpolated normal,
// exactly as the dicer displaces its vertices.
layout(triangles, equal_spacing, ccw) in;

in vec3 tc_position[];
in vec3 tc_normal[];
in vec2 tc_param[];
in vec2 tc_texcoord[];

out vec3 te_base;       // undisplaced point (object space)
out vec3 te_world;      // displaced point (world space)
out vec4 te_attributes; // the BarkSurface attributes (depth, mask, chain, 0)
out vec3 te_flat;       // undisplaced point (world space): its derivatives give the flat facet
out vec3 te_normal;     // interpolated base normal (world space)
out vec2 te_texcoord;   // where an image displacement was looked up (tests capture it)
out vec2 te_param;      // the patch parameters (a tree part's (u, v); tests capture them)

uniform mat4 model;
uniform mat4 view_projection;
uniform int curved_patches;  // 1: point-normal triangles (tree parts), 0: flat (meshes, as the dicer)

// Curved patches for surfaces the path tracer evaluates exactly (a tree part's generalized
// cylinder): the cubic point-normal triangle of Vlachos et al. 2001 through the corners with
// their normals, which follows a cylinder's arc where flat patches would cut its chords.
// Each edge's curve depends on that edge's two corners only, so neighbours still agree.
vec3 pn_position(vec3 w) {
  const vec3 p1 = tc_position[0], p2 = tc_position[1], p3 = tc_position[2];
  const vec3 n1 = normalize(tc_normal[0]), n2 = normalize(tc_normal[1]), n3 = normalize(tc_normal[2]);
  const vec3 b210 = (2.0 * p1 + p2 - dot(p2 - p1, n1) * n1) / 3.0, b120 = (2.0 * p2 + p1 - dot(p1 - p2, n2) * n2) / 3.0;
  const vec3 b021 = (2.0 * p2 + p3 - dot(p3 - p2, n2) * n2) / 3.0, b012 = (2.0 * p3 + p2 - dot(p2 - p3, n3) * n3) / 3.0;
  const vec3 b102 = (2.0 * p3 + p1 - dot(p1 - p3, n3) * n3) / 3.0, b201 = (2.0 * p1 + p3 - dot(p3 - p1, n1) * n1) / 3.0;
  const vec3 e = (b210 + b120 + b021 + b012 + b102 + b201) / 6.0, v = (p1 + p2 + p3) / 3.0;
  const vec3 b111 = e + 0.5 * (e - v);
  const float a = w.x, b = w.y, c = w.z;
  return p1 * a * a * a + p2 * b * b * b + p3 * c * c * c + 3.0 * (b210 * a * a * b + b120 * a * b * b + b201 * a * a * c +
                                                                   b021 * b * b * c + b102 * a * c * c + b012 * b * c * c) +
         6.0 * b111 * a * b * c;
}

void main() {
  const vec3 w = gl_TessCoord;
  const vec3 p = curved_patches != 0 ? pn_position(w) : w.x * tc_position[0] + w.y * tc_position[1] + w.z * tc_position[2];
  const vec3 nn = w.x * tc_normal[0] + w.y * tc_normal[1] + w.z * tc_normal[2];
  const vec3 n = dot(nn, nn) > 0.0 ? normalize(nn) : vec3(0, 1, 0);
  const vec2 uv = w.x * tc_param[0] + w.y * tc_param[1] + w.z * tc_param[2];
  const vec2 texcoord = w.x * tc_texcoord[0] + w.y * tc_texcoord[1] + w.z * tc_texcoord[2];
  float offset = 0.0;
  te_attributes = vec4(0.0);
  if (BARK_KIND == 1) {
    const CrackSample s = crack_at(p, n);
    offset = -s.depth;
    te_attributes = vec4(s.relative, s.mask, s.chain, 0.0);
  } else if (BARK_KIND == 2) {
    const FieldSample f = field_at(uv);
    offset = -f.depth;
    te_attributes = vec4(uv, 0.0, 0.0);
  }
  if (IMAGE_DISPLACEMENT != 0) offset += image_displacement_at(texcoord);
  te_texcoord = texcoord;
  te_param = uv;
  te_base = p;
  const vec3 displaced = p + offset * n;
  te_world = (model * vec4(displaced, 1.0)).xyz;
  te_flat = (model * vec4(p, 1.0)).xyz;
  te_normal = transpose(inverse(mat3(model))) * n;
  gl_Position = view_projection * vec4(te_world, 1.0);
}
