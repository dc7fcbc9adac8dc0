// The cambium's motion, Eq. (1) of Kratt et al. (bark/growth/interface_motion.h): a sphere
// grown at constant speed reaches radius R₀ + ∫s dt everywhere and the matching volume, no
// tetrahedron ever inverts, and eccentric growth favours its side by (1 + e)/(1 − e).
#include <gtest/gtest.h>

#include "bark/geometry/procedural_meshes.h"
#include "bark/growth/interface_motion.h"
#include "bark/growth/growth_rings.h"
#include "bark/growth/interface_refinement.h"
#include "tests/support/closed_surface.h"

#include <map>

using namespace phellem;
using namespace phellem::bark;

namespace {

// c = 1: the Weibull density is exp(−t), its cumulative 1 − exp(−t); over a short span of
// ages the speed is nearly constant, and the total is exact whatever the steps.
GrowthFunction growth_of(double thickness) {
  GrowthFunction g;
  g.weibull_c = 1;
  g.thickness = float(thickness);
  return g;
}

double enclosed_volume(const TetComplex& c) { return c.volume(1); }

}  // namespace

TEST(InterfaceMotion, ASphereGrowsToItsRadiusPlusTheThickeningEverywhere) {
  const double r0 = 0.5;
  TetComplex c = tetrahedralize_surface(icosphere(3, r0), TetSettings{}, "s.json", "/objects/0");
  const double v0 = enclosed_volume(c);
  const GrowthFunction g = growth_of(1.0);
  const double t_end = 0.08;  // total thickening 1 − exp(−0.08) = 0.0769 m
  const int steps = 8;
  for (int k = 0; k < steps; ++k) {
    const InterfaceStepStats st = advance_interface(c, g, t_end * k / steps, t_end * (k + 1) / steps);
    EXPECT_EQ(c.first_inverted(), -1) << "step " << k;
    EXPECT_EQ(st.clamped, 0) << "step " << k;
  }
  const double grown = g.cumulative(t_end);
  // Every interface vertex at R₀ + ∫s dt (within a hundredth of an edge: icosphere(3) edges
  // are about 0.08 m; the vertex normals of a sphere are radial).
  double worst = 0;
  for (size_t i = 0; i < c.points.size(); ++i)
    if (c.on_interface[i]) worst = std::max(worst, std::abs(c.points[i].norm() - (r0 + grown)));
  EXPECT_LT(worst, 1e-3);
  // The volume scales as the radius cubed (the polyhedron grows homothetically).
  EXPECT_NEAR(enclosed_volume(c) / v0, std::pow((r0 + grown) / r0, 3), 0.01);
}

TEST(InterfaceMotion, EccentricGrowthFavoursItsSide) {
  TetComplex c = tetrahedralize_surface(icosphere(3, 0.5), TetSettings{}, "s.json", "/objects/0");
  GrowthFunction g = growth_of(1.0);
  g.eccentricity = 0.4f;
  g.eccentricity_direction = Vec3f(1, 0, 0);
  for (int k = 0; k < 5; ++k) advance_interface(c, g, 0.01 * k, 0.01 * (k + 1));
  EXPECT_EQ(c.first_inverted(), -1);
  double plus = 0, minus = 0;
  for (size_t i = 0; i < c.points.size(); ++i)
    if (c.on_interface[i]) {
      plus = std::max(plus, c.points[i].x());
      minus = std::max(minus, -c.points[i].x());
    }
  const double e = double(0.4f);
  EXPECT_NEAR((plus - 0.5) / (minus - 0.5), (1 + e) / (1 - e), 0.05 * (1 + e) / (1 - e));
}

TEST(InterfaceMotion, AMoveThatWouldInvertATetrahedronIsClampedNotApplied) {
  TetComplex c = tetrahedralize_surface(icosphere(2, 0.5), TetSettings{}, "s.json", "/objects/0");
  // Growth far beyond the room the padding gives (the box is 0.5 m away): vertices run into
  // the fixed box's tetrahedra and must stop, never invert one.
  // (The DSC's retessellation lets a blocked vertex go on part of the way, so a stopped move
  // shows as shortened as often as clamped.)
  const GrowthFunction g = growth_of(3.0);
  long stopped = 0;
  for (int k = 0; k < 4; ++k) {
    const InterfaceStepStats st = advance_interface(c, g, 0.5 * k, 0.5 * (k + 1));
    stopped += st.clamped + st.shortened;
    ASSERT_EQ(c.first_inverted(), -1) << "step " << k;
  }
  EXPECT_GT(stopped, 0);
  for (size_t i = 0; i < c.points.size(); ++i)
    if (c.on_interface[i]) {
      EXPECT_LT(c.points[i].cwiseAbs().maxCoeff(), 1.0) << "inside the box at ±1 m";
    }
}

