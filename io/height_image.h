// Reading what `compare` and `fit` measure: a height map image (8/16-bit PNG, JPEG, TIFF,
// EXR; white = high), the `depth` channel of a FractureField EXR from `phellem simulate`, the
// `displacement.D` layer of a render EXR, or a `patch.exr` written by `phellem fit`.
#pragma once

#include <string>
#include <vector>

namespace phellem {

struct HeightImage {
  enum class Kind { plain, fracture_field, render, patch };
  Kind kind = Kind::plain;
  int width = 0, height = 0;
  std::vector<float> z;  // height × width, row 0 at the top, high = high
  // The scale the file itself states (0 when it states none: plain images and renders).
  // The two differ for a FractureField (circumference across, length along the trunk).
  double px_per_cm_x = 0, px_per_cm_y = 0;
};

// Throws UserError (file = path) for a missing or unreadable file, a size over the image
// limits, a non-finite height, or a render EXR whose pixels are not all on an object.
HeightImage read_height_image(const std::string& path);

// Linear Rec.709 RGB (8-bit and sRGB-tagged images through OpenColorIO's sRGB texture
// transform), row 0 at the top.
struct RgbImage {
  int width = 0, height = 0;
  std::vector<float> rgb;
};
RgbImage read_albedo_image(const std::string& path);

}  // namespace phellem
