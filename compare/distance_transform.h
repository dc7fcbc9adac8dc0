// Exact Euclidean distance transform (issue-22 plan §3.5): Felzenszwalb & Huttenlocher 2012,
// "Distance Transforms of Sampled Functions", Theory of Computing 8.
#pragma once

#include <cstdint>
#include <vector>

namespace phellem {

// For each foreground pixel of `mask` (height × width, nonzero = foreground), the Euclidean
// distance in pixels to the nearest background pixel of the raster; 0 on the background.
// Pixels outside the raster do not count as background (scipy's distance_transform_edt).
// Without any background pixel every distance is +inf.
std::vector<double> euclidean_distance_transform(const std::vector<uint8_t>& mask, int width, int height);

}  // namespace phellem
