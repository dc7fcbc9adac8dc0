// The window's status line (frame time, triangles, edge length) drawn over the top-left corner
// with a built-in 5×7 pixel font, each glyph a 35-bit mask split over two words, scaled by
// `overlay_scale`. Characters are indices into the glyph table below.
layout(location = 0) out vec4 out_color;
layout(location = 1) out vec4 out_aov;

uniform int overlay_text[64];
uniform int overlay_length;
uniform int overlay_scale;
uniform int overlay_height;  // framebuffer height (GL rows run bottom-up)

// Glyphs: 0-9, then ' ', '.', ',', 'm', 's', 't', 'r', 'i', 'a', 'n', 'g', 'l', 'e', 'd', 'p',
// 'x', 'k', 'M', 'f', '|', '-'. Rows top to bottom, 5 bits a row, bit 4 the left column.
const uint kGlyphs[31 * 7] = uint[31 * 7](
  14u,17u,19u,21u,25u,17u,14u,  4u,12u,4u,4u,4u,4u,14u,  14u,17u,1u,2u,4u,8u,31u,  31u,2u,4u,2u,1u,17u,14u,
  2u,6u,10u,18u,31u,2u,2u,  31u,16u,30u,1u,1u,17u,14u,  6u,8u,16u,30u,17u,17u,14u,  31u,1u,2u,4u,8u,8u,8u,
  14u,17u,17u,14u,17u,17u,14u,  14u,17u,17u,15u,1u,2u,12u,
  0u,0u,0u,0u,0u,0u,0u,  0u,0u,0u,0u,0u,12u,12u,  0u,0u,0u,0u,12u,4u,8u,
  0u,0u,26u,21u,21u,17u,17u,  0u,0u,14u,16u,14u,1u,30u,  8u,8u,28u,8u,8u,9u,6u,  0u,0u,22u,25u,16u,16u,16u,
  4u,0u,12u,4u,4u,4u,14u,  0u,0u,14u,1u,15u,17u,15u,  0u,0u,22u,25u,17u,17u,17u,  0u,0u,15u,17u,15u,1u,14u,
  12u,4u,4u,4u,4u,4u,14u,  0u,0u,14u,17u,31u,16u,14u,  1u,1u,13u,19u,17u,17u,15u,  0u,0u,30u,17u,30u,16u,16u,
  0u,0u,17u,10u,4u,10u,17u,  16u,16u,18u,20u,24u,20u,18u,  17u,27u,21u,21u,17u,17u,17u,  6u,9u,8u,28u,8u,8u,8u,
  4u,4u,4u,4u,4u,4u,4u,  0u,0u,0u,31u,0u,0u,0u);

void main() {
  const ivec2 px = ivec2(gl_FragCoord.xy);
  const int x = px.x / overlay_scale - 4, y = (overlay_height - 1 - px.y) / overlay_scale - 4;
  const int cell = x / 6, col = x % 6, row = y;
  // A dark box one glyph-pixel wider than the text keeps it readable on any bark.
  if (x < -1 || y < -1 || y > 7 || x > overlay_length * 6) discard;
  bool on = false;
  if (x >= 0 && y >= 0 && row < 7 && cell < overlay_length && col < 5) {
    const int g = overlay_text[cell];
    on = ((kGlyphs[g * 7 + row] >> uint(4 - col)) & 1u) != 0u;
  }
  out_color = on ? vec4(1.0, 1.0, 0.85, 1.0) : vec4(0.05, 0.05, 0.05, 1.0);
  out_aov = vec4(0.0, 0.0, 1.0 / 0.0, 0.0);
}
