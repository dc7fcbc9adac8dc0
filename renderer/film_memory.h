// Memory of a rendered frame: the film's per-pixel layers (beauty and every AOV, io/film.h)
// and the copies the outputs make of them (the EXR's interleaved layers, the PNG's display
// conversion), estimated before the render so a film too large is refused up front.
#pragma once

#include <cstddef>

namespace phellem {

struct FilmMemory {
  double layers = 0;  // Film: every per-pixel buffer (beauty RGBA and the AOV layers)
  double exr = 0;     // write_exr: the interleaved copy of all layers, and OpenEXR's buffers
  double png = 0;     // write_png: the RGB copy, its display transform and the 8-bit pixels
  // The outputs are written one after the other while the film is held.
  double peak() const { return layers + (exr > png ? exr : png); }
};

// A width × height film, and the copies of the outputs that are written (`exr`, `png`).
FilmMemory film_memory(int width, int height, bool exr, bool png);

}  // namespace phellem
