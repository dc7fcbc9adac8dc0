// compare/distance_transform (Felzenszwalb & Huttenlocher 2012): exact against brute force.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include "compare/distance_transform.h"

namespace phellem {
namespace {

TEST(DistanceTransform, EqualsBruteForceOnARandomMask) {
  const int w = 61, h = 47;
  std::mt19937 rng(7);
  std::vector<uint8_t> m(size_t(w) * h);
  for (auto& v : m) v = (rng() % 100) < 93;  // sparse background: long distances
  const std::vector<double> d = euclidean_distance_transform(m, w, h);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      double best = std::numeric_limits<double>::infinity();
      if (!m[size_t(y) * w + size_t(x)]) best = 0;
      for (int yy = 0; yy < h && best > 0; ++yy)
        for (int xx = 0; xx < w; ++xx)
          if (!m[size_t(yy) * w + size_t(xx)]) best = std::min(best, std::hypot(double(x - xx), double(y - yy)));
      ASSERT_NEAR(d[size_t(y) * w + size_t(x)], best, 1e-12) << x << "," << y;
    }
}

TEST(DistanceTransform, WithoutBackgroundEveryDistanceIsInfinite) {
  const std::vector<double> d = euclidean_distance_transform(std::vector<uint8_t>(12, 1), 4, 3);
  for (double v : d) EXPECT_EQ(v, std::numeric_limits<double>::infinity());
}

}  // namespace
}  // namespace phellem
