// The environment behind the bark: the path tracer's latitude-longitude lookup
// (renderer/light.cpp EnvironmentMap::direction_to_uv, rotated about y), or a flat sky colour
// without a map. Writes "nothing hit" into the AOV target.
in vec2 bg_ndc;

layout(location = 0) out vec4 out_color;
layout(location = 1) out vec4 out_aov;

uniform mat4 inverse_view_projection;
uniform vec3 camera_position;
uniform sampler2D environment;
uniform int has_environment;
uniform float environment_intensity;
uniform float environment_rotation;  // radians
uniform vec3 sky_color;

const float kPi = 3.14159265358979;

void main() {
  const vec4 far_point = inverse_view_projection * vec4(bg_ndc, 1.0, 1.0);
  const vec3 d = normalize(far_point.xyz / far_point.w - camera_position);
  vec3 radiance = sky_color;
  if (has_environment != 0) {
    const float c = cos(environment_rotation), s = sin(environment_rotation);
    const vec3 l = vec3(c * d.x - s * d.z, d.y, s * d.x + c * d.z);  // EnvironmentMap::to_local
    float u = 0.5 + atan(l.x, -l.z) * (0.5 / kPi);
    u -= floor(u);
    const float v = acos(clamp(l.y, -1.0, 1.0)) / kPi;
    radiance = texture(environment, vec2(u, v)).rgb * environment_intensity;
  }
  const vec3 x = clamp(radiance, 0.0, 1.0);
  out_color = vec4(mix(12.92 * x, 1.055 * pow(x, vec3(1.0 / 2.4)) - 0.055, step(0.0031308, x)), 1.0);
  out_aov = vec4(0.0, 0.0, 1.0 / 0.0, 0.0);
}
