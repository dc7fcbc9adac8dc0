// Ridge relief and rough walls (bark/dressing/bark_relief.h) on a synthetic FractureField
// built in code: one straight fracture along the axis, 2 cm wide, a U profile 1 cm deep.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "bark/dressing/bark_relief.h"
#include "bark/dressing/field_bark_surface.h"

using namespace phellem::bark;

namespace {

constexpr int kW = 300, kH = 100, kLeft = 140, kRight = 160;  // 1 mm pixels, fracture columns [140, 160)

FractureField one_fracture() {
  FractureField f;
  f.width = kW;
  f.height = kH;
  f.circumference = 0.3;
  f.length = 0.1;
  const size_t n = size_t(kW) * kH;
  f.opening.assign(n, 0), f.depth.assign(n, 0), f.uv0.assign(2 * n, 0), f.interior.assign(n, 0);
  f.fracture_id.assign(n, 0), f.age.assign(n, 0), f.level.assign(n, 0), f.color.assign(3 * n, 0);
  DepthProfile profile;
  for (int y = 0; y < kH; ++y)
    for (int x = kLeft; x < kRight; ++x) {
      const double a = (x + 0.5 - kLeft) / (kRight - kLeft), q = 1 - std::abs(2 * a - 1);
      f.opening[f.index(x, y)] = 1;
      f.fracture_id[f.index(x, y)] = 1;
      f.depth[f.index(x, y)] = float(0.01 * profile.evaluate(q));
    }
  return f;
}

double median(std::vector<double> v, double p = 0.5) {
  const size_t i = std::min(v.size() - 1, size_t(p * double(v.size() - 1) + 0.5));
  std::nth_element(v.begin(), v.begin() + long(i), v.end());
  return v[i];
}

// The definition, computed here on its own: heights −depth; fissure pixels are the
// fracture's columns, ridge pixels every column more than one pixel from them.
double measured_ratio(const FractureField& f) {
  std::vector<double> ridge, fissure;
  for (int y = 0; y < kH; ++y)
    for (int x = 0; x < kW; ++x) {
      const double h = -f.depth[f.index(x, y)];
      if (x >= kLeft && x < kRight)
        fissure.push_back(h);
      else if (x < kLeft - 1 || x > kRight)
        ridge.push_back(h);
    }
  return (median(ridge) - median(fissure)) / (median(ridge, 0.9) - median(ridge, 0.1));
}

ReliefLook look(double ratio, double detail, double walls) {
  ReliefLook l;
  l.enabled = true;
  l.depth_ratio = ratio;
  l.detail = detail;
  l.wall_noise = walls;
  l.shoulder_width = 0.03;
  l.seed = 9;
  return l;
}

}  // namespace

TEST(BarkRelief, RidgesRoundDownMonotonicallyTowardsTheLip) {
  FractureField f = one_fracture();
  apply_relief(f, look(1.5, 0.0, 0.0), DepthProfile{});
  for (int y = 0; y < kH; y += 7) {
    // Right of the fracture: heights (−depth) rise away from the lip up to the shoulder's width.
    for (int x = kRight; x < kRight + 29; ++x) EXPECT_GT(f.depth[f.index(x, y)], f.depth[f.index(x + 1, y)]) << x;
    for (int x = kLeft - 1; x > kLeft - 30; --x) EXPECT_GT(f.depth[f.index(x, y)], f.depth[f.index(x - 1, y)]) << x;
    EXPECT_FLOAT_EQ(f.depth[f.index(kRight + 40, y)], 0.0f);  // beyond the shoulder: the plate
  }
}

TEST(BarkRelief, DepthRatioIsWhatTheKnobAsks) {
  for (double ratio : {1.0, 1.5, 2.0})
    for (double detail : {0.0, 0.4, 0.8}) {
      FractureField f = one_fracture();
      const ReliefResult r = apply_relief(f, look(ratio, detail, 0.15), DepthProfile{});
      EXPECT_NEAR(r.ratio, measured_ratio(f), 1e-3 * r.ratio);  // it reports what it reached
      EXPECT_GT(r.scale, 0);
      if (detail > 0) {
        EXPECT_NEAR(measured_ratio(f), ratio, 0.2 * ratio) << "detail " << detail;
      } else {
        // A shoulder alone on one fracture in 30 cm of plate: 10 % of the ridge pixels lie on
        // it, so its P90 − P10 cannot exceed a quarter of the fissure depth: the lowest
        // reachable ratio, about 4.
        EXPECT_GE(measured_ratio(f), ratio);
      }
    }
  // Without the relief the ridges are flat: the ratio has no finite value (0 spread).
  EXPECT_EQ(depth_ratio(one_fracture()), 0.0);
}

