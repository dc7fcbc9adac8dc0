// Spiral grain (StripParams::spiral_deg): the fissures of a strip patch lean off the axis by
// the angle asked for, as the compare statistics measure it, with the sign documented (positive:
// θ, the image's x, increases upwards, so the fissures lean right and the mean orientation,
// measured in the image with y down, drops below 90°). 0 leaves the paper's model unchanged.
#include <gtest/gtest.h>

#include "compare/fissure_statistics.h"
#include "compare/fit_parameters.h"
#include "bark/strips/presets.h"

#include <limits>

using namespace phellem;

namespace {

double mean_orientation(double spiral_deg, uint64_t seed) {
  const FitSpace space = strip_fit_space();
  FitCandidate c = space.candidate(space.starts[0]);  // the fissured preset
  c.strips.params.spiral_deg = spiral_deg;
  return analyse_fissures(simulate_candidate(c, PatchSize{320, 320, 5.0}, seed), nullptr, "spiral").stats.orientation_mean_deg;
}

}  // namespace

TEST(SpiralGrain, FissuresLeanByTheAngle) {
  for (uint64_t seed : {3u, 4u}) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    const double straight = mean_orientation(0, seed);
    EXPECT_NEAR(straight, 90.0, 2.0);
    EXPECT_NEAR(mean_orientation(8, seed), 90.0 - 8, 2.5);
    EXPECT_NEAR(mean_orientation(-8, seed), 90.0 + 8, 2.5);
  }
}

TEST(SpiralGrain, OutOfRangeIsRefused) {
  bark::StripParams p = *bark::strip_preset("fissured");
  p.spiral_deg = 46;
  const auto e = bark::validate(p);
  ASSERT_TRUE(e.has_value());
  EXPECT_EQ(e->key, "spiral_deg");
  p.spiral_deg = std::numeric_limits<double>::quiet_NaN();
  EXPECT_TRUE(bark::validate(p).has_value());
  p.spiral_deg = -45;
  EXPECT_FALSE(bark::validate(p).has_value());
}
