// Thinning of a binary raster to its 1-pixel skeleton (issue-22 plan §3.3): Zhang & Suen 1984,
// "A fast parallel algorithm for thinning digital patterns", CACM 27(3).
#pragma once

#include <cstdint>
#include <vector>

namespace phellem {

// `mask` is height × width, row-major, nonzero = foreground; pixels outside the raster are
// background. Returns 1 on the skeleton, 0 elsewhere.
std::vector<uint8_t> zhang_suen_skeleton(const std::vector<uint8_t>& mask, int width, int height);

}  // namespace phellem
