// compare/skeleton (Zhang & Suen 1984): a thick bar thins to a connected 1-px line along its
// middle, of nearly the bar's length.
#include <gtest/gtest.h>

#include <vector>

#include "compare/connected_components.h"
#include "compare/skeleton.h"

namespace phellem {
namespace {

TEST(ZhangSuen, ThinsAThickBarToAOnePixelLineOfTheRightLength) {
  const int w = 80, h = 30, x0 = 10, x1 = 70, y0 = 12, y1 = 19;  // a 60×7 bar
  std::vector<uint8_t> m(size_t(w) * h, 0);
  for (int y = y0; y < y1; ++y)
    for (int x = x0; x < x1; ++x) m[size_t(y) * w + size_t(x)] = 1;
  const std::vector<uint8_t> sk = zhang_suen_skeleton(m, w, h);
  int count = 0, xmin = w, xmax = -1;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      if (sk[size_t(y) * w + size_t(x)]) {
        ++count;
        EXPECT_EQ(y, 15) << "off the middle row at x " << x;  // the middle of rows 12..18
        xmin = std::min(xmin, x), xmax = std::max(xmax, x);
      }
  EXPECT_EQ(count, xmax - xmin + 1);            // one pixel per column: 1 px thick, no gaps
  EXPECT_GE(count, 60 - 7);                     // the ends shrink by at most the half-width each
  EXPECT_LE(count, 60);
  EXPECT_EQ(label_components(sk, w, h).count, 1);
  // Thinning is idempotent on a skeleton, and never adds pixels outside the shape.
  EXPECT_EQ(zhang_suen_skeleton(sk, w, h), sk);
  for (size_t i = 0; i < m.size(); ++i) EXPECT_LE(sk[i], m[i]);
}

TEST(ZhangSuen, KeepsAOnePixelLineAndRemovesNothingFromIt) {
  const int w = 20, h = 20;
  std::vector<uint8_t> m(size_t(w) * h, 0);
  for (int i = 2; i < 18; ++i) m[size_t(i) * w + size_t(i)] = 1;  // a diagonal
  EXPECT_EQ(zhang_suen_skeleton(m, w, h), m);
}

}  // namespace
}  // namespace phellem
