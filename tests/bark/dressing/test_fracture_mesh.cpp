// Dressing into a mesh: fracture polygons are simple and closed, the constrained Delaunay
// triangulation covers the domain once, and mesh and map agree.
#include <gtest/gtest.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
// GCC 12 flags CGAL's own simplicity sweep (Polygon_2_algorithms_impl.h) with a false
// maybe-uninitialized warning; nothing of ours is involved.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#include <CGAL/Polygon_2.h>

#include <cmath>

#include "bark/dressing/fracture_mesh.h"
#include "bark/strips/strip_model.h"
#include "tests/support/strip_helpers.h"

using namespace phellem::bark;

namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;

// A field with two elliptic "fractures", one of them across the seam x = 0.
FractureField ellipses(int W, int H) {
  FractureField f;
  f.width = W;
  f.height = H;
  f.length = 1;
  f.opening.assign(size_t(W) * H, 0);
  f.depth.assign(size_t(W) * H, 0);
  for (int y = 0; y < H; ++y)
    for (int x = 0; x < W; ++x) {
      const double cx[2] = {0.3 * W, 0.0}, cy[2] = {0.5 * H, 0.3 * H};
      float o = 0;
      for (int e = 0; e < 2; ++e) {
        double dx = x + 0.5 - cx[e];
        dx -= W * std::round(dx / W);
        const double r = std::hypot(dx / (0.08 * W), (y + 0.5 - cy[e]) / (0.25 * H));
        o = std::max(o, float(std::clamp(1.5 - r, 0.0, 1.0)));
      }
      f.opening[f.index(x, y)] = o;
      f.depth[f.index(x, y)] = 0.01f * o;
    }
  return f;
}

FractureField simulated(int W, int H) {
  const StripParams p = phellem::test::quick_strip_params(150, 1.005);
  StripModel m(flat_domain(0.4, 0.4, p), p);
  for (int i = 0; i < p.steps; ++i) m.step();
  DepthProfile d;
  return rasterize(m, W, H, d);
}

void expect_closed_and_simple(const std::vector<std::vector<Eigen::Vector2d>>& loops, int W) {
  int checked = 0;
  for (const auto& loop : loops) {
    ASSERT_GE(loop.size(), 3u);
    bool seam = false;
    for (size_t k = 0; k < loop.size(); ++k) {
      const Eigen::Vector2d d = loop[(k + 1) % loop.size()] - loop[k];
      // Closed: consecutive points (last to first included) are neighbours on the lattice.
      const double dx = std::abs(d.x()) > 0.5 * W ? W - std::abs(d.x()) : std::abs(d.x());
      EXPECT_LE(std::hypot(dx, d.y()), 1.5);
      seam = seam || std::abs(d.x()) > 0.5 * W;
    }
    std::vector<K::Point_2> pts;
    for (const auto& p : loop) pts.emplace_back(seam && p.x() < 0.5 * W ? p.x() + W : p.x(), p.y());
    EXPECT_TRUE(CGAL::is_simple_2(pts.begin(), pts.end(), K()));
    ++checked;
  }
  EXPECT_GT(checked, 0);
}

