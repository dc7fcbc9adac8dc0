// compare/colour_statistics: OKLab with Ottosson's matrices, and the fissure contrast.
#include <gtest/gtest.h>

#include "compare/colour_statistics.h"

namespace phellem {
namespace {

TEST(OkLab, WhiteIsLOneAndNeutral) {
  const Eigen::Vector3d w = linear_srgb_to_oklab(Eigen::Vector3d(1, 1, 1));
  EXPECT_NEAR(w[0], 1.0, 1e-6);
  EXPECT_NEAR(w[1], 0.0, 1e-6);
  EXPECT_NEAR(w[2], 0.0, 1e-6);
  EXPECT_NEAR(linear_srgb_to_oklab(Eigen::Vector3d(0, 0, 0)).norm(), 0.0, 1e-12);
}

TEST(OkLab, SrgbRedMatchesThePublishedValue) {
  // Ottosson 2020 / CSS Color 4: sRGB #ff0000 = oklab(0.627955, 0.224863, 0.125846).
  const Eigen::Vector3d r = linear_srgb_to_oklab(Eigen::Vector3d(1, 0, 0));
  EXPECT_NEAR(r[0], 0.627955, 1e-3);
  EXPECT_NEAR(r[1], 0.224863, 1e-3);
  EXPECT_NEAR(r[2], 0.125846, 1e-3);
}

TEST(ColourStatistics, ContrastIsRidgeLightnessMinusFissureLightness) {
  // 4 pixels: two grey ridges (0.5), one dark fissure (0.05), one pixel neither.
  AlbedoField a{2, 2, {0.5f, 0.5f, 0.5f, 0.5f, 0.5f, 0.5f, 0.05f, 0.05f, 0.05f, 0.2f, 0.2f, 0.2f}};
  const ColourStats c = colour_statistics(a, {0, 0, 1, 0}, {1, 1, 0, 0});
  const double L_ridge = linear_srgb_to_oklab(Eigen::Vector3d::Constant(0.5))[0];
  const double L_fissure = linear_srgb_to_oklab(Eigen::Vector3d::Constant(0.05))[0];
  EXPECT_NEAR(c.contrast, L_ridge - L_fissure, 1e-7);  // the albedo is float
  EXPECT_GT(c.contrast, 0.4);
  EXPECT_NEAR(c.a_mean, 0, 1e-6);  // greys
  EXPECT_GT(c.L_std, 0.1);
}

}  // namespace
}  // namespace phellem
