// Obstacles and contact of cambial growth (Kratt et al., Woodification, sec. 4.5;
// bark/growth/tet_complex.h, growth_contact.h): obstacles embedded in the tetrahedral volume
// never move and are never entered by the growing front; fronts that meet freeze in contact
// and stay apart; a surface that overlaps an obstacle at the start is refused with the
// obstacle's path.
#include <gtest/gtest.h>

#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Side_of_triangle_mesh.h>
#include <CGAL/Surface_mesh.h>
#include <tbb/global_control.h>

#include <limits>

#include "bark/geometry/procedural_meshes.h"
#include "bark/growth/growth_contact.h"
#include "bark/growth/interface_components.h"
#include "bark/growth/interface_motion.h"
#include "bark/growth/interface_refinement.h"
#include "util/errors.h"

using namespace phellem;
using namespace phellem::bark;

namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using SurfaceMesh = CGAL::Surface_mesh<K::Point_3>;

K::Point_3 cgal(const Eigen::Vector3d& p) { return {p.x(), p.y(), p.z()}; }

// An axis-aligned box [lo, hi] as a closed mesh facing outwards: a "fence wire" when thin.
TriMesh box_mesh(const Eigen::Vector3d& lo, const Eigen::Vector3d& hi) {
  TriMesh m;
  for (int c = 0; c < 8; ++c)
    m.positions.emplace_back((c & 1) ? hi.x() : lo.x(), (c & 2) ? hi.y() : lo.y(), (c & 4) ? hi.z() : lo.z());
  const int quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  for (const auto& q : quads) {
    m.triangles.push_back({uint32_t(q[0]), uint32_t(q[1]), uint32_t(q[2])});
    m.triangles.push_back({uint32_t(q[0]), uint32_t(q[2]), uint32_t(q[3])});
  }
  return m;
}

TriMesh translated(TriMesh m, const Eigen::Vector3d& by) {
  for (auto& p : m.positions) p += by;
  return m;
}

TriMesh merged(const TriMesh& a, const TriMesh& b) {
  TriMesh m = a;
  const uint32_t base = uint32_t(m.positions.size());
  m.positions.insert(m.positions.end(), b.positions.begin(), b.positions.end());
  for (const auto& t : b.triangles) m.triangles.push_back({t[0] + base, t[1] + base, t[2] + base});
  m.uvs.clear();
  return m;
}

double enclosed_volume(const TriMesh& m) {
  double v = 0;
  for (const auto& t : m.triangles) v += m.positions[t[0]].dot(m.positions[t[1]].cross(m.positions[t[2]])) / 6;
  return v;
}

// The interface (or the faces given) as a CGAL mesh, for point-in-polyhedron tests.
SurfaceMesh mesh_of(const TetComplex& c, const std::vector<std::array<uint32_t, 3>>& faces) {
  SurfaceMesh sm;
  std::vector<SurfaceMesh::Vertex_index> v(c.points.size());
  std::vector<uint8_t> made(c.points.size(), 0);
  for (const auto& f : faces)
    for (uint32_t i : f)
      if (!made[i]) {
        v[i] = sm.add_vertex(cgal(c.points[i]));
        made[i] = 1;
      }
  for (const auto& f : faces) EXPECT_NE(sm.add_face(v[f[0]], v[f[1]], v[f[2]]), SurfaceMesh::null_face());
  return sm;
}

GrowthFunction growth_of(double thickness) {  // c = 1: a nearly constant speed over short spans of age
  GrowthFunction g;
  g.weibull_c = 1;
  g.thickness = float(thickness);
  return g;
}

double longest_interface_edge(const TetComplex& c) {
  double longest = 0;
  for (const auto& e : interface_edges(c)) longest = std::max(longest, (c.points[e[0]] - c.points[e[1]]).norm());
  return longest;
}

