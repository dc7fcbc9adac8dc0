// compare/connected_components: 8-connectivity, a known count, raster-order numbering, and
// agreement with a flood fill on a random mask.
#include <gtest/gtest.h>

#include <random>
#include <vector>

#include "compare/connected_components.h"

namespace phellem {
namespace {

std::vector<uint8_t> parse(const std::vector<std::string>& rows) {
  std::vector<uint8_t> m;
  for (const auto& r : rows)
    for (char c : r) m.push_back(c == '#');
  return m;
}

TEST(ConnectedComponents, CountsEightConnectedPiecesInRasterOrder) {
  // A diagonal chain (one piece through corners), a U whose arms meet only at the bottom (the
  // provisional labels must be merged), and an isolated pixel (the 3rd, last in raster order).
  const std::vector<std::string> rows = {
      "#.........",  //
      ".#..#..#..",  //
      "..#.#..#..",  //
      "....####..",  //
      ".........#",
  };
  const Components c = label_components(parse(rows), 10, 5);
  EXPECT_EQ(c.count, 3);
  EXPECT_EQ(c.label[0], 1);           // the chain starts first
  EXPECT_EQ(c.label[2 * 10 + 2], 1);  // through corners
  EXPECT_EQ(c.label[1 * 10 + 4], 2);  // the U: both arms, one label
  EXPECT_EQ(c.label[1 * 10 + 7], 2);
  EXPECT_EQ(c.label[4 * 10 + 9], 3);  // isolated: (8,3) is background
  EXPECT_EQ(c.label[0 * 10 + 1], 0);
}

TEST(ConnectedComponents, SeparateBlocksAreSeparate) {
  const int w = 40, h = 30;
  std::vector<uint8_t> m(size_t(w) * h, 0);
  for (int by = 0; by < 3; ++by)
    for (int bx = 0; bx < 4; ++bx)
      for (int y = 2 + 10 * by; y < 8 + 10 * by; ++y)
        for (int x = 2 + 10 * bx; x < 8 + 10 * bx; ++x) m[size_t(y) * w + size_t(x)] = 1;
  EXPECT_EQ(label_components(m, w, h).count, 12);
}

TEST(ConnectedComponents, AgreesWithAFloodFillOnARandomMask) {
  const int w = 50, h = 40;
  std::mt19937 rng(11);
  std::vector<uint8_t> m(size_t(w) * h);
  for (auto& v : m) v = (rng() % 100) < 35;
  const Components c = label_components(m, w, h);
  std::vector<int> seen(m.size(), 0);
  int count = 0;
  for (size_t s = 0; s < m.size(); ++s) {
    if (!m[s] || seen[s]) continue;
    ++count;
    std::vector<size_t> stack{s};
    seen[s] = count;
    while (!stack.empty()) {
      const size_t p = stack.back();
      stack.pop_back();
      EXPECT_EQ(c.label[p], c.label[s]);  // one flood-fill region, one label
      const int x = int(p % w), y = int(p / w);
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
          const int xx = x + dx, yy = y + dy;
          if (xx < 0 || yy < 0 || xx >= w || yy >= h) continue;
          const size_t q = size_t(yy) * w + size_t(xx);
          if (m[q] && !seen[q]) seen[q] = count, stack.push_back(q);
        }
    }
  }
  EXPECT_EQ(c.count, count);
}

}  // namespace
}  // namespace phellem