TEST(InterfaceMotion, ABlockedMoveOwesItsRestAndCatchesUpAtMostAtItsOwnRate) {
  const double r0 = 0.5;
  TetComplex c = tetrahedralize_surface(icosphere(3, r0), TetSettings{}, "s.json", "/objects/0");
  TetAdjacency adj(c);
  const GrowthFunction g = growth_of(1.0);
  const double d = g.cumulative(0.01);  // this step's thickening, about 10 mm (edges about 80 mm)
  std::vector<uint32_t> interface;
  for (uint32_t i = 0; i < c.points.size(); ++i)
    if (c.on_interface[i]) interface.push_back(i);
  ASSERT_GT(interface.size(), 10u);
  // A sphere's vertex normals are radial: each vertex goes out by what it moves.
  const uint32_t part = interface[0], many = interface[5], against = interface[9];
  std::vector<double> owed(c.points.size(), 0.0);
  owed[part] = 0.4 * d;   // repaid whole this step
  owed[many] = 3.0 * d;   // repaid at most d a step
  owed[against] = -0.4 * d;  // against the growth: never owed, dropped
  advance_interface(c, adj, interface_faces(c, adj), g, 0.0, 0.01, &owed);
  EXPECT_EQ(c.first_inverted(), -1);
  ASSERT_EQ(owed.size(), c.points.size());
  EXPECT_NEAR(c.points[part].norm(), r0 + 1.4 * d, 1e-9);
  EXPECT_NEAR(c.points[many].norm(), r0 + 2.0 * d, 1e-9);
  EXPECT_NEAR(c.points[against].norm(), r0 + d, 1e-9);
  EXPECT_NEAR(c.points[interface[3]].norm(), r0 + d, 1e-9);
  EXPECT_NEAR(owed[part], 0.0, 1e-12);
  EXPECT_NEAR(owed[many], 2.0 * d, 1e-12);
  EXPECT_EQ(owed[against], 0.0);
  // A move the box stops (growth far past the padding) owes what it did not go.
  std::vector<double> left(c.points.size(), 0.0);
  const GrowthFunction far = growth_of(3.0);
  long stopped = 0;
  for (int k = 0; k < 4; ++k) {
    const InterfaceStepStats st = advance_interface(c, adj, interface_faces(c, adj), far, 0.5 * k, 0.5 * (k + 1), &left);
    stopped += st.clamped + st.shortened;
  }
  ASSERT_GT(stopped, 0);
  double most = 0;
  for (uint32_t v : interface) {
    EXPECT_GE(left[v], 0.0);
    most = std::max(most, left[v]);
  }
  EXPECT_GT(most, 0.05) << "a stopped vertex owes the rest of its step";
  EXPECT_LE(most, 10 * far.thickening(1.5, 2.0, Vec3f::Zero(), Vec3f::UnitX()) + 1e-12) << "at most ten steps' worth";
}

TEST(InterfaceMotion, TheUpkeepRunsOnceForAsManyStepsAsFitInItsReachAndTheSphereStillGrowsTrue) {
  const double r0 = 0.5;
  TetComplex c = tetrahedralize_surface(icosphere(3, r0), TetSettings{}, "s.json", "/objects/0");
  TetAdjacency adj(c);
  const GrowthFunction g = growth_of(1.0);
  const double dt = 0.01;
  const double d = g.cumulative(dt);  // the first step's thickening; later ones are smaller
  // 3.5 steps' reach: the first carry covers 3 steps (it and the next two), the fourth step's
  // thickening is e^−0.03 of the first, so floor(3.5 e^0.03) = 3 again.
  VolumeUpkeep upkeep;
  upkeep.reach = 3.5 * d;
  const int steps = 8;
  const bool expected[steps] = {true, false, false, true, false, false, true, false};
  for (int k = 0; k < steps; ++k) {
    const InterfaceStepStats st = advance_interface(c, adj, interface_faces(c, adj), g, dt * k, dt * (k + 1), nullptr, &upkeep);
    EXPECT_EQ(st.upkeep, expected[k]) << "step " << k;
    if (st.upkeep) {
      EXPECT_GT(st.smoothed, 0) << "step " << k;
    } else {
      EXPECT_EQ(st.smoothed, 0) << "step " << k;
    }
    ASSERT_EQ(c.first_inverted(), -1) << "step " << k;
    EXPECT_EQ(st.clamped + st.shortened, 0) << "step " << k;
  }
  // Every interface vertex at R₀ + ∫s dt, as with the upkeep every step.
  const double grown = g.cumulative(dt * steps);
  double worst = 0;
  for (size_t i = 0; i < c.points.size(); ++i)
    if (c.on_interface[i]) worst = std::max(worst, std::abs(c.points[i].norm() - (r0 + grown)));
  EXPECT_LT(worst, 1e-3);
  // A reach shorter than a step's thickening: the upkeep every step.
  VolumeUpkeep short_reach;
  short_reach.reach = 0.5 * d;
  for (int k = steps; k < steps + 3; ++k)
    EXPECT_TRUE(advance_interface(c, adj, interface_faces(c, adj), g, dt * k, dt * (k + 1), nullptr, &short_reach).upkeep);
}

