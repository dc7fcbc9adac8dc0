// A height field at one physical scale: what `compare` measures and `fit` simulates.
// Rows run top to bottom (row 0 is the top of the image, the top of the trunk); high = high.
#pragma once

#include <cstddef>
#include <vector>

namespace phellem {

struct HeightField {
  int width = 0, height = 0;
  double px_per_cm = 0;  // the same along both axes
  std::vector<float> z;  // height × width, row-major
  float at(int x, int y) const { return z[size_t(y) * size_t(width) + size_t(x)]; }
};

// Linear Rec.709 RGB at the same pixels as a HeightField (optional input of `compare`).
struct AlbedoField {
  int width = 0, height = 0;
  std::vector<float> rgb;  // height × width × 3, row-major
};

}  // namespace phellem
