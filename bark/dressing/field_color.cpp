#include "bark/dressing/field_color.h"

#include <algorithm>

namespace phellem::bark {

void dress_colors(FractureField& f, const FieldColors& c, double max_depth) {
  const size_t n = size_t(f.width) * f.height;
  for (size_t p = 0; p < n; ++p) {
    const Eigen::Vector3f skin = f.level[p] > 0 && f.opening[p] <= 0 ? c.hardened : c.epidermis;
    const Eigen::Vector3f base = skin + f.opening[p] * (c.fracture - skin);
    const float dark = 1.0f - c.depth_darkening * float(std::clamp(f.depth[p] / max_depth, 0.0, 1.0));
    for (int k = 0; k < 3; ++k) f.color[3 * p + size_t(k)] = base[k] * dark;
  }
}

}  // namespace phellem::bark
