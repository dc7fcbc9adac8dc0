// Keeping the growth volume usable over large growth (issue 24): free vertices pressed
// against the interface are removed (free_vertex_removal.h), the volume is tetrahedralized
// again when the local repair no longer keeps moves from blocking (volume_remesh.h, TetGen in
// a child process: tetgen_process.h), and so a jittered log grown to twice its radius stays a
// log instead of breaking into pits and blobs.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "bark/geometry/procedural_meshes.h"
#include "bark/growth/cambial_growth.h"
#include "bark/growth/free_vertex_removal.h"
#include "bark/growth/interface_motion.h"
#include "bark/growth/interface_refinement.h"
#include "bark/growth/volume_remesh.h"
#include "tests/support/closed_surface.h"

using namespace phellem;
using namespace phellem::bark;

namespace {

std::vector<std::array<uint32_t, 3>> rotated(std::vector<std::array<uint32_t, 3>> f) {
  for (auto& t : f) std::rotate(t.begin(), std::min_element(t.begin(), t.end()), t.end());
  std::sort(f.begin(), f.end());
  return f;
}

// An icosphere's complex grown four steps with splits and no repair: squashed outside, new
// interface points from the splits, UVs and source vertices on every interface point.
TetComplex grown_sphere() {
  TriMesh s = icosphere(3, 0.5);
  s.uvs.clear();
  for (const auto& p : s.positions) s.uvs.push_back(Eigen::Vector2d(p.x(), p.y()));
  TetComplex c = tetrahedralize_surface(s, TetSettings{}, "s.json", "/objects/0");
  GrowthFunction g;
  g.weibull_c = 1;
  g.thickness = 1;
  double band = 0;
  for (const auto& e : interface_edges(c)) band = std::max(band, (c.points[e[0]] - c.points[e[1]]).norm());
  // Four steps wear the outside next to the interface (0.27 % of its tetrahedra below quality
  // 0.1, the worst 0.037). Two did before the motion retried its blocked moves.
  for (int k = 0; k < 4; ++k) {
    advance_interface(c, g, 0.05 * k, 0.05 * (k + 1));
    split_long_interface_edges(c, band);
  }
  return c;
}

double enclosed_volume(const TetComplex& c) {
  double v = 0;
  for (const auto& f : c.interface_faces()) v += c.points[f[0]].dot(c.points[f[1]].cross(c.points[f[2]])) / 6;
  return v;
}

}  // namespace

TEST(VolumeRemesh, TheInterfaceAndItsPointsStayAsTheyWereAndTheVolumeIsWellShapedAgain) {
  TetComplex c = grown_sphere();
  const TetComplex before = c;
  const auto faces = c.interface_faces();
  ASSERT_TRUE(retetrahedralize(c, {}, TetSettings{}, "s.json", "/objects/0"));
  EXPECT_EQ(rotated(c.interface_faces()), rotated(faces));
  EXPECT_EQ(c.first_inverted(), -1);
  EXPECT_TRUE(test::closed_manifold(c.interface_faces()));
  for (uint32_t p = 0; p < before.points.size(); ++p) {
    if (!before.on_interface[p]) continue;
    ASSERT_EQ(c.on_interface[p], 1) << p;
    EXPECT_EQ(c.points[p], before.points[p]) << p;
    EXPECT_EQ(c.uv[p], before.uv[p]) << p;
    EXPECT_EQ(c.source_vertex[p], before.source_vertex[p]) << p;
  }
  // Every point the tetrahedra use that is not an interface point is TetGen's new one.
  for (const auto& t : c.tets)
    for (uint32_t p : t) {
      if (!c.on_interface[p]) {
        EXPECT_EQ(c.source_vertex[p], -1);
      }
    }
  EXPECT_NEAR(c.volume(TetComplex::kInside), enclosed_volume(before), 1e-9);
  // The squashed outside next to the interface is made anew: far fewer poor tetrahedra there
  // (quality below 0.1), and the worst no worse.
  auto poor_share = [](const TetComplex& x) {
    long poor = 0, all = 0;
    for (size_t t = 0; t < x.tets.size(); ++t) {
      bool near = false;
      for (uint32_t p : x.tets[t]) near = near || x.on_interface[p];
      if (!near || x.label[t] != TetComplex::kOutside) continue;
      ++all;
      poor += tet_quality(x, x.tets[t]) < 0.1;
    }
    return double(poor) / double(all);
  };
  auto worst_near = [](const TetComplex& x) {
    double q = 1e300;
    for (size_t t = 0; t < x.tets.size(); ++t) {
      bool near = false;
      for (uint32_t p : x.tets[t]) near = near || x.on_interface[p];
      if (near && x.label[t] == TetComplex::kOutside) q = std::min(q, tet_quality(x, x.tets[t]));
    }
    return q;
  };
  // (Measured: 0.29 % of them below 0.1 before, 0.009 % after; the worst 0.032 → 0.035.)
  EXPECT_GT(poor_share(before), 10 * poor_share(c));
  EXPECT_GE(worst_near(c), worst_near(before));
}

