// Reading what `compare` and `fit` measure: a height map image (8/16-bit PNG, JPEG, TIFF,
// EXR; white = high), the `depth` channel of a FractureField EXR from `phellem simulate`, the
// `displacement.D` layer of a render EXR, or a `patch.exr` written by `phellem fit`.
#pragma once

#include <string>
#include <vector>

namespace phellem {

// Header attributes (float) that state a height image's scale: a patch.exr's pixels per
// centimetre (written by `phellem fit`), and a FractureField EXR's trunk length and
// circumference in metres (written by `phellem simulate`).
inline constexpr const char* kPxPerCmAttribute = "phellem:px_per_cm";
inline constexpr const char* kFieldLengthAttribute = "phellem:length_m";
inline constexpr const char* kFieldCircumferenceAttribute = "phellem:circumference_m";
// The channels that make an EXR a FractureField (height = −depth), a render (the displacement
// AOV, every pixel on an object) or a patch (Y, with kPxPerCmAttribute).
inline constexpr const char* kFieldDepthChannel = "depth";
inline constexpr const char* kRenderDisplacementChannel = "displacement.D";
inline constexpr const char* kRenderObjectIdChannel = "object_id.id";
inline constexpr const char* kPatchHeightChannel = "Y";

struct HeightImage {
  enum class Kind { plain, fracture_field, render, patch };
  Kind kind = Kind::plain;
  int width = 0, height = 0;
  std::vector<float> z;  // height × width, row 0 at the top, high = high
  // The scale the file itself states (0 when it states none: plain images and renders).
  // The two differ for a FractureField (circumference across, length along the trunk).
  double px_per_cm_x = 0, px_per_cm_y = 0;
};

// Plain images give the raw code values of channel 0 (the mean of the first three for colour)
// divided by the largest code (255, 65535), never linearized: gamma is not an affine change
// of the heights; float images give their values as they are.
// Throws UserError (file = path) for a missing or unreadable file, a size over the image
// limits (io/image_limits.h, checked from the header before any pixel is decoded), a
// non-finite height, a FractureField or patch whose scale attributes are missing or not
// positive, or a render EXR without the displacement layer or whose pixels are not all on an
// object.
HeightImage read_height_image(const std::string& path);

// Linear Rec.709 RGB (integer images through OpenColorIO's sRGB texture transform; float
// images such as EXR as they are), row 0 at the top; grey gives R = G = B. `rgb` is
// #height×#width×3. Throws UserError as read_height_image does.
struct RgbImage {
  int width = 0, height = 0;
  std::vector<float> rgb;
};
RgbImage read_albedo_image(const std::string& path);

}  // namespace phellem
