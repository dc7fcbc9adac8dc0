#include "renderer/film_memory.h"

#include "io/film.h"

namespace phellem {

namespace {

// Measured (max RSS, /usr/bin/time -v) on a one-sphere scene, 1 spp, depth 1, 2 threads, at
// 1000², 2000² and 4000² pixels (64² as the baseline, 141 MB):
//   phellem render film.json --res 4000x4000 -o f.exr --quiet       2293 MB (2000²: 690 MB)
//   phellem render film.json --res 4000x4000 --png f.png --quiet    2132 MB (2000²: 632 MB)
//   phellem render film.json --res 4000x4000 -o f.exr --png f.png   2293 MB (the two writes follow each other)
// i.e. 137-140 bytes a pixel with an EXR and 125-127 with a PNG alone: the film's 68
// (Film::kChannels floats) plus 72 for the EXR's interleaved float copy (68) and OpenEXR's
// buffers, or 59 for the PNG (12 for the RGB copy, 3 for the 8-bit pixels, the rest the
// display transform's working copy: OCIO processes the image as one long row).
// The displacement layer (issue 22) added a float to the film and to the EXR's copy: 72 + 76,
// measured the same way: 2000² with the EXR 722 MB (64²: 141 MB), 148.7 bytes a pixel.
constexpr double kExrBytesPerPixel = 76;
constexpr double kPngBytesPerPixel = 59;

}  // namespace

FilmMemory film_memory(int width, int height, bool exr, bool png) {
  const double pixels = double(width) * double(height);
  FilmMemory m;
  m.layers = pixels * double(Film::kChannels * sizeof(float));
  if (exr) m.exr = pixels * kExrBytesPerPixel;
  if (png) m.png = pixels * kPngBytesPerPixel;
  return m;
}

}  // namespace phellem
