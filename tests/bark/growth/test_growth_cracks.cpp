// Cracks and stress through time (bark/growth/growth_cracks.h; Spicker 2014 ch. 5): the stress
// field carried by vertex identity (exactly on an unchanged mesh, plus the stretch's Green
// strain on a moved one), and on a growing log: the crack network of each step contains the
// previous one's, widths never decrease, the interface stays the stress mesh, and the volume
// stays valid.
#include <gtest/gtest.h>

#include <map>
#include <queue>
#include <set>

#include "bark/geometry/procedural_meshes.h"
#include "bark/growth/cambial_growth.h"
#include "bark/growth/growth_cracks.h"
#include "bark/growth/interface_caps.h"
#include "tests/support/closed_surface.h"

using namespace phellem;
using namespace phellem::bark;
using phellem::test::closed_manifold;

namespace {

StressParams bark_params(StressPattern pattern) {
  StressParams p;
  p.pattern = pattern;
  p.cracks_per_iteration = 4;
  p.alpha = 0.3;
  p.threshold = 0.5;
  p.seed = 9;
  return p;
}

// Whether a and b are joined by crack edges (breadth-first over `edges`).
bool joined(const std::set<std::pair<uint32_t, uint32_t>>& edges, uint32_t a, uint32_t b) {
  std::map<uint32_t, std::vector<uint32_t>> adj;
  for (const auto& [u, v] : edges) {
    adj[u].push_back(v);
    adj[v].push_back(u);
  }
  std::set<uint32_t> seen{a};
  std::queue<uint32_t> q;
  q.push(a);
  while (!q.empty()) {
    const uint32_t u = q.front();
    q.pop();
    if (u == b) return true;
    for (uint32_t v : adj[u])
      if (seen.insert(v).second) q.push(v);
  }
  return false;
}

double crack_length(const TetComplex& c, const std::set<std::pair<uint32_t, uint32_t>>& edges) {
  double l = 0;
  for (const auto& [a, b] : edges) l += (c.points[a] - c.points[b]).norm();
  return l;
}

}  // namespace

TEST(GrowthCracks, TransferKeepsTheStressExactlyOnAnUnchangedMesh) {
  TetComplex c = tetrahedralize_surface(icosphere(2, 0.5), TetSettings{}, "s.json", "/objects/0");
  TetAdjacency adj(c);
  StressParams p = bark_params(StressPattern::Horizontal);
  p.random_rotation = 0.5;  // a field that varies from face to face
  GrowthCracks cracks(p, {0, 4.0});
  cracks.step(c, adj, "s.json", "/objects/0/growth/cracks");
  const GrowthCracks::FaceStress before = cracks.face_stress();
  ASSERT_EQ(before.size(), c.interface_faces().size());
  double largest = 0;
  for (const auto& [key, r] : before) largest = std::max(largest, r.sigma.norm());
  ASSERT_GT(largest, 0.1);  // the pattern set a field
  cracks.step(c, adj, "s.json", "/objects/0/growth/cracks");
  ASSERT_EQ(cracks.face_stress().size(), before.size());
  for (const auto& [key, r] : cracks.face_stress()) {
    const auto it = before.find(key);
    ASSERT_NE(it, before.end());
    EXPECT_EQ(r.sigma, it->second.sigma);  // bit for bit
  }
}

