// The micro-edge length the preview's tessellation aims at (pixels on screen), and its range.
#pragma once

namespace phellem::preview {

// Finer than half a pixel adds nothing the picture can show: one sample per pixel already
// sees the displacement at two or more points across it. The work does not stop there: the
// triangles grow as 1/P² until the level reaches its maximum (64) on every patch, and at
// --edge-px 0.01 a 32×24 snapshot of the default scene ran for minutes. The window's finer
// key stops here too.
inline constexpr float kMinEdgePx = 0.5f;
inline constexpr float kMaxEdgePx = 1000.0f;

}  // namespace phellem::preview
