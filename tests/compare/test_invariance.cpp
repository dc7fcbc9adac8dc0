// Affine invariance (plan §3.0): z → 3.75·z + 12 of stripes plus noise changes no statistic
// (1e-9 relative) and scores < 1e-9. The heights are quantised to 2⁻¹² and the scale is 3.75 so
// that the changed field is exact in float: with 3.7 (not a binary fraction) the float inputs
// themselves would differ from an affine image by rounding (~1e-7), which is not what is tested.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "compare/compare_score.h"
#include "tests/compare/synthetic_fields.h"

namespace phellem {
namespace {

void expect_relative(double a, double b, const char* name) {
  EXPECT_LE(std::abs(a - b), 1e-9 * std::max({std::abs(a), std::abs(b), 1e-300})) << name << ": " << a << " vs " << b;
}

TEST(Invariance, AnAffineChangeOfTheHeightsChangesNoStatistic) {
  HeightField f = test::add(test::stripes(512, 10, 32, 5), test::smooth_noise(512, 10, 3, 1), 0.05);
  for (float& v : f.z) v = std::round(v * 4096.0f) / 4096.0f;
  HeightField g = f;
  for (float& v : g.z) v = 3.75f * v + 12.0f;
  for (size_t i = 0; i < f.z.size(); ++i) ASSERT_EQ(double(g.z[i]), 3.75 * double(f.z[i]) + 12.0);  // exact
  const FissureStats a = analyse_fissures(f, nullptr, "f").stats, b = analyse_fissures(g, nullptr, "g").stats;
  expect_relative(a.fissure_fraction, b.fissure_fraction, "fissure_fraction");
  expect_relative(a.vertical_fraction, b.vertical_fraction, "vertical_fraction");
  expect_relative(a.orientation_mean_deg, b.orientation_mean_deg, "orientation_mean_deg");
  expect_relative(a.spacing_h_mean, b.spacing_h_mean, "spacing_h_mean");
  expect_relative(a.spacing_h_std, b.spacing_h_std, "spacing_h_std");
  expect_relative(a.spacing_v_mean, b.spacing_v_mean, "spacing_v_mean");
  expect_relative(a.spacing_v_std, b.spacing_v_std, "spacing_v_std");
  expect_relative(a.width_mean, b.width_mean, "width_mean");
  expect_relative(a.width_std, b.width_std, "width_std");
  expect_relative(a.length_median, b.length_median, "length_median");
  expect_relative(a.depth_ratio, b.depth_ratio, "depth_ratio");
  for (int k = 0; k < kOrientationBins; ++k) EXPECT_NEAR(a.orientation_hist[size_t(k)], b.orientation_hist[size_t(k)], 1e-9);
  const Comparison c = compare_fissures(a, b);
  EXPECT_LT(c.score, 1e-9);
  EXPECT_LT(c.orientation_emd_deg, 1e-9);
  // The field is not degenerate: it has fissures and noise.
  EXPECT_GT(a.fissure_fraction, 0.1);
  EXPECT_GT(a.spacing_h_std, 0);
}

}  // namespace
}  // namespace phellem