// The integrator of sec. 4.5: a motion step, the refinement, then the contact freeze.
struct GrowthRun {
  long frozen_obstacle = 0, frozen_front = 0;
};
GrowthRun grow(TetComplex& c, const GrowthFunction& g, double t_end, int steps, double max_edge, double gap, bool contact,
               const std::function<void(int)>& after_step = {}) {
  GrowthRun run;
  for (int k = 0; k < steps; ++k) {
    advance_interface(c, g, t_end * k / steps, t_end * (k + 1) / steps);
    split_long_interface_edges(c, max_edge);
    if (contact) {
      const ContactStats st = freeze_contacts(c, gap);
      run.frozen_obstacle += st.obstacle;
      run.frozen_front += st.front;
    }
    if (after_step) after_step(k);
  }
  return run;
}

// The smallest distance from a vertex of component 0 to a face of component 1.
double closest_between(const TetComplex& c, const InterfaceComponents& parts) {
  using Triangles = std::vector<K::Triangle_3>;
  Triangles other;
  for (const auto& f : c.interface_faces())
    if (parts.of_point[f[0]] == 1) other.emplace_back(cgal(c.points[f[0]]), cgal(c.points[f[1]]), cgal(c.points[f[2]]));
  CGAL::AABB_tree<CGAL::AABB_traits<K, CGAL::AABB_triangle_primitive<K, Triangles::const_iterator>>> tree(other.cbegin(),
                                                                                                          other.cend());
  tree.accelerate_distance_queries();
  double closest2 = std::numeric_limits<double>::infinity();
  for (size_t i = 0; i < c.points.size(); ++i)
    if (parts.of_point[i] == 0) closest2 = std::min(closest2, tree.squared_distance(cgal(c.points[i])));
  return std::sqrt(closest2);
}

// A sphere of radius 0.3 at the origin and a thin square wire along z beside it, 0.06 m from
// its surface: grown by 0.15 m the sphere would swallow the wire.
const Eigen::Vector3d kWireLo(0.36, -0.01, -0.2), kWireHi(0.38, 0.01, 0.2);
constexpr double kGrowSpan = 0.16;  // 1 − exp(−0.16) = 0.148 m with thickness 1
constexpr int kGrowSteps = 16;
constexpr double kGap = 0.004;      // under half a step's thickening (0.0093 m)

}  // namespace

TEST(GrowthObstacles, ObstacleRegionsAreLabelledFrozenAndOffTheInterface) {
  const TriMesh sphere = icosphere(2, 0.3);
  // The second obstacle reaches beyond the sphere's padded box (±0.6): the box grows.
  const TriMesh wire = box_mesh(kWireLo, kWireHi), post = box_mesh({-0.05, -0.9, 0.4}, {0.05, 0.9, 0.5});
  const TetComplex c = tetrahedralize_surface(sphere, {{wire, "/o/0"}, {post, "/o/1"}}, TetSettings{}, "s.json", "/objects/0");
  EXPECT_EQ(c.first_inverted(), -1);
  EXPECT_EQ(c.interface_faces().size(), sphere.triangles.size());  // obstacle faces are not bark
  EXPECT_EQ(c.boundary_faces(TetComplex::kObstacle).size(), wire.triangles.size() + post.triangles.size());
  EXPECT_NEAR(c.volume(TetComplex::kInside), enclosed_volume(sphere), 1e-9);
  EXPECT_NEAR(c.volume(TetComplex::kObstacle), enclosed_volume(wire) + enclosed_volume(post), 1e-12);
  double top = -1e9;
  for (const auto& p : c.points) top = std::max(top, p.y());
  EXPECT_GT(top, 0.9);  // the enlarged box holds the post with room around it
  for (size_t t = 0; t < c.tets.size(); ++t)
    if (c.label[t] == TetComplex::kObstacle)
      for (uint32_t v : c.tets[t]) {
        EXPECT_EQ(c.frozen[v], 1);
        EXPECT_EQ(c.on_interface[v], 0);
      }
  size_t frozen_surface = 0;
  for (size_t i = 0; i < sphere.positions.size(); ++i) frozen_surface += c.frozen[i];
  EXPECT_EQ(frozen_surface, 0u);
  // An obstacle given facing inwards is the same obstacle.
  TriMesh inward = wire;
  for (auto& t : inward.triangles) std::swap(t[1], t[2]);
  const TetComplex d = tetrahedralize_surface(sphere, {{inward, "/o/0"}}, TetSettings{}, "s.json", "/objects/0");
  EXPECT_NEAR(d.volume(TetComplex::kObstacle), enclosed_volume(wire), 1e-12);
}

