// An environment light's image, read once for every renderer (the path tracer's environment
// map and the preview's background and ambient term): linear RGB, non-finite and negative
// values 0, texels brighter than the light's `clamp` scaled down to it (hue kept).
#pragma once

#include <vector>

#include "scene/scene_desc.h"

namespace phellem {

// The size is bounded from the header before anything is decoded; every failure is a
// UserError at the light's `file` key.
std::vector<float> load_environment_image(const LightDesc& l, int* width, int* height);

}  // namespace phellem
