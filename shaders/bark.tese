// Displacement of the tessellated surface by the bark (bark/dressing/bark_surface.h): the
// stress model's crack V-profiles or the strip model's FractureField depth, along the
// interpolated normal, exactly as the path tracer's dicer displaces its vertices.
layout(triangles, equal_spacing, ccw) in;

in vec3 tc_position[];
in vec3 tc_normal[];
in vec2 tc_param[];

out vec3 te_base;       // undisplaced point (object space)
out vec3 te_world;      // displaced point (world space)
out vec4 te_attributes; // the BarkSurface attributes (depth, mask, chain, 0)
out vec3 te_flat;       // undisplaced point (world space): its derivatives give the flat facet
out vec3 te_normal;     // interpolated base normal (world space)

uniform mat4 model;
uniform mat4 view_projection;

void main() {
  const vec3 w = gl_TessCoord;
  const vec3 p = w.x * tc_position[0] + w.y * tc_position[1] + w.z * tc_position[2];
  const vec3 nn = w.x * tc_normal[0] + w.y * tc_normal[1] + w.z * tc_normal[2];
  const vec3 n = dot(nn, nn) > 0.0 ? normalize(nn) : vec3(0, 1, 0);
  const vec2 uv = w.x * tc_param[0] + w.y * tc_param[1] + w.z * tc_param[2];
  float offset = 0.0;
  te_attributes = vec4(0.0);
  if (bark_kind == 1) {
    const CrackSample s = crack_at(p, n);
    offset = -s.depth;
    te_attributes = vec4(s.relative, s.mask, s.chain, 0.0);
  } else if (bark_kind == 2) {
    const FieldSample f = field_at(uv);
    offset = -f.depth;
    te_attributes = vec4(uv, 0.0, 0.0);
  }
  te_base = p;
  const vec3 displaced = p + offset * n;
  te_world = (model * vec4(displaced, 1.0)).xyz;
  te_flat = (model * vec4(p, 1.0)).xyz;
  te_normal = transpose(inverse(mat3(model))) * n;
  gl_Position = view_projection * vec4(te_world, 1.0);
}
