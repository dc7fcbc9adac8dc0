// compare/maximal_rectangle: the largest rectangle of set pixels, against every rectangle
// tried by brute force on random masks, and its tie-break.
#include <gtest/gtest.h>

#include <random>

#include "compare/maximal_rectangle.h"

namespace phellem {
namespace {

// Every rectangle, the largest kept with the same tie-break (top-most, then left-most).
PixelRect brute_force(const std::vector<uint8_t>& m, int w, int h) {
  PixelRect best;
  for (int y0 = 0; y0 < h; ++y0)
    for (int x0 = 0; x0 < w; ++x0)
      for (int y1 = y0; y1 < h; ++y1)
        for (int x1 = x0; x1 < w; ++x1) {
          bool all = true;
          for (int y = y0; y <= y1 && all; ++y)
            for (int x = x0; x <= x1 && all; ++x) all = m[size_t(y) * size_t(w) + size_t(x)] != 0;
          if (!all) break;  // wider rectangles from (x0, y0) to y1 contain this hole too
          const PixelRect r{x0, y0, x1 - x0 + 1, y1 - y0 + 1};
          if (r.area() > best.area() || (r.area() == best.area() && (y0 < best.y || (y0 == best.y && x0 < best.x)))) best = r;
        }
  return best;
}

TEST(MaximalRectangle, MatchesBruteForceOnRandomMasks) {
  std::mt19937 rng(7);
  for (int trial = 0; trial < 300; ++trial) {
    const int w = 1 + int(rng() % 13), h = 1 + int(rng() % 11);
    const double fill = 0.5 + 0.45 * double(rng() % 100) / 100.0;
    std::vector<uint8_t> m(size_t(w) * size_t(h));
    for (auto& v : m) v = std::uniform_real_distribution<double>(0, 1)(rng) < fill;
    const PixelRect got = maximal_rectangle(m, w, h), want = brute_force(m, w, h);
    ASSERT_EQ(got, want) << "trial " << trial << " " << w << "×" << h << ": got " << got.x << "," << got.y << " " << got.width
                         << "×" << got.height << ", want " << want.x << "," << want.y << " " << want.width << "×" << want.height;
  }
}

TEST(MaximalRectangle, EmptyFullAndTies) {
  EXPECT_EQ(maximal_rectangle(std::vector<uint8_t>(12, 0), 4, 3).area(), 0);
  EXPECT_EQ(maximal_rectangle(std::vector<uint8_t>(12, 1), 4, 3), (PixelRect{0, 0, 4, 3}));
  // Two 2×2 blocks of equal area: the top-most wins, then the left-most.
  const std::vector<uint8_t> m = {0, 0, 0, 1, 1,  //
                                  1, 1, 0, 1, 1,  //
                                  1, 1, 0, 0, 0};
  EXPECT_EQ(maximal_rectangle(m, 5, 3), (PixelRect{3, 0, 2, 2}));
  const std::vector<uint8_t> side = {1, 1, 0, 1, 1,  //
                                     1, 1, 0, 1, 1};
  EXPECT_EQ(maximal_rectangle(side, 5, 2), (PixelRect{0, 0, 2, 2}));
  // A long thin run beats a squarer smaller one: the area decides.
  const std::vector<uint8_t> thin = {1, 1, 1, 1, 1, 1, 1,  //
                                     1, 1, 0, 0, 0, 0, 0,  //
                                     1, 1, 0, 0, 0, 0, 0};
  EXPECT_EQ(maximal_rectangle(thin, 7, 3), (PixelRect{0, 0, 7, 1}));
}

}  // namespace
}  // namespace phellem
