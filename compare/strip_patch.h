// A flat patch of strip-model bark as a height field (z = −depth), the size of a photo at its
// scale. The strips do not wrap around (tile_theta = false); a margin is simulated on every
// side and cropped, so the patch has no boundary effects.
#pragma once

#include <cstdint>

#include "bark/dressing/bark_relief.h"
#include "bark/strips/fracture_field.h"
#include "bark/strips/strip_params.h"
#include "compare/height_field.h"
#include "compare/patch_size.h"

namespace phellem {

struct StripPatchParams {
  bark::StripParams params;  // orientation, seed and tiling are set by strip_patch
  bark::DepthProfile depth;
  bark::ReliefLook relief;  // the dressing's ridge relief and rough walls (off: flat ridges)
};

inline constexpr double kStripPatchMarginM = 0.05;

// Throws bark::StripParamError for parameters the model refuses.
HeightField strip_patch(const StripPatchParams& p, const PatchSize& size, uint64_t seed);

// strip_patch in two steps, so that one simulation can be dressed with several reliefs (the
// fit's relief stage): the simulated, rasterized field with its margin and without relief,
// then the relief applied to a copy of it and the margin cropped. The relief's noise is seeded
// from the simulation seed (as a scene seeds it from the bark's).
bark::FractureField strip_patch_field(const StripPatchParams& p, const PatchSize& size, uint64_t seed);
HeightField strip_patch_heights(bark::FractureField field, const StripPatchParams& p, const PatchSize& size, uint64_t seed);

}  // namespace phellem
