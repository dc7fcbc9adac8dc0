// Output drivers: multi-layer half-float OpenEXR (the scene-linear truth) and display PNG
// through the OpenColorIO config shipped in the repository. Both write atomically: a
// temporary file in the same folder, renamed over the target only when complete.
#pragma once

#include <Eigen/Core>
#include <optional>
#include <string>
#include <vector>

#include "io/film.h"

namespace phellem {

// Channel layout of the EXR (layer.channel): beauty.{R,G,B,A}, albedo.{R,G,B},
// normal.{X,Y,Z}, depth.Z, position.{X,Y,Z} (32-bit float), object_id.id (32-bit float),
// crack.{mask,depth}, displacement.D; the rest half.
std::vector<std::string> exr_channel_names();

// The camera a render was seen from, stated in its EXR header so that `compare` can tell which
// pixels face it: `phellem:camera_position` (world, metres) and the standard OpenEXR
// `worldToCamera` (Imath convention: row vectors, p_camera = p_world · M).
struct ExrCamera {
  Eigen::Vector3f position;
  Eigen::Matrix4f world_to_camera;  // column vectors (OpenGL's view matrix); transposed on write
};

void write_exr(const Film& film, const std::string& path, const std::optional<ExrCamera>& camera = std::nullopt);
// view: one of ocio_views(); display "sRGB".
void write_png(const Film& film, const std::string& path, const std::string& view);
std::vector<std::string> ocio_views();
// UserError (naming --view) unless `view` is one of ocio_views().
void require_view(const std::string& view);
std::string default_view();

// Applies the display view to linear RGB (n pixels, in place) — exposed for tests.
void apply_display_view(std::vector<float>& rgb, const std::string& view);

const char* ocio_config_text();

// Decodes sRGB-encoded texture values to scene-linear Rec.709 in place through the OCIO
// config ("sRGB - Texture" -> "lin_rec709"); `channels` 1–4, alpha (4th) untouched.
void srgb_texture_to_linear(float* pixels, long count, int channels);

}  // namespace phellem
