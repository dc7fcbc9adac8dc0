// Fissure spacing along the image axes (issue-22 plan §3.4).
#pragma once

#include <cstdint>
#include <vector>

namespace phellem {

// Along every row (`along_rows`) or column of `mask` (height × width, 1 = fissure): the runs of
// fissure pixels that touch neither end of the line, their centres, and the gaps between
// consecutive centres, in pixels. For stripes at angle θ to the rows, the row gaps are P/|sin θ|:
// the spacing is measured along the image axis, by definition.
std::vector<double> run_spacings_px(const std::vector<uint8_t>& mask, int width, int height, bool along_rows);

}  // namespace phellem
