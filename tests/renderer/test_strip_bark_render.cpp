// Strip bark on whole trees: propagation across branch junctions (Figure 20), the BarkSurface
// hand-off, and the displaced render agreeing with the fracture field.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "bark/dressing/field_bark_surface.h"
#include "bark/strips/tree_bark.h"
#include "tests/support/render_helpers.h"
#include "tests/support/strip_helpers.h"

using namespace phellem;
using namespace phellem::bark;

namespace {

StripParams junction_params() { return test::quick_strip_params(200, 1.006); }

// A vertical trunk and one branch leaving it at half height, 50° from the axis.
std::vector<TreeCylinder> trunk_and_branch() {
  auto trunk = std::make_shared<GeneralizedCylinder>(std::vector<Eigen::Vector3d>{{0, 0, 0}, {0, 1.2, 0}},
                                                     std::vector<double>{0.12}, Eigen::Vector3d::UnitX());
  const double a = 50 * M_PI / 180;
  const Eigen::Vector3d base = trunk->axis_point(0.5), dir(std::sin(a), std::cos(a), 0);
  auto branch = std::make_shared<GeneralizedCylinder>(std::vector<Eigen::Vector3d>{base, base + 0.6 * dir},
                                                      std::vector<double>{0.06}, Eigen::Vector3d::UnitY());
  return {{trunk, -1, 0}, {branch, 0, 0.5}};
}

}  // namespace

TEST(TreeStripBark, FracturesContinueIntoTheChildBranchAtTheSamePoint) {
  TreeStripBark tree(trunk_and_branch(), junction_params());
  tree.run();
  int into_child = 0, into_parent = 0;
  for (const JunctionCrossing& c : tree.crossings()) {
    // The new fracture starts where the tip was: within the strips' discretization.
    EXPECT_LT((c.at_from - c.at_to).norm(), 3 * 0.01) << "crossing at step " << c.step << " " << c.from << "->" << c.to << " "
                                                      << c.at_from.transpose() << " / " << c.at_to.transpose();
    (c.to == 1 ? into_child : into_parent) += 1;
  }
  EXPECT_GT(into_child, 0);
  // Every arrival started a fracture in the child, except where one was already there.
  EXPECT_GT(tree.model(1).stats().arrived, 0);
  EXPECT_LE(tree.model(1).stats().arrived, into_child);
  EXPECT_LE(tree.model(0).stats().arrived, into_parent);
}

TEST(TreeStripBark, WithoutAJunctionNothingCrosses) {
  auto cyl = trunk_and_branch();
  cyl[1].parent = -1;  // two unrelated cylinders
  TreeStripBark tree(cyl, junction_params());
  tree.run();
  EXPECT_TRUE(tree.crossings().empty());
  EXPECT_EQ(tree.model(1).stats().arrived, 0);
}

TEST(FieldBarkSurface, SamplesTexelCentresExactlyAndWrapsAroundTheTrunk) {
  FractureField f;
  f.width = 4;
  f.height = 3;
  f.length = 2;
  const size_t n = 12;
  f.opening.resize(n);
  f.depth.resize(n);
  f.color.resize(3 * n);
  for (size_t p = 0; p < n; ++p) {
    f.depth[p] = 0.001f * float(p);
    f.opening[p] = float(p % 2);
    for (int c = 0; c < 3; ++c) f.color[3 * p + c] = 0.1f * float(c + 1);
  }
  const FieldBarkSurface s(f, 0.02);
  for (int y = 0; y < 3; ++y)
    for (int x = 0; x < 4; ++x) {
      const double u = (x + 0.5) / 4, v = (y + 0.5) / 3;
      EXPECT_FLOAT_EQ(s.depth(u, v), f.depth[f.index(x, y)]);
      EXPECT_FLOAT_EQ(s.shade_at(u, v).mask, f.opening[f.index(x, y)]);
      EXPECT_FLOAT_EQ(s.shade_at(u, v).depth, f.depth[f.index(x, y)] / 0.02f);
    }
  // Halfway between the last and the first column: the average of both (no seam at θ = 0).
  EXPECT_FLOAT_EQ(s.depth(0.0, 0.5), 0.5f * (f.depth[f.index(3, 1)] + f.depth[f.index(0, 1)]));
  EXPECT_FLOAT_EQ(s.depth(1.0, 0.5), s.depth(0.0, 0.5));
  EXPECT_FLOAT_EQ(s.shade_at(0.3, 0.4).albedo.y(), 0.2f);
}

TEST(StripBarkRender, DisplacementFollowsTheFieldDepthAndFillsTheCrackAov) {
  // A straight trunk of radius R seen from the side: every hit lies at distance
  // R − depth from the axis, and the crack AOV reports that depth (normalized by max_depth).
  const double R = 0.1, max_depth = 0.02;
  const std::string scene = R"({
    "camera": {"position": [0, 0.3, 0.9], "look_at": [0, 0.3, 0], "fov_deg": 16},
    "render": {"resolution": [96, 96], "spp": 4, "max_depth": 2, "seed": 3},
    "lights": [{"type": "environment", "color": [1, 1, 1]}],
    "materials": {"bark": {"type": "diffuse", "base_color": [0.5, 0.5, 0.5]}},
    "objects": [{"type": "tree", "material": "bark", "axis": [[0, 0, 0], [0, 0.6, 0]], "radius": [0.1],
                 "bark": {"model": "strips", "preset": "furrowed", "steps": 300, "strip_width": 0.006,
                          "depth": {"profile": "u", "max_depth": 0.02, "depth_per_width": 1.5}}}]
  })";
  const RenderResult r = test::render_json(scene);
  const Film& f = r.film;
  std::vector<double> err, err_deep;
  int cracked = 0, deep = 0;
  for (int y = 1; y < f.height - 1; ++y)
    for (int x = 1; x < f.width - 1; ++x) {
      if (!test::interior_pixel(f, x, y)) continue;  // keep silhouette pixels (partly sky) out
      const size_t p = size_t(y) * f.width + x;
      const double r_hit = std::hypot(f.position[3 * p], f.position[3 * p + 2]);
      const double mask = f.crack[2 * p], depth = f.crack[2 * p + 1];
      cracked += mask > 0.5;
      deep += depth > 0.25;  // at least 5 mm below the epidermis
      // Pixels straddling a crack lip average hits at different depths linearly in both.
      err.push_back(std::abs(r_hit - (R - depth * max_depth)));
      // Undisplaced, these would be off by depth · max_depth ≥ 5 mm.
      if (depth > 0.25) err_deep.push_back(err.back());
    }
  ASSERT_GT(err.size(), 1000u);
  EXPECT_GT(cracked, 20);
  EXPECT_GT(deep, 5);
  std::sort(err.begin(), err.end());
  EXPECT_LT(err[err.size() / 2], 2e-4) << "median |r − (R − depth)| (m)";
  EXPECT_LT(err[err.size() * 95 / 100], 1.5e-3) << "95th percentile (m)";
  std::sort(err_deep.begin(), err_deep.end());
  EXPECT_LT(err_deep[err_deep.size() / 2], 1e-3) << "median over pixels deeper than 5 mm (m)";
}
