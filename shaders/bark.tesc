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
in vec2 vs_texcoord[];
out vec3 tc_position[];
out vec3 tc_normal[];
out vec2 tc_param[];
out vec2 tc_texcoord[];

uniform mat4 model_view_projection;
uniform vec2 viewport;             // pixels
uniform float target_near_px;      // micro-edge length near cracks (pixels)
uniform float target_far_px;       // elsewhere
uniform float max_level;           // GL_MAX_TESS_GEN_LEVEL, or the user's budget
uniform int asymmetric_levels;     // tests only: 1 makes levels depend on the patch (holes)
uniform vec3 camera_position;      // world space
uniform mat4 inverse_model;
uniform int cull_patches;          // 0: tessellate every patch
uniform float displacement_reach;  // the most an image displacement moves a point (object space, m)

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

// A patch nobody can see: every corner, moved either way along its normal by as much as an
// image displacement can move it, beyond the same side of the view frustum (with a margin for
// the bark's displacement), or every corner's normal facing away from the eye (bark only
// carves inwards, so a back-facing patch stays hidden behind the front of the surface; an
// image's bumps could only peek over a silhouette by their height, at grazing angles).
bool culled() {
  if (cull_patches == 0) return false;
  vec4 c[6];
  for (int i = 0; i < 3; ++i) {
    const vec3 n = dot(vs_normal[i], vs_normal[i]) > 0.0 ? normalize(vs_normal[i]) : vec3(0.0);
    c[2 * i] = model_view_projection * vec4(vs_position[i] + displacement_reach * n, 1.0);
    c[2 * i + 1] = model_view_projection * vec4(vs_position[i] - displacement_reach * n, 1.0);
  }
  for (int axis = 0; axis < 3; ++axis) {
    bool below = true, above = true;
    for (int i = 0; i < 6; ++i) {
      const float m = 1.05 * c[i].w;
      below = below && c[i][axis] < -m;
      above = above && c[i][axis] > m;
    }
    if (below || above) return true;
  }
  bool away = true;
  for (int i = 0; i < 3; ++i) {
    const vec3 eye = (inverse_model * vec4(camera_position, 1.0)).xyz;
    away = away && dot(vs_normal[i], eye - vs_position[i]) < -0.05 * length(eye - vs_position[i]);
  }
  return away;
}

void main() {
  tc_position[gl_InvocationID] = vs_position[gl_InvocationID];
  tc_normal[gl_InvocationID] = vs_normal[gl_InvocationID];
  tc_param[gl_InvocationID] = vs_param[gl_InvocationID];
  tc_texcoord[gl_InvocationID] = vs_texcoord[gl_InvocationID];
  if (gl_InvocationID == 0) {
    if (culled()) {  // a level of 0 discards the patch
      gl_TessLevelOuter[0] = gl_TessLevelOuter[1] = gl_TessLevelOuter[2] = gl_TessLevelInner[0] = 0.0;
      return;
    }
    // Outer level k belongs to the edge opposite corner k.
    gl_TessLevelOuter[0] = edge_level(1, 2);
    gl_TessLevelOuter[1] = edge_level(2, 0);
    gl_TessLevelOuter[2] = edge_level(0, 1);
    gl_TessLevelInner[0] = max(gl_TessLevelOuter[0], max(gl_TessLevelOuter[1], gl_TessLevelOuter[2]));
  }
}