TEST(InterfaceRefinement, SplitsKeepTheGrowingSphereFineClosedAndPositive) {
  const double r0 = 0.3;
  TetComplex c = tetrahedralize_surface(icosphere(2, r0), TetSettings{}, "s.json", "/objects/0");
  double max0 = 0;
  for (const auto& e : interface_edges(c)) max0 = std::max(max0, (c.points[e[0]] - c.points[e[1]]).norm());
  const GrowthFunction g = growth_of(1.0);
  long splits = 0, shortened = 0;
  for (int k = 0; k < 10; ++k) {  // to about 0.48 m: edges would stretch by 1.6 without splits
    const InterfaceStepStats st = advance_interface(c, g, 0.02 * k, 0.02 * (k + 1));
    shortened += st.shortened + st.clamped;
    splits += split_long_interface_edges(c, max0);
    ASSERT_EQ(c.first_inverted(), -1) << "step " << k;
    ASSERT_TRUE(phellem::test::closed_manifold(c.interface_faces())) << "step " << k;
  }
  EXPECT_GT(splits, 100);
  for (const auto& e : interface_edges(c)) EXPECT_LE((c.points[e[0]] - c.points[e[1]]).norm(), max0 + 1e-12);
  // Still a sphere, roughly: every interface vertex near the grown radius. Not yet tight: a
  // few moves per step are shortened or clamped (about 10 of 600) by outside tetrahedra whose corners are
  // all on the interface, which the flips of deformable simplicial complexes (not written
  // yet) would remove; those vertices lag. Measured: 0.031 m against an edge bound of 0.097.
  const double r = r0 + g.cumulative(0.2);
  double worst = 0;
  for (size_t i = 0; i < c.points.size(); ++i)
    if (c.on_interface[i]) worst = std::max(worst, std::abs(c.points[i].norm() - r));
  EXPECT_LT(worst, 0.4 * max0) << "edge bound " << max0 << ", " << shortened << " moves shortened or clamped";
}

TEST(GrowthRings, RingsOfAGrowingSphereNestInEveryCrossSection) {
  TetComplex c = tetrahedralize_surface(icosphere(3, 0.4), TetSettings{}, "s.json", "/objects/0");
  const GrowthFunction g = growth_of(1.0);
  std::vector<GrowthRing> rings{record_ring(c, 0)};
  for (int k = 1; k <= 6; ++k) {
    advance_interface(c, g, 0.01 * (k - 1), 0.01 * k);
    if (k % 2 == 0) rings.push_back(record_ring(c, k));  // a ring every 2 steps
  }
  ASSERT_EQ(rings.size(), 4u);
  EXPECT_EQ(rings.back().faces.size(), rings.front().faces.size());
  for (const Eigen::Vector3d& n : {Eigen::Vector3d(0, 1, 0), Eigen::Vector3d(1, 1, 0).normalized()}) {
    // Each ring's trace is a closed polygon around the centre; ring k's nearest point lies
    // beyond ring k − 1's farthest: they nest and never intersect.
    double previous_outer = 0;
    for (const auto& r : rings) {
      const auto segments = slice_ring(r, Eigen::Vector3d(0, 0.05, 0), n);
      ASSERT_GT(segments.size(), 20u);
      double inner = 1e9, outer = 0;
      for (const auto& s : segments)
        for (const auto& p : s) {
          const double radial = (p - Eigen::Vector3d(0, 0, 0)).norm();
          inner = std::min(inner, radial);
          outer = std::max(outer, radial);
        }
      EXPECT_GT(inner, previous_outer) << "ring at step " << r.step;
      previous_outer = outer;
    }
  }
}
