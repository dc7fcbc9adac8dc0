// Fracture fields rasterized from the strip model: tileable samples wrap without a seam.
#include <gtest/gtest.h>

#include "bark/strips/fracture_field.h"
#include "bark/strips/strip_model.h"
#include "tests/support/strip_helpers.h"

using namespace phellem::bark;

TEST(FractureFieldTest, TileableSampleWrapsWithoutSeam) {
  StripParams p = phellem::test::small_strip_params();
  p.tile_theta = p.tile_s = true;
  const FractureField f = rasterize(phellem::test::run_flat(p, 0.3, 0.3), 128, 128, DepthProfile{});
  auto col_diff = [&](int a, int b) {
    double d = 0;
    for (int y = 0; y < f.height; ++y) d += std::abs(f.opening[f.index(a, y)] - f.opening[f.index(b, y)]);
    return d / f.height;
  };
  auto row_diff = [&](int a, int b) {
    double d = 0;
    for (int x = 0; x < f.width; ++x) d += std::abs(f.opening[f.index(x, a)] - f.opening[f.index(x, b)]);
    return d / f.width;
  };
  double cols = 0, rows = 0;
  for (int x = 0; x + 1 < f.width; ++x) cols += col_diff(x, x + 1) / (f.width - 1);
  for (int y = 0; y + 1 < f.height; ++y) rows += row_diff(y, y + 1) / (f.height - 1);
  ASSERT_GT(cols, 0);
  // Across the seam the image changes no more than between any two neighbouring columns/rows.
  EXPECT_LT(col_diff(f.width - 1, 0), 3 * cols);
  EXPECT_LT(row_diff(f.height - 1, 0), 3 * rows);
}

// The power profile 1 − (1 − q)^k is V at k = 1 and U at k = 2, and keeps the ends fixed
// (0 at the lip, 1 at the axis) for every exponent.
TEST(FractureFieldTest, PowerProfileSpansVAndU) {
  DepthProfile v{DepthProfileShape::V}, u{DepthProfileShape::U}, p{DepthProfileShape::Power};
  for (double q = 0; q <= 1.0; q += 0.125) {
    p.exponent = 1;
    EXPECT_DOUBLE_EQ(p.evaluate(q), v.evaluate(q)) << q;
    p.exponent = 2;
    EXPECT_NEAR(p.evaluate(q), u.evaluate(q), 1e-15) << q;
  }
  for (double k : {0.25, 0.5, 3.0, 8.0}) {
    p.exponent = k;
    EXPECT_DOUBLE_EQ(p.evaluate(0), 0.0) << k;
    EXPECT_DOUBLE_EQ(p.evaluate(1), 1.0) << k;
    EXPECT_NEAR(p.evaluate(0.5), 1 - std::pow(0.5, k), 1e-15) << k;
  }
}
