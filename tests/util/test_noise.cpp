// Gradient noise and its band-limited fractal sums.
#include <gtest/gtest.h>

#include "util/noise.h"

namespace phellem {
namespace {

TEST(Noise, IsZeroOnTheLatticeAndBounded) {
  for (int x = -3; x <= 3; ++x)
    for (int z = -2; z <= 2; ++z) EXPECT_EQ(gradient_noise(Vec3f(float(x), 1.0f, float(z)), 5), 0.0f);
  float lo = 0, hi = 0;
  for (int i = 0; i < 20000; ++i) {
    const float v = gradient_noise(Vec3f(0.37f * i, 0.11f * i, 0.053f * i), 9);
    lo = std::min(lo, v);
    hi = std::max(hi, v);
  }
  EXPECT_GT(lo, -1.5f);
  EXPECT_LT(hi, 1.5f);
  EXPECT_LT(lo, -0.3f);  // it does vary
  EXPECT_GT(hi, 0.3f);
}

TEST(Noise, FilteredFbmMatchesFbmWhenUnfilteredAndFadesBandsOut) {
  double var[4] = {0, 0, 0, 0}, mean_wide = 0;
  const float widths[4] = {0.0f, 0.1f, 0.2f, 0.45f};
  for (int i = 0; i < 4000; ++i) {
    const Vec3f p(0.731f * i, 0.291f * i, 0.117f * i);
    ASSERT_EQ(fbm_filtered(p, 3, 3, 0.0f), fbm(p, 3, 3));
    EXPECT_EQ(fbm_filtered(p, 3, 3, 0.5f), 0.0f);  // every band at or past Nyquist
    for (int k = 0; k < 4; ++k) {
      const float v = fbm_filtered(p, 3, 3, widths[k]);
      var[k] += double(v) * v;
    }
    mean_wide += fbm_filtered(p, 3, 3, 0.2f);
  }
  // Wider filters keep fewer bands: the variance falls monotonically but stays positive
  // while the first band survives.
  for (int k = 1; k < 4; ++k) EXPECT_LT(var[k], var[k - 1]) << "width " << widths[k];
  EXPECT_GT(var[3], 0.0);
  EXPECT_NEAR(mean_wide / 4000, 0.0, 0.05);  // dropped bands are replaced by their mean
  EXPECT_EQ(band_weight(0.2f), 1.0f);
  EXPECT_EQ(band_weight(0.5f), 0.0f);
  EXPECT_FLOAT_EQ(band_weight(0.375f), 0.5f);
}

}  // namespace
}  // namespace phellem

namespace phellem {

TEST(Noise, TileableValueNoiseWrapsAfterItsPeriodAndStaysInTheUnitInterval) {
  const int64_t nx = 7, ny = 5;
  for (int i = 0; i < 200; ++i) {
    const double x = 0.37 * i - 20, y = 0.61 * i - 30;
    const float v = tileable_value_noise(x, y, 9, nx, ny);
    EXPECT_GE(v, 0.0f);
    EXPECT_LE(v, 1.0f);
    EXPECT_FLOAT_EQ(v, tileable_value_noise(x + nx, y, 9, nx, ny));
    EXPECT_FLOAT_EQ(v, tileable_value_noise(x, y - 2 * ny, 9, nx, ny));
  }
  // At lattice points it is the lattice value; another seed gives other lattice values. (Not
  // every interpolated value differs: the seed enters the hash by one XOR before a single
  // multiply, so cell centres, averages of four lattice values, can coincide for two seeds.)
  EXPECT_FLOAT_EQ(tileable_value_noise(3, 2, 9, nx, ny), lattice_hash01(3, 2, 9, nx, ny));
  int differ = 0;
  for (int i = 0; i < 20; ++i) differ += lattice_hash01(i, 0, 9, 0, 0) != lattice_hash01(i, 0, 10, 0, 0);
  EXPECT_EQ(differ, 20);
}

}  // namespace phellem
