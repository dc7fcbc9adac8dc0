// The procedural branch junction (bark/geometry/branch_junction.h): once its UV seam copies
// are welded by position it is a closed, outward-oriented 2-manifold enclosing the union of
// its two cylinders, has about the triangles asked for, is the same from build to build, refuses
// parameters that make no junction by name, and grows.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <map>
#include <memory>
#include <set>
#include <stdexcept>
#include <tuple>

#include "bark/geometry/branch_junction.h"
#include "bark/growth/cambial_growth.h"
#include "tests/support/closed_surface.h"

using namespace phellem::bark;
using phellem::test::manifold_problem;
using phellem::test::signed_volume;

namespace {

constexpr double kPi = 3.141592653589793;

BranchJunctionParams small_junction(double angle_deg = 45, int triangles = 3000) {
  BranchJunctionParams p;
  p.radius = 0.1;
  p.height = 0.6;
  p.branch_radius = 0.05;
  p.branch_angle_deg = angle_deg;
  p.branch_length = 0.35;
  p.branch_height = 0.35;
  p.triangles = triangles;
  p.jitter = 0.3;
  p.seed = 5;
  return p;
}

}  // namespace

TEST(ProceduralBranchJunction, IsAClosedOutwardManifoldEnclosingTheUnionsVolume) {
  for (double angle : {90.0, 45.0, 30.0}) {
    BranchJunctionParams p = small_junction(angle);
    if (angle == 30.0) {  // its top leaves the trunk higher up, and it needs longer to get out
      p.branch_height = 0.2;
      p.branch_length = 0.45;
    }
    const TriMesh m = branch_junction_mesh(p);
    EXPECT_EQ(manifold_problem(m), "") << angle << "°";
    const double volume = signed_volume(m);
    const double trunk = kPi * p.radius * p.radius * p.height;
    const double branch = kPi * p.branch_radius * p.branch_radius * p.branch_length;
    EXPECT_GT(volume, trunk) << angle << "°";           // positive: outwards; more than the trunk alone
    EXPECT_LT(volume, trunk + branch) << angle << "°";  // less than both apart
    const double estimate = branch_junction_volume_estimate(p);
    EXPECT_NEAR(volume, estimate, 0.02 * estimate) << angle << "°";
  }
}

TEST(ProceduralBranchJunction, HasAboutTheTrianglesAskedFor) {
  // Within 10 % from a few thousand up; coarser, the cylinders keep at least 24 sides and the
  // count is rougher.
  for (const auto& [angle, n, within] :
       {std::tuple{45.0, 1500, 0.25}, {45.0, 3000, 0.1}, {90.0, 6000, 0.1}, {60.0, 12000, 0.1}}) {
    const TriMesh m = branch_junction_mesh(small_junction(angle, n));
    EXPECT_NEAR(double(m.triangles.size()), n, within * n) << angle << "°";
  }
}

TEST(ProceduralBranchJunction, UvsFollowEachPartWithoutSmearingAcrossTheSeam) {
  const BranchJunctionParams p = small_junction();
  const TriMesh m = branch_junction_mesh(p);
  ASSERT_EQ(m.uvs.size(), m.positions.size());
  for (const auto& t : m.triangles) {
    const double lo = std::min({m.uvs[t[0]].x(), m.uvs[t[1]].x(), m.uvs[t[2]].x()});
    const double hi = std::max({m.uvs[t[0]].x(), m.uvs[t[1]].x(), m.uvs[t[2]].x()});
    const Eigen::Vector3d c = (m.positions[t[0]] + m.positions[t[1]] + m.positions[t[2]]) / 3;
    // Faces at a cap's centre span every angle; elsewhere a face covers a small arc.
    const double a = p.branch_angle_deg * kPi / 180;
    const Eigen::Vector3d base(0, p.branch_height * p.height, 0), axis(std::sin(a), std::cos(a), 0);
    const bool near_axis =
        std::hypot(c.x(), c.z()) < 0.3 * p.radius || (c - base - (c - base).dot(axis) * axis).norm() < 0.3 * p.branch_radius;
    if (!near_axis) {
      EXPECT_LT(hi - lo, 0.25) << "face at " << c.transpose() << " u " << lo << " to " << hi;
    }
  }
  // v along the trunk is y / height.
  for (size_t i = 0; i < m.positions.size(); ++i) {
    const Eigen::Vector3d& x = m.positions[i];
    if (x.x() < -0.5 * p.radius && x.y() > 0.05 && x.y() < p.height - 0.05) {
      EXPECT_NEAR(m.uvs[i].y(), x.y() / p.height, 1e-9);
    }
  }
}

