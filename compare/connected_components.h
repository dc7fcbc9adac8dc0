// 8-connected component labelling of a binary raster (issue-22 plan §3.1 and §3.6).
#pragma once

#include <cstdint>
#include <vector>

namespace phellem {

struct Components {
  std::vector<int32_t> label;  // height × width: 0 = background, 1..count in raster order of first pixel
  int count = 0;
};

// `mask` is height × width, row-major, nonzero = foreground. Two pixels touching by an edge or
// a corner belong to one component.
Components label_components(const std::vector<uint8_t>& mask, int width, int height);

}  // namespace phellem