TEST(VolumeRemesh, AnInterfaceFoldedOntoItselfIsLeftAsItWas) {
  TetComplex c = grown_sphere();
  // One interface point moved onto the middle of a triangle on the far side of the sphere.
  const auto faces = c.interface_faces();
  uint32_t p = 0;
  while (!c.on_interface[p]) ++p;
  const Eigen::Vector3d dir = c.points[p].normalized();
  const auto far = *std::min_element(faces.begin(), faces.end(), [&](const auto& a, const auto& b) {
    return c.points[a[0]].dot(dir) < c.points[b[0]].dot(dir);
  });
  c.points[p] = (c.points[far[0]] + c.points[far[1]] + c.points[far[2]]) / 3;
  const TetComplex folded = c;
  EXPECT_FALSE(retetrahedralize(c, {}, TetSettings{}, "s.json", "/objects/0"));
  EXPECT_EQ(c.tets, folded.tets);
  EXPECT_EQ(c.points, folded.points);
  EXPECT_EQ(c.label, folded.label);
}

TEST(FreeVertexRemoval, AFreeVertexPressedAgainstTheInterfaceGoesAndTheStarKeepsItsVolume) {
  TetComplex c = grown_sphere();
  TetAdjacency adj(c);
  const auto faces = c.interface_faces();
  const double inside = c.volume(TetComplex::kInside), outside = c.volume(TetComplex::kOutside);
  // The free point next to the interface with the worst tetrahedron.
  uint32_t w = 0;
  double worst = 1e300;
  for (uint32_t p = 0; p < c.points.size(); ++p) {
    if (c.on_interface[p] || c.on_box[p] || adj.unused(p)) continue;
    bool near = false;
    double q = 1e300;
    for (uint32_t t : adj.around(p)) {
      q = std::min(q, tet_quality(c, c.tets[t]));
      for (uint32_t x : c.tets[t]) near = near || c.on_interface[x];
    }
    if (near && q < worst) {
      worst = q;
      w = p;
    }
  }
  ASSERT_LT(worst, 0.05);
  // Its neighbours' tetrahedra before, to check the worst quality rises.
  FlipStats st;
  ASSERT_TRUE(remove_free_vertex(c, adj, w, Probe{}, st));
  EXPECT_EQ(st.removed, 1);
  EXPECT_TRUE(adj.unused(w));
  for (const auto& t : c.tets) EXPECT_EQ(std::count(t.begin(), t.end(), w), 0);
  EXPECT_EQ(c.first_inverted(), -1);
  EXPECT_EQ(rotated(c.interface_faces()), rotated(faces));
  EXPECT_NEAR(c.volume(TetComplex::kInside), inside, 1e-12);
  EXPECT_NEAR(c.volume(TetComplex::kOutside), outside, 1e-9);
  // Interface and box points never go.
  uint32_t on = 0;
  while (!c.on_interface[on]) ++on;
  EXPECT_FALSE(remove_free_vertex(c, adj, on, Probe{}, st));
  for (uint32_t t : adj.around(on)) EXPECT_NE(std::find(c.tets[t].begin(), c.tets[t].end(), on), c.tets[t].end());
}

// A jittered log grown with nearly uniform speed to twice its radius: the middle of every
// interface vertex within a tenth of the band's lower bound of R₀ + thickening, and every
// normal within 3° of radial. (Without re-tetrahedralizing, measured: worst lag 2.7 mm and
// 5°; before the free-vertex removal and the lattice, 70 mm and the surface in blobs.)
TEST(CambialGrowth, AJitteredLogGrownToTwiceItsRadiusStaysALog) {
  const double r0 = 0.08, height = 0.4;
  const TriMesh log = log_mesh(r0, height, 40, int(std::lround(40 * height / (2 * M_PI * r0))), 0.2, 7);
  CambialGrowthSettings s;
  s.function.weibull_c = 1;
  s.function.age_scale = 10;
  s.function.thickness = float(r0 / (1 - std::exp(-0.1)));
  s.age_start = 0;
  s.age_end = 1;
  s.steps = 40;
  s.ring_interval = 0;
  CambialGrowth g(log, {}, s, "s.json", "/objects/0");
  while (g.step()) {
  }
  EXPECT_GT(g.stats().remeshes, 0);
  const double r = r0 + s.function.cumulative(1);
  const GrowthSurface surface = extract_interface(g.complex());
  const TriMesh& m = surface.mesh;
  std::vector<Eigen::Vector3d> n(m.positions.size(), Eigen::Vector3d::Zero());
  for (const auto& t : m.triangles) {
    const Eigen::Vector3d a = (m.positions[t[1]] - m.positions[t[0]]).cross(m.positions[t[2]] - m.positions[t[0]]);
    for (uint32_t v : t) n[v] += a;
  }
  long middle = 0;
  for (size_t i = 0; i < m.positions.size(); ++i) {
    const Eigen::Vector3d& p = m.positions[i];
    if (p.y() < 0.3 * height || p.y() > 0.7 * height) continue;
    ++middle;
    EXPECT_NEAR(std::hypot(p.x(), p.z()), r, 0.1 * g.settings().edge_min) << "vertex " << i << " at y " << p.y();
    const Eigen::Vector3d radial = Eigen::Vector3d(p.x(), 0, p.z()).normalized();
    EXPECT_GT(n[i].normalized().dot(radial), std::cos(3 * M_PI / 180)) << "vertex " << i << " at y " << p.y();
  }
  EXPECT_GT(middle, 500);
}
