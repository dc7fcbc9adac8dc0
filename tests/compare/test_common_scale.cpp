// compare/common_scale (plan §3.0 and "Synthetic tests", two scales): the same random
// V-fissure field at 10 px/cm and at 5 px/cm scores ≤ 0.08 when the scales are declared, and
// ≥ 0.15 when the coarse one is declared 10 px/cm: the scale matters.
#include <gtest/gtest.h>

#include "compare/common_scale.h"
#include "compare/compare_score.h"
#include "tests/compare/synthetic_fields.h"

namespace phellem {
namespace {

// A second camera: 2×2 pixels averaged (not OIIO's filter, so the pipeline test is not trivial).
HeightField box_half(const HeightField& f) {
  HeightField h{f.width / 2, f.height / 2, f.px_per_cm / 2, {}};
  for (int y = 0; y < h.height; ++y)
    for (int x = 0; x < h.width; ++x)
      h.z.push_back(0.25f * (f.at(2 * x, 2 * y) + f.at(2 * x + 1, 2 * y) + f.at(2 * x, 2 * y + 1) + f.at(2 * x + 1, 2 * y + 1)));
  return h;
}

TEST(CommonScale, IsTheCoarserScaleAndNeverUpsamples) {
  EXPECT_EQ(common_scale(10, 5), 5);
  EXPECT_EQ(common_scale(4, 12.5), 4);
  const HeightField f = test::smooth_noise(400, 10, 2, 3);
  const HeightField same = resample(f, 10, 10, 10);
  EXPECT_EQ(same.width, 400);
  EXPECT_EQ(same.z, f.z);
  const HeightField up = resample(f, 10, 10, 20);  // asked to upsample: stays as it is
  EXPECT_EQ(up.width, 400);
  EXPECT_EQ(up.px_per_cm, 10);
  const HeightField half = resample(f, 10, 10, 5);
  EXPECT_EQ(half.width, 200);
  EXPECT_EQ(half.height, 200);
  EXPECT_EQ(half.px_per_cm, 5);
  // Each axis to the target on its own: 10 px/cm across, 5 along.
  HeightField rect{400, 300, 0, std::vector<float>(400 * 300, 1.0f)};
  const HeightField r = resample(rect, 10, 5, 5);
  EXPECT_EQ(r.width, 200);
  EXPECT_EQ(r.height, 300);
  EXPECT_NEAR(r.z[1234], 1.0f, 1e-5);  // a constant stays constant (the filter is normalised)
  // The scale is recomputed from the rounded size: 333 px at 10 → 3.33·… rounds to 111 px.
  const HeightField odd = resample(test::smooth_noise(333, 10, 2, 4), 10, 10, 3.3);
  EXPECT_EQ(odd.width, 110);
  EXPECT_NEAR(odd.px_per_cm, 10.0 * 110 / 333, 1e-12);
}

TEST(CommonScale, TheSameFieldAtTwoDeclaredScalesIsTheSameBark) {
  const HeightField a = test::v_fissures(1024, 10, 260, 5);
  const HeightField b = box_half(a);  // 512², 5 px/cm
  const FissureStats sb = analyse_fissures(b, nullptr, "B").stats;
  // The statistics are physical (cm): measured at their own scales, they agree.
  const Comparison direct = compare_fissures(analyse_fissures(a, nullptr, "A").stats, sb);
  EXPECT_LE(direct.score, 0.08);
  // Through the common scale (`--scale A=10 --scale B=5`): A is shrunk to 5 px/cm.
  const double s = common_scale(a.px_per_cm, b.px_per_cm);
  const HeightField a5 = resample(a, a.px_per_cm, a.px_per_cm, s);
  const Comparison pipeline = compare_fissures(analyse_fissures(a5, nullptr, "A").stats, sb);
  EXPECT_LE(pipeline.score, 0.08);
  // Declaring B at 10 px/cm (a 2× mismatch) makes it another bark.
  HeightField b_wrong = b;
  b_wrong.px_per_cm = 10;
  const Comparison wrong = compare_fissures(analyse_fissures(a, nullptr, "A").stats,
                                            analyse_fissures(b_wrong, nullptr, "B").stats);
  EXPECT_GE(wrong.score, 0.15);
  std::printf("two scales: direct %.3f, common scale %.3f, wrong scale %.3f\n", direct.score, pipeline.score, wrong.score);
}

}  // namespace
}  // namespace phellem