TEST(GrowthObstacles, ObstaclePointsNeverMoveAndTheFrontNeverEntersTheWire) {
  const TriMesh sphere = icosphere(3, 0.3);
  const TriMesh wire = box_mesh(kWireLo, kWireHi);
  // And a chunky block on the other side, 0.08 m away, whose inside TetGen fills with
  // tetrahedra that the smoothing could move, were they not frozen.
  const TriMesh block = box_mesh({-0.5, -0.12, -0.12}, {-0.38, 0.12, 0.12});
  TetComplex c = tetrahedralize_surface(sphere, {{wire, "/objects/0/growth/obstacles/0"}, {block, "/objects/0/growth/obstacles/1"}},
                                        TetSettings{}, "s.json", "/objects/0");
  const double max_edge = longest_interface_edge(c);
  // The obstacle's points: every corner of an obstacle tetrahedron.
  std::vector<std::pair<size_t, Eigen::Vector3d>> fixed;
  std::vector<uint8_t> of_obstacle(c.points.size(), 0);
  for (size_t t = 0; t < c.tets.size(); ++t)
    if (c.label[t] == TetComplex::kObstacle)
      for (uint32_t v : c.tets[t]) of_obstacle[v] = 1;
  for (size_t i = 0; i < c.points.size(); ++i)
    if (of_obstacle[i]) fixed.push_back({i, c.points[i]});
  ASSERT_GE(fixed.size(), 8u);
  const double obstacle_volume = c.volume(TetComplex::kObstacle);
  const K::Iso_cuboid_3 wire_box(cgal(kWireLo), cgal(kWireHi)), block_box(cgal(block.positions[0]), cgal(block.positions[7]));
  const GrowthRun run = grow(c, growth_of(1.0), kGrowSpan, kGrowSteps, max_edge, kGap, true, [&](int k) {
    ASSERT_EQ(c.first_inverted(), -1) << "step " << k;
    // (a) The obstacle's points, its corners and TetGen's points inside it, stay bit-identical.
    for (const auto& [i, p] : fixed) {
      ASSERT_EQ(c.points[i], p) << "point " << i << " step " << k;
      ASSERT_EQ(c.frozen[i], 1);
    }
    // (b) No interface vertex inside the wire, no interface face touching it.
    for (size_t i = 0; i < c.points.size(); ++i)
      if (c.on_interface[i]) {
        ASSERT_FALSE(wire_box.has_on_bounded_side(cgal(c.points[i]))) << "vertex " << i << " step " << k;
        ASSERT_FALSE(block_box.has_on_bounded_side(cgal(c.points[i]))) << "vertex " << i << " step " << k;
      }
    for (const auto& f : c.interface_faces()) {
      const K::Triangle_3 t(cgal(c.points[f[0]]), cgal(c.points[f[1]]), cgal(c.points[f[2]]));
      ASSERT_FALSE(CGAL::do_intersect(t, wire_box)) << "step " << k;
      ASSERT_FALSE(CGAL::do_intersect(t, block_box)) << "step " << k;
    }
  });
  EXPECT_NEAR(c.volume(TetComplex::kObstacle), obstacle_volume, 1e-15);
  // The front reached the wire and froze on it; the rest grew on (a closed surface still).
  EXPECT_GT(run.frozen_obstacle, 0);
  double farthest = 0;
  for (size_t i = 0; i < c.points.size(); ++i)
    if (c.on_interface[i]) farthest = std::max(farthest, c.points[i].norm());
  EXPECT_GT(farthest, 0.3 + 0.8 * growth_of(1.0).cumulative(kGrowSpan));
  EXPECT_EQ(interface_components(c).count, 1);

  // Without the obstacle the same growth swallows the wire: the test above can fail.
  TetComplex free = tetrahedralize_surface(sphere, TetSettings{}, "s.json", "/objects/0");
  const GrowthRun alone = grow(free, growth_of(1.0), kGrowSpan, kGrowSteps, max_edge, kGap, true);
  // A lone growing sphere touches nothing: its own sheet, however split, never counts as contact.
  EXPECT_EQ(alone.frozen_front, 0);
  EXPECT_EQ(alone.frozen_obstacle, 0);
  const SurfaceMesh grown = mesh_of(free, free.interface_faces());
  const CGAL::Side_of_triangle_mesh<SurfaceMesh, K> inside(grown);
  for (const auto& p : wire.positions) EXPECT_EQ(inside(cgal(p)), CGAL::ON_BOUNDED_SIDE);
}

