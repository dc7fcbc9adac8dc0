#include "compare/fissure_spacing.h"

#include <cstddef>

namespace phellem {

std::vector<double> run_spacings_px(const std::vector<uint8_t>& mask, int width, int height, bool along_rows) {
  const int lines = along_rows ? height : width, n = along_rows ? width : height;
  auto at = [&](int line, int k) {
    return mask[along_rows ? size_t(line) * size_t(width) + size_t(k) : size_t(k) * size_t(width) + size_t(line)];
  };
  std::vector<double> gaps;
  for (int line = 0; line < lines; ++line) {
    bool have_previous = false;
    double previous = 0;
    for (int k = 0; k < n;) {
      if (!at(line, k)) {
        ++k;
        continue;
      }
      const int start = k;
      while (k < n && at(line, k)) ++k;  // run [start, k)
      if (start == 0 || k == n) continue;  // a run cut by the border has no known centre
      const double centre = 0.5 * (start + k - 1);
      if (have_previous) gaps.push_back(centre - previous);
      previous = centre;
      have_previous = true;
    }
  }
  return gaps;
}

}  // namespace phellem
