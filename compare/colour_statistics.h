// Albedo statistics in OKLab (issue-22 plan §3.8; reported, not scored).
#pragma once

#include <cstdint>
#include <vector>

#include <Eigen/Core>

#include "compare/fissure_statistics.h"
#include "compare/height_field.h"

namespace phellem {

// Linear Rec.709/sRGB → OKLab (Ottosson 2020, "A perceptual color space for image
// processing"): LMS = M1·rgb, L'M'S' = cube root, Lab = M2·L'M'S'.
Eigen::Vector3d linear_srgb_to_oklab(const Eigen::Vector3d& rgb);

// Mean and std of L, a, b over all pixels, and the contrast median L(ridge) − median L(mask).
// `mask` and `ridge` have the albedo's pixels.
ColourStats colour_statistics(const AlbedoField& albedo, const std::vector<uint8_t>& mask,
                              const std::vector<uint8_t>& ridge);

}  // namespace phellem