void expect_covering_and_agreeing(const FractureField& f, const FractureMesh& m, double min_agreement) {
  // Covers [0, W] × [0, H] exactly once: all triangles counter-clockwise, areas sum to W·H.
  double area = 0;
  for (const auto& t : m.triangles) {
    const Eigen::Vector2d a = m.param[t[0]], b = m.param[t[1]], c = m.param[t[2]];
    const double a2 = (b - a).x() * (c - a).y() - (b - a).y() * (c - a).x();
    EXPECT_GT(a2, 0);
    area += 0.5 * a2;
  }
  EXPECT_NEAR(area, double(f.width) * f.height, 1e-6 * f.width * f.height);
  // Mesh ↔ map: the triangle under each pixel centre is a fracture triangle iff the pixel is.
  std::vector<int> owner(size_t(f.width) * f.height, -1);
  for (size_t ti = 0; ti < m.triangles.size(); ++ti) {
    const auto& t = m.triangles[ti];
    const Eigen::Vector2d a = m.param[t[0]], b = m.param[t[1]], c = m.param[t[2]];
    const int x0 = int(std::floor(std::min({a.x(), b.x(), c.x()}))), x1 = int(std::ceil(std::max({a.x(), b.x(), c.x()})));
    const int y0 = int(std::floor(std::min({a.y(), b.y(), c.y()}))), y1 = int(std::ceil(std::max({a.y(), b.y(), c.y()})));
    for (int y = std::max(0, y0); y < std::min(f.height, y1 + 1); ++y)
      for (int x = std::max(0, x0); x < std::min(f.width, x1 + 1); ++x) {
        const Eigen::Vector2d p(x + 0.5, y + 0.5);
        auto edge = [&](const Eigen::Vector2d& u, const Eigen::Vector2d& v) {
          return (v - u).x() * (p - u).y() - (v - u).y() * (p - u).x();
        };
        if (edge(a, b) >= 0 && edge(b, c) >= 0 && edge(c, a) >= 0) owner[f.index(x, y)] = int(ti);
      }
  }
  size_t agree = 0;
  for (size_t p = 0; p < owner.size(); ++p) {
    ASSERT_GE(owner[p], 0) << "pixel " << p << " in no triangle";
    agree += (f.opening[p] > 0.5f) == (m.fracture[size_t(owner[p])] != 0);
  }
  EXPECT_GE(double(agree) / double(owner.size()), min_agreement);
}

}  // namespace

TEST(FractureMesh, ContoursOfEllipsesAreTwoSimpleClosedPolygonsAcrossTheSeam) {
  const FractureField f = ellipses(64, 48);
  const auto loops = contour_loops(f.opening, f.width, f.height, 0.5f);
  EXPECT_EQ(loops.size(), 2u);
  expect_closed_and_simple(loops, f.width);
}

TEST(FractureMesh, TriangulationCoversTheDomainAndAgreesWithTheMap) {
  const FractureField f = ellipses(64, 48);
  const FractureMesh m = mesh_fracture_field(f, 0.01);
  expect_covering_and_agreeing(f, m, 0.99);
  // Seam: every vertex on x = 0 has a twin at x = W (the cylinder closes without a crack).
  std::vector<double> left, right;
  for (const auto& p : m.param) {
    if (p.x() == 0) left.push_back(p.y());
    if (p.x() == f.width) right.push_back(p.y());
  }
  std::sort(left.begin(), left.end());
  std::sort(right.begin(), right.end());
  EXPECT_EQ(left, right);
}

TEST(FractureMesh, SimulatedFieldMeshesIntoSimplePolygonsAndAgreeingTriangles) {
  const FractureField f = simulated(96, 96);
  const FractureMesh m = mesh_fracture_field(f, DepthProfile{}.max_depth);
  ASSERT_GT(m.silhouettes.size(), 3u);
  expect_closed_and_simple(m.silhouettes, f.width);
  expect_covering_and_agreeing(f, m, 0.97);
}
#pragma GCC diagnostic pop

// Bark with no open fracture (a young trunk: nothing reaches half opening) still meshes, all
// epidermis. CGAL's insert_constraints(points, indices) inserts nothing when there are no
// constraints: `simulate` wrote an empty .glb for a 100-step furrowed trunk.
TEST(FractureMesh, BarkWithoutOpenFracturesMeshesAsWholeEpidermis) {
  FractureField f = ellipses(64, 48);
  for (float& o : f.opening) o *= 0.3f;  // at most 0.3 open: no contour at 0.5
  for (float& d : f.depth) d *= 0.01f;   // and no depth level reached: no constraint at all
  const FractureMesh m = mesh_fracture_field(f, 0.01);
  EXPECT_TRUE(m.silhouettes.empty());
  ASSERT_FALSE(m.triangles.empty());
  double area = 0;
  for (size_t t = 0; t < m.triangles.size(); ++t) {
    const Eigen::Vector2d a = m.param[m.triangles[t][0]], b = m.param[m.triangles[t][1]], c = m.param[m.triangles[t][2]];
    area += 0.5 * std::abs((b - a).x() * (c - a).y() - (b - a).y() * (c - a).x());
    EXPECT_EQ(m.fracture[t], 0);
  }
  EXPECT_NEAR(area, 64.0 * 48.0, 1e-6);
}
