// The polynomial inverse trigonometric functions against libm over their whole domain.
#include <gtest/gtest.h>

#include "util/fast_trig.h"

namespace phellem {
namespace {

TEST(FastTrig, AcosWithinOneMicroradian) {
  float worst = 0;
  for (int i = 0; i <= 200000; ++i) {
    const float x = -1.0f + 2.0f * float(i) / 200000.0f;
    worst = std::max(worst, std::abs(fast_acos(x) - std::acos(x)));
  }
  EXPECT_LT(worst, 1e-6f);
  EXPECT_EQ(fast_acos(1.0f), 0.0f);
  EXPECT_NEAR(fast_acos(-1.0f), kPi, 1e-6f);
}

TEST(FastTrig, Atan2WithinOneMicroradianInEveryOctant) {
  float worst = 0;
  for (int i = 0; i < 100000; ++i) {
    const float a = kTwoPi * float(i) / 100000.0f - kPi;
    for (float r : {1e-3f, 1.0f, 250.0f}) {
      const float y = r * std::sin(a), x = r * std::cos(a);
      float e = std::abs(fast_atan2(y, x) - std::atan2(y, x));
      e = std::min(e, kTwoPi - e);  // ±π are the same angle
      worst = std::max(worst, e);
    }
  }
  EXPECT_LT(worst, 1e-6f);
  EXPECT_EQ(fast_atan2(0.0f, 0.0f), 0.0f);
  EXPECT_EQ(fast_atan2(0.0f, 1.0f), 0.0f);
  EXPECT_NEAR(fast_atan2(1.0f, 0.0f), 0.5f * kPi, 1e-7f);
  EXPECT_NEAR(fast_atan2(-1.0f, 0.0f), -0.5f * kPi, 1e-7f);
}

TEST(FastTrig, SinCosWithinFloatRounding) {
  float worst = 0;
  for (int i = 0; i <= 400000; ++i) {
    const float x = -4.0f * kPi + 8.0f * kPi * float(i) / 400000.0f;
    float s, c;
    fast_sincos(x, &s, &c);
    worst = std::max({worst, std::abs(s - std::sin(x)), std::abs(c - std::cos(x))});
  }
  EXPECT_LT(worst, 5e-7f);
  float s, c;
  fast_sincos(0.0f, &s, &c);
  EXPECT_EQ(s, 0.0f);
  EXPECT_EQ(c, 1.0f);
}

}  // namespace
}  // namespace phellem