TEST(GrowthObstacles, TwoSpheresGrowingIntoEachOtherFreezeInContactAndStayTwo) {
  const double r0 = 0.25, gap = kGap;
  const TriMesh two = merged(translated(icosphere(3, r0), {-0.3, 0, 0}), translated(icosphere(3, r0), {0.3, 0, 0}));
  TetComplex c = tetrahedralize_surface(two, TetSettings{}, "s.json", "/objects/0");
  ASSERT_EQ(interface_components(c).count, 2);
  const double max_edge = longest_interface_edge(c);
  // Grown by 0.1 m each, they would overlap by 0.1 m.
  const GrowthRun run = grow(c, growth_of(1.0), 0.105, 12, max_edge, gap, true, [&](int k) {
    ASSERT_EQ(c.first_inverted(), -1) << "step " << k;
    ASSERT_EQ(interface_components(c).count, 2) << "step " << k;
  });
  EXPECT_GT(run.frozen_front, 0);
  const InterfaceComponents parts = interface_components(c);
  ASSERT_EQ(parts.count, 2);
  // The frozen vertices are where they meet (near x = 0), and the fronts are apart but close:
  // the smallest distance from a vertex of one to a face of the other.
  long frozen_between = 0;
  for (size_t i = 0; i < c.points.size(); ++i)
    if (c.on_interface[i] && c.frozen[i]) {
      EXPECT_LT(std::abs(c.points[i].x()), 0.05) << "frozen vertex " << i << " at " << c.points[i].transpose();
      ++frozen_between;
    }
  EXPECT_GT(frozen_between, 5);
  const double closest = closest_between(c, parts);
  EXPECT_GT(closest, 0);
  EXPECT_LE(closest, 3 * gap);
  const auto faces = c.interface_faces();
  // Neither passed into the other: no vertex of one inside the other's polyhedron.
  for (int side = 0; side < 2; ++side) {
    std::vector<std::array<uint32_t, 3>> own;
    for (const auto& f : faces)
      if (parts.of_point[f[0]] == side) own.push_back(f);
    const SurfaceMesh m = mesh_of(c, own);
    const CGAL::Side_of_triangle_mesh<SurfaceMesh, K> inside(m);
    for (size_t i = 0; i < c.points.size(); ++i)
      if (parts.of_point[i] == 1 - side) {
        EXPECT_EQ(inside(cgal(c.points[i])), CGAL::ON_UNBOUNDED_SIDE) << i;
      }
  }
  // The crease persists: growing on, the frozen vertices stay where they froze, the fronts stay
  // two and apart.
  std::vector<std::pair<size_t, Eigen::Vector3d>> frozen;
  for (size_t i = 0; i < c.points.size(); ++i)
    if (c.on_interface[i] && c.frozen[i]) frozen.push_back({i, c.points[i]});
  grow(c, growth_of(1.0), 0.03, 4, max_edge, gap, true, [&](int k) {
    ASSERT_EQ(c.first_inverted(), -1) << "step " << k;
    for (const auto& [i, p] : frozen) ASSERT_EQ(c.points[i], p) << "point " << i << " step " << k;
  });
  const InterfaceComponents later = interface_components(c);
  EXPECT_EQ(later.count, 2);
  EXPECT_GT(closest_between(c, later), 0);
}

