// The cambial growth stepper (bark/growth/cambial_growth.h): UVs persist (sec. 4.6: texture
// coordinates do not swim as the surface grows and is refined), rings nest, and reversed
// growth (sec. 4.3) shrinks a surface by the thickening it would have grown.
#include <gtest/gtest.h>

#include <cmath>

#include "bark/geometry/procedural_meshes.h"
#include "bark/growth/cambial_growth.h"
#include "bark/growth/ring_section.h"

using namespace phellem;
using namespace phellem::bark;

namespace {

constexpr double kPiD = 3.141592653589793;

CambialGrowthSettings uniform_growth(double thickness, int steps) {
  CambialGrowthSettings s;
  s.function.weibull_c = 1;
  s.function.age_scale = 1;
  s.function.thickness = float(thickness);
  s.age_start = 0;
  s.age_end = 1;
  s.steps = steps;
  s.ring_interval = 2;
  return s;
}

// The largest distance in UV between an interface vertex's carried UV and the longitude /
// latitude UV of its direction (icosphere's own layout), away from the seam and the poles.
double worst_uv_error(const CambialGrowth& g) {
  const TetComplex& c = g.complex();
  double worst = 0;
  for (size_t i = 0; i < c.points.size(); ++i) {
    if (!c.on_interface[i]) continue;
    const Eigen::Vector3d d = c.points[i].normalized();
    const double u = 0.5 + std::atan2(d.z(), d.x()) / (2 * kPiD), v = std::acos(std::clamp(d.y(), -1.0, 1.0)) / kPiD;
    if (v < 0.2 || v > 0.8 || u < 0.1 || u > 0.9) continue;
    worst = std::max(worst, (Eigen::Vector2d(u, v) - c.uv[i]).norm());
  }
  return worst;
}

}  // namespace

TEST(CambialGrowth, UvsFollowTheSurfaceAndConvergeWithRefinement) {
  // A sphere growing 1.8× its radius: every edge is split at least once or twice, so most
  // vertices carry interpolated UVs. A vertex that slid tangentially, or a UV interpolated
  // wrongly, shows as a difference from the layout.
  // Levels 2 and 3 only: at level 4 (and 32 steps) vertices lag behind the front by up to a
  // sixth of the growth where the outside tetrahedra are needles to the box corners, their
  // normals tilt, and the error is 0.03 (issue 24's notes: the lag is the open problem).
  double error[2];
  double edge[2];
  for (int level : {2, 3}) {
    const TriMesh sphere = icosphere(level, 0.5);
    CambialGrowth g(sphere, {}, uniform_growth(0.4 / (1 - std::exp(-1.0)), 32), "s.json", "/objects/0/growth");
    while (g.step()) {
    }
    ASSERT_GT(g.stats().splits, 100) << "level " << level;
    error[level - 2] = worst_uv_error(g);
    edge[level - 2] = 1.0 / (5 * std::pow(2.0, level));  // icosphere edge in UV, about
  }
  // Bound: a tenth of an edge of the input's layout; convergence: finer input, smaller error.
  EXPECT_LT(error[0], 0.1 * edge[0]) << error[0];
  EXPECT_LT(error[1], 0.1 * edge[1]) << error[1];
  EXPECT_LT(error[1], 0.6 * error[0]) << error[0] << " -> " << error[1];
}

TEST(CambialGrowth, RingsNestInEveryCrossSection) {
  CambialGrowthSettings s = uniform_growth(0.15, 8);
  s.function.eccentricity = 0.5f;
  s.function.eccentricity_direction = Vec3f(1, 0, 0);
  const TriMesh log = log_mesh(0.1, 0.4, 40, 20, 0.2, 5);
  CambialGrowth g(log, {}, s, "s.json", "/objects/0/growth");
  while (g.step()) {
  }
  ASSERT_EQ(g.rings().size(), 5u);
  // In the plane y = 0.2, along rays from the axis, the rings are crossed in order.
  const SectionPlane plane{1, 0.2};
  for (int ray = 0; ray < 24; ++ray) {
    const Eigen::Vector2d dir(std::cos(2 * kPiD * ray / 24), std::sin(2 * kPiD * ray / 24));
    double last = 0;
    for (const GrowthRing& r : g.rings()) {
      double hit = -1;
      for (const auto& seg : section_segments(r, plane)) {
        // Ray from the origin (the log's axis) against the segment.
        Eigen::Matrix2d m;
        m << dir, seg[0] - seg[1];
        if (std::abs(m.determinant()) < 1e-14) continue;
        const Eigen::Vector2d ts = m.colPivHouseholderQr().solve(seg[0]);
        if (ts.x() > 0 && ts.y() >= 0 && ts.y() <= 1) hit = std::max(hit, ts.x());
      }
      ASSERT_GT(hit, 0) << "ring " << r.step << " ray " << ray;
      EXPECT_GE(hit, last) << "ring " << r.step << " crosses the one before on ray " << ray;
      last = hit;
    }
  }
}

TEST(CambialGrowth, ReversedGrowthShrinksByTheThickeningItWouldHaveGrown) {
  const double r0 = 0.5, thickness = 0.1;
  CambialGrowthSettings s = uniform_growth(thickness, 6);
  s.reverse = true;
  CambialGrowth g(icosphere(3, r0), {}, s, "s.json", "/objects/0/growth");
  EXPECT_DOUBLE_EQ(g.age(), 1.0);  // reversed: starts at the end age
  while (g.step()) {
  }
  EXPECT_DOUBLE_EQ(g.age(), 0.0);
  const double expected = r0 - thickness * (1 - std::exp(-1.0));
  const TetComplex& c = g.complex();
  EXPECT_EQ(c.first_inverted(), -1);
  for (size_t i = 0; i < c.points.size(); ++i)
    if (c.on_interface[i]) {
      EXPECT_NEAR(c.points[i].norm(), expected, 0.004) << "point " << i;
    }
}

TEST(CambialGrowth, APaintedSpeedMapGrowsOnlyWhereItIsPainted) {
  // Sec. 4.4: speed 1 on the +x half of a sphere, 0 on the −x half.
  const double r0 = 0.5, thickness = 0.06;
  const TriMesh sphere = icosphere(3, r0);
  std::vector<float> speed;
  for (const auto& p : sphere.positions) speed.push_back(p.x() > 0 ? 1.0f : 0.0f);
  CambialGrowth g(sphere, {}, uniform_growth(thickness, 6), "s.json", "/objects/0/growth", speed);
  while (g.step()) {
  }
  const double grown = thickness * (1 - std::exp(-1.0));
  const TetComplex& c = g.complex();
  int painted = 0, bare = 0;
  for (size_t i = 0; i < c.points.size(); ++i) {
    if (!c.on_interface[i]) continue;
    const Eigen::Vector3d& p = c.points[i];
    if (p.x() > 0.2) {  // well inside the painted half
      EXPECT_NEAR(p.norm(), r0 + grown, 0.01) << "point " << i;
      ++painted;
    } else if (p.x() < -0.2) {
      EXPECT_NEAR(p.norm(), r0, 1e-9) << "point " << i;
      ++bare;
    }
  }
  EXPECT_GT(painted, 50);
  EXPECT_GT(bare, 50);
}
