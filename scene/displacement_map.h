// A height map image that displaces a surface (`"displacement": {"type": "image", ...}`), as
// Cycles' displacement node or pbrt-v4's displacement texture do: the offset along the normal
// is scale × (value − midlevel) metres, the value looked up bilinearly at the surface's
// texture coordinates × uv_repeat. The map is read once, by the scene parser.
#pragma once

#include <string>
#include <vector>

#include "util/math.h"

namespace phellem {

struct DisplacementMap {
  int width = 0, height = 0;
  std::vector<float> value;  // height × width, row 0 at the top (v = 1), as the image stores it
};

// Reads a height map through OpenImageIO (8/16-bit PNG, JPEG, TIFF, float EXR; a patch.exr's
// `Y`; a FractureField's heights), its size bounded from the header before any pixel is
// decoded. Throws UserError (file = path) for a missing or unreadable file, a non-finite
// value, or a map smaller than 2×2 pixels (nothing to interpolate).
DisplacementMap read_displacement_map(const std::string& path);

// The map's value at texture coordinates `uv` (v up: v = 0 is the bottom row): bilinear
// between texel centres at ((i + ½) / width, 1 − (j + ½) / height). `clamp`: coordinates
// outside [0, 1] take the edge's value and the edges are not blended with the opposite side;
// otherwise the map repeats.
float sample_displacement_map(const DisplacementMap& map, const Vec2f& uv, bool clamp);

}  // namespace phellem