TEST(GrowthObstacles, FreezingIsTheSameAtAnyThreadCount) {
  // freeze_contacts decides on a snapshot, so one thread and all of them freeze the same points.
  const TriMesh two = merged(translated(icosphere(2, 0.25), {-0.28, 0, 0}), translated(icosphere(2, 0.25), {0.28, 0, 0}));
  TetComplex a = tetrahedralize_surface(two, {{box_mesh({0.25, 0.3, -0.03}, {0.31, 0.36, 0.03}), "/o/0"}}, TetSettings{}, "s.json",
                                        "/objects/0");
  grow(a, growth_of(1.0), 0.03, 3, 1.0, 0.01, false);
  TetComplex b = a;
  const ContactStats all = freeze_contacts(a, 0.03);
  ContactStats one;
  {
    tbb::global_control single(tbb::global_control::max_allowed_parallelism, 1);
    one = freeze_contacts(b, 0.03);
  }
  EXPECT_GT(all.front, 0);
  EXPECT_GT(all.obstacle, 0);
  EXPECT_EQ(all.front, one.front);
  EXPECT_EQ(all.obstacle, one.obstacle);
  EXPECT_EQ(a.frozen, b.frozen);
}

TEST(GrowthObstacles, AnObstacleOverlappingTheSurfaceOrAnotherObstacleIsRefusedByName) {
  const TriMesh sphere = icosphere(2, 0.3);
  const TriMesh apart = box_mesh(kWireLo, kWireHi);
  auto error_of = [&](const std::vector<GrowthObstacle>& obstacles) -> std::pair<std::string, std::string> {
    try {
      tetrahedralize_surface(sphere, obstacles, TetSettings{}, "scene.json", "/objects/0");
    } catch (const UserError& e) {
      return {e.where(), e.what()};
    }
    return {"", "no error"};
  };
  // Crossing the surface.
  auto [where, what] = error_of({{apart, "/objects/0/growth/obstacles/0"},
                                 {box_mesh({0.25, -0.02, -0.02}, {0.4, 0.02, 0.02}), "/objects/0/growth/obstacles/1"}});
  EXPECT_EQ(where, "/objects/0/growth/obstacles/1");
  EXPECT_NE(what.find("scene.json: /objects/0/growth/obstacles/1: the obstacle touches, intersects"), std::string::npos) << what;
  // Wholly inside the surface.
  std::tie(where, what) = error_of({{box_mesh({-0.05, -0.05, -0.05}, {0.05, 0.05, 0.05}), "/objects/0/growth/obstacles/0"}});
  EXPECT_EQ(where, "/objects/0/growth/obstacles/0") << what;
  // Touching another obstacle (sharing a face's plane and area).
  std::tie(where, what) = error_of({{apart, "/o/0"}, {box_mesh({0.38, -0.01, -0.1}, {0.42, 0.01, 0.1}), "/o/1"}});
  EXPECT_EQ(where, "/o/1");
  EXPECT_NE(what.find("the obstacle at /o/0"), std::string::npos) << what;
  // Not closed.
  TriMesh open = apart;
  open.triangles.pop_back();
  std::tie(where, what) = error_of({{open, "/o/0"}});
  EXPECT_EQ(where, "/o/0");
  EXPECT_NE(what.find("an obstacle must be closed"), std::string::npos) << what;
  // Apart: accepted.
  EXPECT_EQ(error_of({{apart, "/o/0"}}).second, "no error");
}
