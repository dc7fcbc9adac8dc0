// Bark colours from a photograph (issue 22): a photo's albedo and its height map (a scan's
// displacement) split into ridge pixels (the high part of the height map) and fissure pixels
// (the low part); their mean linear colours become the dressing's ridge and fissure samples,
// their brightness spread the samples' variation, and the colours of 1 cm patches the tints
// each plate and fracture picks (bark/dressing/field_color.h).
//   "photo": {"albedo": "bark.jpg", "height": "bark_disp.png", "px_per_cm": 10,
//             "ridge_above": 0.6, "fissure_below": 0.25, "tints": 1}
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

namespace phellem {

class JsonObject;

struct BarkPhoto {
  Eigen::Vector3f ridge{0, 0, 0}, fissure{0, 0, 0};  // mean scene-linear albedo
  float ridge_variation = 0, fissure_variation = 0;  // std / mean of the luminance
  std::vector<Eigen::Vector3f> ridge_tints, fissure_tints;  // patch colour / mean colour
};

// Reads both images once (integer images are sRGB-encoded: linearized through OpenColorIO's
// sRGB texture transform, io/image_output.h). Every failure is a UserError at the key's path.
BarkPhoto read_bark_photo(JsonObject o, const std::string& base_dir);

}  // namespace phellem
