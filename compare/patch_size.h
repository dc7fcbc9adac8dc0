// The size of a simulated patch: the photo's pixels at the photo's scale.
#pragma once

namespace phellem {

struct PatchSize {
  int width = 0, height = 0;  // pixels
  double px_per_cm = 0;
  double width_m() const { return width / (100.0 * px_per_cm); }
  double height_m() const { return height / (100.0 * px_per_cm); }
};

}  // namespace phellem
