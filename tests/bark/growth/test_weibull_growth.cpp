// Growth functions of cambial growth (bark/growth/weibull_growth.h; Kratt et al., Eqs. 2–3).
#include <gtest/gtest.h>

#include <cmath>

#include "bark/growth/weibull_growth.h"

using namespace phellem;
using namespace phellem::bark;

TEST(WeibullGrowth, Equation2IntegratesToItsCumulativeForm) {
  for (float c : {1.0f, 2.0f, 3.5f}) {
    GrowthFunction g;
    g.weibull_c = c;
    g.thickness = 1;
    // Known values: s(1) = c/e, and the density peaks at t = ((c − 1)/c)^(1/c) for c > 1.
    EXPECT_NEAR(g.weibull(1.0), c / std::exp(1.0), 1e-12);
    // ∫₀³ s dt by Simpson's rule against 1 − exp(−3^c).
    const int n = 20000;
    double sum = 0;
    for (int i = 0; i <= n; ++i) {
      const double t = 3.0 * i / n, w = (i == 0 || i == n) ? 1 : (i % 2 ? 4 : 2);
      sum += w * g.weibull(t);
    }
    sum *= 3.0 / n / 3;
    EXPECT_NEAR(sum, g.cumulative(3.0), 1e-6) << c;
    EXPECT_NEAR(g.cumulative(3.0), 1 - std::exp(-std::pow(3.0, c)), 1e-12);
  }
  GrowthFunction g;
  g.weibull_c = 2;
  const double peak = std::sqrt(0.5);  // ((c − 1)/c)^(1/c)
  EXPECT_GT(g.weibull(peak), g.weibull(peak - 0.05));
  EXPECT_GT(g.weibull(peak), g.weibull(peak + 0.05));
}

TEST(WeibullGrowth, TotalThickeningDoesNotDependOnTheStepSize) {
  GrowthFunction g;
  g.age_scale = 40;  // years
  g.thickness = 0.08;
  const Vec3f p(0, 1, 0), n(1, 0, 0);
  for (int steps : {1, 7, 200, 5000}) {
    double total = 0;
    for (int i = 0; i < steps; ++i) total += g.thickening(60.0 * i / steps, 60.0 * (i + 1) / steps, p, n);
    EXPECT_NEAR(total, g.cumulative(60.0), 1e-12) << steps;
  }
  EXPECT_NEAR(g.cumulative(60.0), double(0.08f) * (1 - std::exp(-std::pow(1.5, 2.0))), 1e-12);  // the float parameter
}

TEST(WeibullGrowth, Equation3FavoursOneSideByOnePlusEOverOneMinusE) {
  GrowthFunction g;
  g.eccentricity = 0.3f;
  g.eccentricity_direction = Vec3f(0, 0, 1);
  const Vec3f p = Vec3f::Zero();
  const double up = g.thickening(0, 1, p, Vec3f(0, 0, 1)), down = g.thickening(0, 1, p, Vec3f(0, 0, -1));
  const double e = double(0.3f);  // the float parameter
  EXPECT_NEAR(up / down, (1 + e) / (1 - e), 1e-12);
  EXPECT_NEAR(g.thickening(0, 1, p, Vec3f(1, 0, 0)), g.cumulative(1), 1e-12);  // across: unchanged
}

TEST(WeibullGrowth, StrokesScaleTheSpeedWithAGaussianFalloff) {
  GrowthFunction g;
  g.strokes.push_back({Vec3f(0, 0, 0), 0.1f, 2.0f});
  g.strokes.push_back({Vec3f(5, 0, 0), 0.1f, -1.0f});
  EXPECT_NEAR(g.stroke_factor(Vec3f(0, 0, 0)), 3.0, 1e-6);
  EXPECT_NEAR(g.stroke_factor(Vec3f(0.1f, 0, 0)), 1 + 2 * std::exp(-0.5), 1e-6);  // one σ away
  EXPECT_NEAR(g.stroke_factor(Vec3f(2, 0, 0)), 1.0, 1e-6);                         // far from both
  EXPECT_NEAR(g.stroke_factor(Vec3f(5, 0, 0)), 0.0, 1e-6);                         // growth stopped
  EXPECT_EQ(g.thickening(0, 1, Vec3f(5, 0, 0), Vec3f(0, 1, 0)), 0.0);
}
