// Stripes rotated by θ (plan §3, "Synthetic tests"): the circular mean orientation is θ within
// 1.5°, 95 % of the histogram mass lies within ±10° of θ, and along the rows the spacing is
// P/|sin θ| within 1 px for θ ≥ 30° (the spacing is measured along the image axis).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "compare/fissure_statistics.h"
#include "tests/compare/synthetic_fields.h"

namespace phellem {
namespace {

double axial_difference(double a, double b) {
  const double d = std::fmod(std::abs(a - b), 180.0);
  return std::min(d, 180 - d);
}

TEST(RotatedStripes, OrientationAndRowSpacingFollowTheAngle) {
  const double s = 10, P = 32, W = 5;
  for (double theta : {0, 15, 30, 45, 60, 75, 90}) {
    SCOPED_TRACE("theta " + std::to_string(theta));
    const FissureStats st = analyse_fissures(test::stripes(512, s, P, W, theta), nullptr, "rotated").stats;
    EXPECT_LE(axial_difference(st.orientation_mean_deg, theta), 1.5);
    double near = 0;
    for (int k = 0; k < kOrientationBins; ++k)
      if (axial_difference(10.0 * k, theta) <= 10) near += st.orientation_hist[size_t(k)];
    EXPECT_GE(near, 0.95);
    if (theta >= 30) {
      EXPECT_NEAR(st.spacing_h_mean * s, P / std::abs(std::sin(theta * std::numbers::pi / 180)), 1.0);
    }
  }
}

}  // namespace
}  // namespace phellem
