// Passes the base mesh's patch corners (object space) to the tessellation stages.
layout(location = 0) in vec3 in_position;
layout(location = 1) in vec3 in_normal;
layout(location = 2) in vec2 in_param;
layout(location = 3) in float in_crack_near;  // 1 where a crack can reach an edge of this vertex
layout(location = 4) in vec2 in_texcoord;     // where an image displacement is looked up (0 without one)

out vec3 vs_position;
out vec3 vs_normal;
out vec2 vs_param;
out float vs_crack_near;
out vec2 vs_texcoord;

void main() {
  vs_position = in_position;
  vs_normal = in_normal;
  vs_param = in_param;
  vs_crack_near = in_crack_near;
  vs_texcoord = in_texcoord;
}