TEST(GrowthCracks, ResidualsAndVirtualDisplacementAreCarriedByPointAcrossSteps) {
  // Eq. 6's residuals (a tip's surplus over τ, kept until it cracks) and the virtual
  // displacement summed by the relaxations belong to the surface, not to one step's cracker:
  // a transfer-only step on an unchanged mesh hands them on bit for bit.
  TetComplex c = tetrahedralize_surface(icosphere(3, 0.5), TetSettings{}, "s.json", "/objects/0");
  TetAdjacency adj(c);
  StressParams p = bark_params(StressPattern::Horizontal);
  p.relaxations_per_iteration = 2;
  GrowthCracks cracks(p, {3, 4.0});
  cracks.step(c, adj, "s.json", "/objects/0/growth/cracks");
  ASSERT_FALSE(cracks.crack_edges().empty());
  const std::vector<Eigen::Matrix3d> residual = cracks.residual();
  const std::vector<Eigen::Vector3d> displacement = cracks.displacement();
  ASSERT_EQ(residual.size(), c.points.size());
  long with_residual = 0, displaced = 0;
  for (size_t q = 0; q < residual.size(); ++q) {
    with_residual += residual[q].norm() > 0;
    displaced += displacement[q].norm() > 0;
  }
  EXPECT_GT(with_residual, 0);  // tips that took a surplus and have not cracked yet
  EXPECT_GT(displaced, 100);
  cracks.set_settings({0, 4.0});  // transfer only
  cracks.step(c, adj, "s.json", "/objects/0/growth/cracks");
  ASSERT_EQ(cracks.residual().size(), residual.size());
  for (size_t q = 0; q < residual.size(); ++q) {
    EXPECT_EQ(cracks.residual()[q], residual[q]) << "point " << q;
    EXPECT_EQ(cracks.displacement()[q], displacement[q]) << "point " << q;
  }
}

TEST(GrowthCracks, StretchAddsTheGreenStrain) {
  // Every point scaled by (1 + e) about the centre: each face's Green strain is
  // ((1 + e)² − 1) / 2 in every in-plane direction, and its frame does not turn.
  TetComplex c = tetrahedralize_surface(icosphere(2, 0.5), TetSettings{}, "s.json", "/objects/0");
  TetAdjacency adj(c);
  const double k = 3.0, e = 0.1, strain = ((1 + e) * (1 + e) - 1) / 2;
  GrowthCracks cracks(bark_params(StressPattern::Horizontal), {0, k});
  cracks.step(c, adj, "s.json", "/objects/0/growth/cracks");
  const GrowthCracks::FaceStress before = cracks.face_stress();
  for (auto& x : c.points) x *= 1 + e;
  cracks.step(c, adj, "s.json", "/objects/0/growth/cracks");
  for (const auto& [key, r] : cracks.face_stress()) {
    const Eigen::Matrix2d added = r.sigma - before.at(key).sigma;
    EXPECT_NEAR(added(0, 0), k * strain, 1e-9);
    EXPECT_NEAR(added(1, 1), k * strain, 1e-9);
    EXPECT_NEAR(added(0, 1), 0, 1e-9);
  }
}

