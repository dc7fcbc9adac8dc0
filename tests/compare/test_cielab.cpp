// compare/cielab: CIE L*a*b* (D65) of linear Rec.709 against published values.
#include <gtest/gtest.h>

#include "compare/cielab.h"

namespace phellem {
namespace {

TEST(Cielab, D65WhiteIsL100AndNeutral) {
  const Eigen::Vector3d w = linear_rec709_to_lab(Eigen::Vector3d(1, 1, 1));
  EXPECT_NEAR(w[0], 100, 1e-3);
  EXPECT_NEAR(w[1], 0, 1e-3);
  EXPECT_NEAR(w[2], 0, 1e-3);
  // Any grey is neutral; 18 % grey is L* 49.5 (CIE 15:2004 eq. 8.1: 116·0.18^(1/3) − 16 = 49.496).
  const Eigen::Vector3d g = linear_rec709_to_lab(Eigen::Vector3d::Constant(0.18));
  EXPECT_NEAR(g[0], 49.496, 1e-3);
  EXPECT_NEAR(g[1], 0, 1e-9);
  EXPECT_NEAR(g[2], 0, 1e-9);
  EXPECT_NEAR(linear_rec709_to_lab(Eigen::Vector3d::Zero()).norm(), 0, 1e-9);
}

TEST(Cielab, SrgbPrimariesMatchPublishedValues) {
  // sRGB #FF0000 / #00FF00 / #0000FF under D65 (Lindbloom's calculator, CSS Color 4 lab()):
  // red (53.24, 80.09, 67.20), green (87.73, −86.18, 83.18), blue (32.30, 79.19, −107.86).
  const Eigen::Vector3d r = linear_rec709_to_lab(Eigen::Vector3d(1, 0, 0));
  EXPECT_NEAR(r[0], 53.24, 0.02);
  EXPECT_NEAR(r[1], 80.09, 0.05);
  EXPECT_NEAR(r[2], 67.20, 0.05);
  const Eigen::Vector3d g = linear_rec709_to_lab(Eigen::Vector3d(0, 1, 0));
  EXPECT_NEAR(g[0], 87.73, 0.02);
  EXPECT_NEAR(g[1], -86.18, 0.05);
  EXPECT_NEAR(g[2], 83.18, 0.05);
  const Eigen::Vector3d b = linear_rec709_to_lab(Eigen::Vector3d(0, 0, 1));
  EXPECT_NEAR(b[0], 32.30, 0.02);
  EXPECT_NEAR(b[1], 79.19, 0.05);
  EXPECT_NEAR(b[2], -107.86, 0.05);
}

TEST(Cielab, DarkColoursUseTheLinearSegment) {
  // Y = 0.001 is under (6/29)³ = 0.008856: L* = 903.3·Y (CIE 15:2004 eq. 8.1, κ = 24389/27).
  const Eigen::Vector3d d = linear_rec709_to_lab(Eigen::Vector3d::Constant(0.001));
  EXPECT_NEAR(d[0], 24389.0 / 27 * 0.001, 1e-6);
}

}  // namespace
}  // namespace phellem
