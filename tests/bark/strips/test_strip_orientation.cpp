// Strip orientation on a trunk (Lefebvre & Neyret 2002, sec. 5): horizontal strips tear
// around the trunk, vertical ones along it, axial strips follow the local circumference.
#include <gtest/gtest.h>

#include <Eigen/Dense>

#include "bark/geometry/generalized_cylinder.h"
#include "bark/strips/fracture_field.h"
#include "bark/strips/presets.h"
#include "bark/strips/strip_model.h"
#include "tests/support/strip_helpers.h"

using namespace phellem::bark;

namespace {

// Mean length (m) of the runs of open pixels along the rows (around the trunk) and along the
// columns (along it).
Eigen::Vector2d mean_runs(const FractureField& f) {
  auto open = [&](int x, int y) { return f.opening[f.index(x, y)] > 0.5f; };
  auto mean = [](long long pixels, long long runs) { return runs ? double(pixels) / double(runs) : 0.0; };
  long long hp = 0, hr = 0, vp = 0, vr = 0;
  for (int y = 0; y < f.height; ++y)
    for (int x = 0; x < f.width; ++x) {
      if (!open(x, y)) continue;
      ++hp, ++vp;
      hr += !open((x + f.width - 1) % f.width, y);
      vr += y == 0 || !open(x, y - 1);
    }
  return {mean(hp, hr) * f.circumference / f.width, mean(vp, vr) * f.length / f.height};
}

FractureField cylinder_field(StripParams p, int steps) {
  p.steps = steps;
  const GeneralizedCylinder c({{0, 0, 0}, {0, 0.5, 0}}, {0.07});
  StripModel m(oriented_domain(c, p), p);
  while (m.steps_done() < m.steps_total()) m.step();
  return rasterize(m, 440, 500, DepthProfile{});
}

}  // namespace

TEST(StripOrientation, HorizontalStripsTearAroundTheTrunkAndVerticalOnesAlongIt) {
  // The paper's model tears along the axis; its horizontal variant (strips along the axis,
  // axial growth) tears around it. Open runs are several times longer in the tear direction (3.8× measured).
  const Eigen::Vector2d banded = mean_runs(cylinder_field(*strip_preset("banded"), 300));
  const Eigen::Vector2d furrowed = mean_runs(cylinder_field(*strip_preset("furrowed"), 300));
  EXPECT_GT(banded.x(), 2.5 * banded.y()) << banded.transpose();
  EXPECT_GT(furrowed.y(), 2.5 * furrowed.x()) << furrowed.transpose();
}

TEST(StripOrientation, AxialStripsFollowTheLocalCircumference) {
  // On a cone the strips along the axis narrow with the radius (sec. 5.3: K = R w / l0), so
  // the fracture density around the trunk stays constant; the domain spans the mean
  // circumference with about one strip per strip_width.
  StripParams p = *strip_preset("banded");
  const GeneralizedCylinder cone({{0, 0, 0}, {0, 1, 0}}, {0.2, 0.1});
  const StripDomain d = longitudinal_domain(cone, p, 16);
  EXPECT_TRUE(d.along_axis && d.wrap_s && !d.cyclic);
  EXPECT_NEAR(d.length, 2 * M_PI * 0.15, 0.01);
  EXPECT_NEAR(d.strip_width, p.strip_width, 0.05 * p.strip_width);
  const StripMetric& m = d.strips[3];
  EXPECT_NEAR(m.width.front() / m.width.back(), (0.2 - 0.1 / 32) / (0.1 + 0.1 / 32), 0.01);
  double along = 0;
  for (double b : m.bin_length) along += b;
  EXPECT_NEAR(along, std::hypot(1.0, 0.1), 1e-3);
}