TEST(GrowthCracks, CracksPersistLengthenAndWidenAsALogGrows) {
  CambialGrowthSettings s;
  s.function.weibull_c = 1;
  s.function.age_scale = 1;
  s.function.thickness = 0.12f;
  s.steps = 6;
  s.ring_interval = 0;
  const TriMesh log = log_mesh(0.1, 0.4, 32, 16, 0.2, 5);
  CambialGrowth g(log, {}, s, "s.json", "/objects/0/growth");
  // Horizontal tension (vertical cracks), a little under τ at first: the stretch of the
  // growing girth tears it.
  StressParams p = bark_params(StressPattern::Horizontal);
  p.magnitude = 1.0;
  g.couple_cracks(p, {2, 6.0});
  const GrowthCracks& cr = *g.cracks();
  auto edges = cr.crack_edges();
  auto width = cr.width();
  const size_t first = edges.size();
  double length = crack_length(g.complex(), edges);
  while (g.step()) {
    const TetComplex& c = g.complex();
    ASSERT_EQ(c.first_inverted(), -1) << "step " << g.steps_done();
    const auto faces = c.interface_faces();
    ASSERT_TRUE(closed_manifold(faces)) << "step " << g.steps_done();
    // The crack step takes the interface from the adjacency's scan, sorted: the same faces.
    {
      const TetAdjacency adj(c);
      auto scanned = interface_faces(c, adj);
      std::sort(scanned.begin(), scanned.end());
      ASSERT_EQ(scanned, faces) << "step " << g.steps_done();
      const GrowthSurface a = extract_interface(c), b = extract_interface(c, scanned);
      ASSERT_EQ(a.point, b.point);
      ASSERT_EQ(a.mesh.triangles, b.mesh.triangles);
    }
    // The interface is the stress mesh: the cracked mesh has one vertex per interface point.
    std::set<uint32_t> points;
    for (const auto& f : faces) points.insert(f.begin(), f.end());
    EXPECT_EQ(cr.result()->mesh.positions.size(), points.size()) << "step " << g.steps_done();
    // The crack network contains the last step's: both ends of every old crack edge still
    // lie on cracks, joined by crack edges.
    for (const auto& [a, b] : edges) {
      ASSERT_TRUE(c.on_crack[a] && c.on_crack[b]) << "step " << g.steps_done();
      ASSERT_TRUE(joined(cr.crack_edges(), a, b)) << "step " << g.steps_done() << ": " << a << "-" << b;
    }
    for (size_t q = 0; q < width.size(); ++q) ASSERT_GE(cr.width()[q], width[q]) << "point " << q;
    const double now = crack_length(c, cr.crack_edges());
    EXPECT_GT(now, length) << "step " << g.steps_done();  // the surface stretches them and new ones open
    length = now;
    edges = cr.crack_edges();
    width = cr.width();
  }
  EXPECT_GT(edges.size(), first + 10);
  EXPECT_EQ(cr.stats().edges_lost, 0);
  EXPECT_EQ(cr.stats().splits_lost, 0);
  EXPECT_GT(cr.stats().splits_mirrored, 0);
  EXPECT_GT(g.stats().cracks_s, 0);
}

TEST(InterfaceCaps, AFlattenedTriangleBecomesAnEdgeAndItsCapVertexStays) {
  TetComplex c = tetrahedralize_surface(icosphere(2, 0.5), TetSettings{}, "s.json", "/objects/0");
  TetAdjacency adj(c);
  const auto faces = c.interface_faces();
  const std::array<uint32_t, 3> f = faces[faces.size() / 2];
  const uint32_t p = f[0], a = f[1], b = f[2];
  // Walk p towards the midpoint of a–b while every tetrahedron stays positive.
  const Eigen::Vector3d start = c.points[p], target = 0.5 * (c.points[a] + c.points[b]);
  double reached = 0;
  for (int k = 1; k <= 100; ++k) {
    const double s = 1 - std::pow(0.5, k / 5.0);
    const Eigen::Vector3d before = c.points[p];
    c.points[p] = (1 - s) * start + s * target;
    if (c.first_inverted() >= 0) {
      c.points[p] = before;
      break;
    }
    reached = s;
  }
  const Eigen::Vector3d u = c.points[a] - c.points[p], v = c.points[b] - c.points[p];
  const double angle = std::atan2(u.cross(v).norm(), u.dot(v));
  ASSERT_GT(angle, 2.9) << "p reached " << reached << " of the way";
  const Eigen::Vector3d kept = c.points[p];
  c.on_crack.assign(c.points.size(), 0);
  c.on_crack[p] = 1;  // a crack runs through the cap vertex: it must neither go nor move
  const CapStats st = remove_interface_caps(c, adj, 2.8);
  EXPECT_GE(st.found, 1);
  EXPECT_GE(st.removed, 1);
  EXPECT_EQ(c.first_inverted(), -1);
  const auto after = c.interface_faces();
  EXPECT_EQ(st.faces, after);  // the faces it hands on are the interface's, sorted
  EXPECT_TRUE(closed_manifold(after));
  EXPECT_EQ(after.size(), faces.size());  // the split adds two faces, the collapse removes two
  EXPECT_TRUE(c.on_interface[p]);
  EXPECT_EQ(c.points[p], kept);  // the cap vertex stays where it was
  for (const auto& g : after) {
    const Eigen::Vector3d x = c.points[g[1]] - c.points[g[0]], y = c.points[g[2]] - c.points[g[0]];
    EXPECT_GT(x.cross(y).norm(), 1e-6) << "a flat face is left";
  }
}
