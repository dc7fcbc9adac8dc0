// Crack-aware tessellation levels (Spicker 2014 ch. 4): each edge's level comes from that
// edge's two endpoints only — its length on screen, divided by a target length in pixels
// that is finer when a crack can reach it — so the two patches sharing an edge compute the
// same level and the surface stays watertight. The endpoints are ordered first, so the
// arithmetic is the same whichever patch evaluates it.
layout(vertices = 3) out;

in vec3 vs_position[];
in vec3 vs_normal[];
in vec2 vs_param[];
in float vs_crack_near[];
out vec3 tc_position[];
out vec3 tc_normal[];
out vec2 tc_param[];

uniform mat4 model_view_projection;
uniform vec2 viewport;             // pixels
uniform float target_near_px;      // micro-edge length near cracks (pixels)
uniform float target_far_px;       // elsewhere
uniform float max_level;           // GL_MAX_TESS_GEN_LEVEL, or the user's budget
uniform int asymmetric_levels;     // tests only: 1 makes levels depend on the patch (holes)

bool before(vec3 a, vec3 b) { return a.x < b.x || (a.x == b.x && (a.y < b.y || (a.y == b.y && a.z < b.z))); }

vec2 to_screen(vec3 p) {
  const vec4 c = model_view_projection * vec4(p, 1.0);
  return c.xy / max(c.w, 1e-6) * 0.5 * viewport;
}

float edge_level(int i, int j) {
  vec3 a = vs_position[i], b = vs_position[j];
  if (before(b, a)) {
    const vec3 t = a;
    a = b;
    b = t;
  }
  const bool near = vs_crack_near[i] > 0.5 && vs_crack_near[j] > 0.5;
  const float len = distance(to_screen(a), to_screen(b));
  float level = len / (near ? target_near_px : target_far_px);
  if (asymmetric_levels != 0) level += float(gl_PrimitiveID % 3) * 1.7;
  return clamp(level, 1.0, max_level);
}

void main() {
  tc_position[gl_InvocationID] = vs_position[gl_InvocationID];
  tc_normal[gl_InvocationID] = vs_normal[gl_InvocationID];
  tc_param[gl_InvocationID] = vs_param[gl_InvocationID];
  if (gl_InvocationID == 0) {
    // Outer level k belongs to the edge opposite corner k.
    gl_TessLevelOuter[0] = edge_level(1, 2);
    gl_TessLevelOuter[1] = edge_level(2, 0);
    gl_TessLevelOuter[2] = edge_level(0, 1);
    gl_TessLevelInner[0] = max(gl_TessLevelOuter[0], max(gl_TessLevelOuter[1], gl_TessLevelOuter[2]));
  }
}
