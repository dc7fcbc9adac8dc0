// Stripes against isotropic noise (plan §3, "Synthetic tests"): the score says "different"
// (≥ 0.5) and the orientation histograms are ≥ 30° apart.
#include <gtest/gtest.h>

#include "compare/compare_score.h"
#include "tests/compare/synthetic_fields.h"

namespace phellem {
namespace {

TEST(StripesVsNoise, AreFarApart) {
  const HeightField stripes = test::add(test::stripes(512, 10, 32, 5), test::smooth_noise(512, 10, 3, 1), 0.05);
  const HeightField noise = test::smooth_noise(512, 10, 5, 2);  // G(0.5 cm)∗white
  const Comparison c = compare_fissures(analyse_fissures(stripes, nullptr, "stripes").stats,
                                        analyse_fissures(noise, nullptr, "noise").stats);
  EXPECT_GE(c.score, 0.5);
  EXPECT_GE(c.orientation_emd_deg, 30);
  EXPECT_EQ(c.verdict, "different");
  EXPECT_EQ(c.core.size(), 7u);
  // And a field against itself is the same bark, at distance 0.
  const FissureStats a = analyse_fissures(noise, nullptr, "noise").stats;
  const Comparison self = compare_fissures(a, a);
  EXPECT_EQ(self.score, 0);
  EXPECT_EQ(self.orientation_emd_deg, 0);
  EXPECT_EQ(self.verdict, "same bark");
}

}  // namespace
}  // namespace phellem
