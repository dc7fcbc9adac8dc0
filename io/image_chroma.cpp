#include "io/image_chroma.h"

#include <algorithm>
#include <vector>

namespace phellem {

double colour_chroma(const float* rgb, int width, int height, int channels) {
  const int b = width >= 8 && height >= 8 ? 8 : 1;
  const int bw = width / b, bh = height / b;
  if (bw == 0 || bh == 0) return 0;
  std::vector<double> sums(size_t(bw) * 3);
  std::vector<float> chroma;
  chroma.reserve(size_t(bw) * size_t(bh));
  for (int by = 0; by < bh; ++by) {
    std::fill(sums.begin(), sums.end(), 0.0);
    for (int y = by * b; y < (by + 1) * b; ++y) {
      const float* row = rgb + size_t(y) * size_t(width) * size_t(channels);
      for (int x = 0; x < bw * b; ++x)
        for (int c = 0; c < 3; ++c) sums[size_t(x / b) * 3 + size_t(c)] += row[size_t(x) * size_t(channels) + size_t(c)];
    }
    for (int bx = 0; bx < bw; ++bx) {
      const double* s = &sums[size_t(bx) * 3];
      chroma.push_back(float((std::max({s[0], s[1], s[2]}) - std::min({s[0], s[1], s[2]})) / double(b * b)));
    }
  }
  const auto mid = chroma.begin() + std::ptrdiff_t(chroma.size() / 2);
  std::nth_element(chroma.begin(), mid, chroma.end());
  return double(*mid);
}

}  // namespace phellem
