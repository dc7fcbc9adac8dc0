// The painted speed map of a growth (scene/growth_desc.h, Kratt et al. sec. 4.4): bilinear
// between texel centres, repeating, and safe for the huge or non-finite texture coordinates a
// mesh file may hold.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "scene/growth_desc.h"

using namespace phellem;

TEST(GrowthSpeedMap, BilinearBetweenTexelCentresRepeatingAndSafeForAnyUv) {
  GrowthSpeedMap m;
  m.width = 2;
  m.height = 1;
  m.values = {0.0f, 1.0f};
  EXPECT_FLOAT_EQ(m.at(0.25, 0.5), 0.0f);  // the first texel's centre
  EXPECT_FLOAT_EQ(m.at(0.75, 0.5), 1.0f);  // the second's
  EXPECT_FLOAT_EQ(m.at(0.5, 0.5), 0.5f);   // half-way
  EXPECT_FLOAT_EQ(m.at(0.0, 0.5), 0.5f);   // the seam blends the last texel with the first
  EXPECT_FLOAT_EQ(m.at(1.75, -3.5), 1.0f); // repeats in both directions
  EXPECT_FLOAT_EQ(m.at(-0.25, 0.5), 1.0f);
  for (double bad : {1e30, -1e300, std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity()}) {
    const float x = m.at(bad, bad);
    EXPECT_TRUE(x >= 0.0f && x <= 1.0f) << bad;
  }
}