TEST(BarkRelief, RoughWallsChangeTheProfileByTheRequestedRms) {
  for (double eps : {0.05, 0.2}) {
    const FractureField f0 = one_fracture();
    FractureField f = f0;
    roughen_walls(f, look(1.5, 0.4, eps));
    double s2 = 0;
    int n = 0;
    for (size_t p = 0; p < f.depth.size(); ++p) {
      if (f0.depth[p] <= 0) {
        EXPECT_EQ(f.depth[p], f0.depth[p]);  // the plates keep their height
        continue;
      }
      const double r = (f.depth[p] - f0.depth[p]) / f0.depth[p];
      s2 += r * r, ++n;
    }
    EXPECT_NEAR(std::sqrt(s2 / n), eps, 1e-3 * eps + 1e-5);
  }
}

TEST(BarkRelief, DetailTilesAcrossTheSeam) {
  const double C = 0.3;
  for (int i = 0; i < 50; ++i) {
    const double s = 0.013 * i;
    EXPECT_NEAR(tileable_fbm(0.0, s, 0.008, C, 0, 4), tileable_fbm(C, s, 0.008, C, 0, 4), 1e-6);
    EXPECT_NEAR(tileable_fbm(1e-4, s, 0.008, C, 0, 4), tileable_fbm(C + 1e-4, s, 0.008, C, 0, 4), 1e-6);
  }
  // The dressed field's displacement is the same at u = 0 and u = 1, and continuous across.
  FractureField f = one_fracture();
  apply_relief(f, look(1.5, 0.6, 0.15), DepthProfile{});
  const FieldBarkSurface s(f, 0.01);
  for (int i = 0; i < 20; ++i) {
    const double v = 0.05 * i + 0.01;
    EXPECT_NEAR(s.depth(0.0, v), s.depth(1.0, v), 1e-6);
  }
}

TEST(BarkRelief, OffLeavesTheFieldBitIdentical) {
  const FractureField f0 = one_fracture();
  FractureField f = f0;
  const ReliefResult r = apply_relief(f, ReliefLook{}, DepthProfile{});
  EXPECT_EQ(f.depth, f0.depth);
  EXPECT_EQ(r.scale, 0.0);
}

TEST(BarkRelief, WithoutRidgesOnlyTheWallsChange) {
  const FractureField f0 = one_fracture();
  ReliefLook l = look(1.0, 0.6, 0.2);
  l.ridges = false;
  FractureField f = f0, walls = f0;
  const ReliefResult r = apply_relief(f, l, DepthProfile{});
  roughen_walls(walls, l);
  EXPECT_EQ(f.depth, walls.depth);  // exactly the rough walls: no shoulder, no detail
  EXPECT_NE(f.depth, f0.depth);
  EXPECT_EQ(r.scale, 0.0);
  for (size_t p = 0; p < f.depth.size(); ++p) {
    if (f0.depth[p] <= 0) {
      ASSERT_EQ(f.depth[p], 0.0f) << p;  // the plates stay flat
    }
  }
}

TEST(BarkRelief, NoDetailAndNoWallNoiseSkipTheirNoiseExactly) {
  // detail 0 and wall_noise 0 multiply their fbm by 0: skipping it must not change a bit.
  FractureField a = one_fracture(), b = one_fracture();
  ReliefLook l = look(1.5, 0.0, 0.0);
  apply_relief(a, l, DepthProfile{});
  l.detail = 1e-60;  // computes the fbm, whose contribution rounds to 0 in float
  l.wall_noise = 1e-60;
  apply_relief(b, l, DepthProfile{});
  EXPECT_EQ(a.depth, b.depth);
}

TEST(BarkRelief, FissureDistanceIsEuclideanAndPeriodic) {
  FractureField f = one_fracture();
  const std::vector<float> d = fissure_distance(f);
  EXPECT_FLOAT_EQ(d[f.index(kLeft, 5)], 0.0f);
  EXPECT_NEAR(d[f.index(kRight + 9, 5)], 0.010, 1e-6);   // 10 pixels of 1 mm from column 159
  EXPECT_NEAR(d[f.index(kLeft - 20, 5)], 0.020, 1e-6);
  // Column 0 is 140 px from column 140 and 141 px from 159 across the seam; column 299 is
  // 140 px from 159 and 141 px from 140 across the seam.
  EXPECT_NEAR(d[f.index(0, 5)], 0.140, 1e-6);
  EXPECT_NEAR(d[f.index(kW - 1, 5)], 0.140, 1e-6);
}
