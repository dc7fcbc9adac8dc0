// Reading what `compare` and `fit` measure: a height map image (8/16-bit PNG, JPEG, TIFF,
// EXR; white = high), the `depth` channel of a FractureField EXR from `phellem simulate`, the
// `displacement.D` layer of a render EXR (with the layers that say which pixels show bark),
// or a `patch.exr` written by `phellem fit`.
#pragma once

#include <Eigen/Core>
#include <optional>
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
// AOV and the layers of io/image_output.h) or a patch (Y, with kPxPerCmAttribute).
inline constexpr const char* kFieldDepthChannel = "depth";
inline constexpr const char* kRenderDisplacementChannel = "displacement.D";
inline constexpr const char* kRenderObjectIdChannel = "object_id.id";
inline constexpr const char* kRenderAlphaChannel = "beauty.A";
inline constexpr const char* kRenderNormalChannels[3] = {"normal.X", "normal.Y", "normal.Z"};
inline constexpr const char* kRenderPositionChannels[3] = {"position.X", "position.Y", "position.Z"};
inline constexpr const char* kRenderAlbedoChannels[3] = {"albedo.R", "albedo.G", "albedo.B"};
inline constexpr const char* kPatchHeightChannel = "Y";
// Where a render's camera stood (world space, metres), written by write_exr beside the
// standard OpenEXR `worldToCamera` matrix; a render without it is read through that matrix.
inline constexpr const char* kCameraPositionAttribute = "phellem:camera_position";
inline constexpr const char* kWorldToCameraAttribute = "worldToCamera";

// The layers of a render EXR that say which of its pixels show bark (compare/render_pixels.h):
// each #height×#width (×3 for vectors), row 0 at the top.
struct RenderLayers {
  std::vector<float> alpha;      // beauty.A: the share of the pixel's samples that hit something
  std::vector<float> object_id;  // object_id.id: 1-based object of the first sample, 0 = none
  std::vector<float> normal;     // normal.XYZ: world-space shading normal (×3)
  std::vector<float> position;   // position.XYZ: world position in metres (×3)
  std::vector<float> albedo;     // albedo.RGB: linear Rec.709 (×3); empty when the file has none
  std::optional<Eigen::Vector3d> camera;  // the camera position, when the header states it
};

struct HeightImage {
  enum class Kind { plain, fracture_field, render, patch };
  Kind kind = Kind::plain;
  int width = 0, height = 0;
  std::vector<float> z;  // height × width, row 0 at the top, high = high
  // The scale the file itself states (0 when it states none: plain images and renders).
  // The two differ for a FractureField (circumference across, length along the trunk).
  double px_per_cm_x = 0, px_per_cm_y = 0;
  // Plain images with three channels or more: how coloured they are (colour_chroma in
  // io/image_chroma.h); 0 for one-channel images. A colour photo is no height map.
  double chroma = 0;
  // Renders only: the layers that say which pixels show bark.
  std::optional<RenderLayers> render;
};

// Plain images give the raw code values of channel 0 (the mean of the first three for colour)
// divided by the largest code (255, 65535), never linearized: gamma is not an affine change
// of the heights; float images give their values as they are.
// Throws UserError (file = path) for a missing or unreadable file, a size over the image
// limits (io/image_limits.h, checked from the header before any pixel is decoded), a
// non-finite height, a FractureField or patch whose scale attributes are missing or not
// positive, or a render EXR without the displacement, beauty.A, object_id, normal or position
// layers. A render's background is read as it is: compare/render_pixels.h chooses the bark.
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
