// The pictures of the compare report, as PNG bytes: a height field in grey (1st–99th
// percentile stretched to black–white), the same with its fissure mask tinted over it, and
// an albedo through the sRGB display transform. Larger than `max_side` pixels, they are
// box-filtered down by a whole factor.
#pragma once

#include <cstdint>
#include <vector>

#include "compare/height_field.h"

namespace phellem {

inline constexpr int kReportImageSide = 1024;

std::vector<unsigned char> height_png(const HeightField& field, int max_side = kReportImageSide);
std::vector<unsigned char> mask_overlay_png(const HeightField& field, const std::vector<uint8_t>& mask,
                                            int max_side = kReportImageSide);
std::vector<unsigned char> albedo_png(const AlbedoField& albedo, int max_side = kReportImageSide);

}  // namespace phellem