TEST(ProceduralBranchJunction, IsTheSameFromBuildToBuildWhateverTheHeap) {
  const BranchJunctionParams p = small_junction(60, 2000);
  const TriMesh first = branch_junction_mesh(p);
  std::vector<std::unique_ptr<std::vector<char>>> clutter;  // moves later allocations around
  for (int round = 0; round < 3; ++round) {
    for (size_t k = 0; k < 64; ++k) clutter.push_back(std::make_unique<std::vector<char>>(size_t(1000 * (k % 7 + 1)) << round));
    for (size_t k = 0; k < clutter.size(); k += 3) clutter[k].reset();
    const TriMesh again = branch_junction_mesh(p);
    ASSERT_EQ(again.positions, first.positions) << "round " << round;
    ASSERT_EQ(again.uvs, first.uvs) << "round " << round;
    ASSERT_EQ(again.triangles, first.triangles) << "round " << round;
  }
  BranchJunctionParams other = p;
  other.seed = 6;  // the jitter follows the seed
  EXPECT_NE(branch_junction_mesh(other).positions, first.positions);
}

TEST(ProceduralBranchJunction, ParametersThatMakeNoJunctionAreRefusedByName) {
  struct Case {
    void (*edit)(BranchJunctionParams&);
    std::string parameter;
  };
  const std::vector<Case> cases = {
      {[](BranchJunctionParams& p) { p.branch_radius = p.radius; }, "branch_radius"},
      {[](BranchJunctionParams& p) { p.branch_angle_deg = 10; }, "branch_angle_deg"},
      {[](BranchJunctionParams& p) { p.branch_angle_deg = 120; }, "branch_angle_deg"},
      {[](BranchJunctionParams& p) { p.branch_height = 0.95; }, "branch_height"},  // leaves through the top cap
      {[](BranchJunctionParams& p) { p.branch_height = 0.01; }, "branch_height"},  // base below the trunk
      {[](BranchJunctionParams& p) { p.branch_length = 0.12; }, "branch_length"},  // ends inside the trunk
      {[](BranchJunctionParams& p) { p.triangles = 100; }, "triangles"},
      {[](BranchJunctionParams& p) { p.jitter = 0.5; }, "jitter"},
  };
  EXPECT_FALSE(check_branch_junction(small_junction()).has_value());
  for (const Case& c : cases) {
    BranchJunctionParams p = small_junction();
    c.edit(p);
    const auto problem = check_branch_junction(p);
    ASSERT_TRUE(problem.has_value()) << c.parameter;
    EXPECT_EQ(problem->parameter, c.parameter) << problem->what;
    EXPECT_THROW(branch_junction_mesh(p), std::invalid_argument) << c.parameter;
  }
}

TEST(ProceduralBranchJunction, GrowsAStep) {
  const TriMesh m = branch_junction_mesh(small_junction(45, 1200));
  CambialGrowthSettings s;
  s.function.weibull_c = 1;
  s.function.age_scale = 1;
  s.function.thickness = 0.01f;
  s.age_end = 1;
  s.steps = 2;
  CambialGrowth g(m, {}, s, "junction.json", "/objects/0/growth");
  EXPECT_TRUE(g.step());
  const TriMesh grown = extract_interface(g.complex()).mesh;
  EXPECT_EQ(manifold_problem(grown), "");
  EXPECT_GT(signed_volume(grown), signed_volume(m));
}
