// A triangle covering the screen; the fragment stage looks the environment up per pixel.
out vec2 bg_ndc;

void main() {
  const vec2 corner = vec2(float((gl_VertexID << 1) & 2), float(gl_VertexID & 2));  // (0,0) (2,0) (0,2)
  bg_ndc = corner * 2.0 - 1.0;
  gl_Position = vec4(bg_ndc, 1.0, 1.0);
}
