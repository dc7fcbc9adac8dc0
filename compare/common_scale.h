// Bringing two height fields to one physical scale: the coarser of the two (never upsampled),
// resampled with an anti-aliasing filter.
#pragma once

#include "compare/height_field.h"

namespace phellem {

double common_scale(double px_per_cm_a, double px_per_cm_b);

// `field` resampled to `px_per_cm` along both axes; `px_per_cm_x`/`_y` are its own scales
// (they differ for a FractureField EXR). The returned scale is recomputed from the rounded size.
HeightField resample(const HeightField& field, double px_per_cm_x, double px_per_cm_y, double px_per_cm);
AlbedoField resample(const AlbedoField& albedo, int width, int height);

}  // namespace phellem
