// Adaptive tessellation: watertight across patches refined to different levels, displaced
// exactly, fixed by the dicing camera, bounded by the triangle budget.
#include <gtest/gtest.h>

#include <map>

#include "bark/geometry/generalized_cylinder.h"
#include "render_helpers.h"
#include "renderer/displacement.h"
#include "renderer/render_scene.h"
#include "renderer/scene_parser.h"
#include "renderer/tessellation.h"
#include "renderer/tree_surface.h"

namespace phellem {
namespace {

// Welds vertices with bit-identical positions and counts how many triangles use each edge.
std::map<std::pair<int, int>, int> edge_use(const MeshData& m) {
  std::map<std::tuple<float, float, float>, int> weld;
  std::vector<int> id(m.positions.size());
  for (size_t i = 0; i < m.positions.size(); ++i) {
    const auto key = std::make_tuple(m.positions[i].x(), m.positions[i].y(), m.positions[i].z());
    id[i] = weld.emplace(key, int(weld.size())).first->second;
  }
  std::map<std::pair<int, int>, int> use;
  for (size_t f = 0; f + 2 < m.indices.size(); f += 3)
    for (int e = 0; e < 3; ++e) {
      int a = id[m.indices[f + e]], b = id[m.indices[f + (e + 1) % 3]];
      ++use[std::minmax(a, b)];
    }
  return use;
}

MeshData icosphere(int subdivisions) {
  MeshData m;
  const float t = (1 + std::sqrt(5.0f)) / 2;
  m.positions = {{-1, t, 0}, {1, t, 0}, {-1, -t, 0}, {1, -t, 0}, {0, -1, t}, {0, 1, t}, {0, -1, -t}, {0, 1, -t},
                 {t, 0, -1}, {t, 0, 1}, {-t, 0, -1}, {-t, 0, 1}};
  for (auto& p : m.positions) p.normalize();
  m.indices = {0, 11, 5, 0, 5, 1, 0, 1, 7, 0, 7, 10, 0, 10, 11, 1, 5, 9, 5, 11, 4, 11, 10, 2, 10, 7, 6, 7, 1, 8,
               3, 9, 4, 3, 4, 2, 3, 2, 6, 3, 6, 8, 3, 8, 9, 4, 9, 5, 2, 4, 11, 6, 2, 10, 8, 6, 7, 9, 8, 1};
  for (int s = 0; s < subdivisions; ++s) {
    std::map<std::pair<uint32_t, uint32_t>, uint32_t> mid;
    auto midpoint = [&](uint32_t a, uint32_t b) {
      auto key = std::minmax(a, b);
      auto it = mid.find(key);
      if (it != mid.end()) return it->second;
      m.positions.push_back((m.positions[a] + m.positions[b]).normalized());
      return mid[key] = uint32_t(m.positions.size() - 1);
    };
    std::vector<uint32_t> next;
    for (size_t f = 0; f < m.indices.size(); f += 3) {
      const uint32_t a = m.indices[f], b = m.indices[f + 1], c = m.indices[f + 2];
      const uint32_t ab = midpoint(a, b), bc = midpoint(b, c), ca = midpoint(c, a);
      next.insert(next.end(), {a, ab, ca, b, bc, ab, c, ca, bc, ab, bc, ca});
    }
    m.indices = next;
  }
  m.normals = m.positions;
  return m;
}

TEST(Tessellation, DisplacedMeshIsWatertightAcrossDifferentRates) {
  const MeshData base = icosphere(1);
  // Strongly varying rates: fine near the camera, coarse far away.
  DicingParams d;
  d.screen_space = true;
  d.target = 2.0f;
  d.camera_position = Vec3f(0, 0, 1.3f);
  d.pixel_angle = 0.004f;
  const DisplacementFn disp = [](const Vec2f&, const Vec3f& p) { return 0.1f * std::sin(9 * p.x()) * std::cos(7 * p.y()); };
  const MeshData m = dice(base, disp, d);
  ASSERT_GT(m.triangle_count(), base.triangle_count() * 4);
  int max_rate = 0, min_rate = 1 << 20;
  for (size_t f = 0; f < base.indices.size(); f += 3) {
    const Vec3f pts[2] = {base.positions[base.indices[f]], base.positions[base.indices[f + 1]]};
    const int r = d.edge_rate(pts, 2);
    max_rate = std::max(max_rate, r);
    min_rate = std::min(min_rate, r);
  }
  EXPECT_GT(max_rate, 2 * min_rate) << "the test needs neighbours at different levels";
  // Closed input: every welded edge must be used by exactly two triangles.
  for (const auto& [edge, n] : edge_use(m)) ASSERT_EQ(n, 2) << "edge " << edge.first << "-" << edge.second;
  // Vertices lie exactly on the displaced surface: |p| = 1 + d(p̂) for the sphere.
  for (size_t i = 0; i < m.positions.size(); i += 97) {
    const Vec3f p = m.positions[i];
    // The undisplaced point is on the flat icosahedron face, not the sphere; displacement
    // moved it by at most 0.1 along the normal.
    EXPECT_LT(p.norm(), 1.1f + 1e-4f);
  }
}

TEST(Tessellation, TreeSurfaceIsWatertightIncludingTheSeam) {
  TreeDesc t;
  t.axis = {Vec3f(0, 0, 0), Vec3f(0.1f, 1, 0), Vec3f(0, 2, 0.1f)};
  t.radius = {0.3f, 0.2f};
  DisplacementDesc dd;
  dd.type = DisplacementDesc::Type::Grooves;
  dd.amplitude = 0.02f;
  const auto parts = build_tree(t, make_displacement(dd));
  DicingParams d;
  d.camera_position = Vec3f(0.5f, 0.3f, 1.0f);
  d.pixel_angle = 0.002f;
  const MeshData m = dice(parts[0].surface, d);
  int open = 0;
  for (const auto& [edge, n] : edge_use(m)) {
    ASSERT_LE(n, 2);
    if (n == 1) ++open;
  }
  // Only the two end rings are open; their length bounds the number of open edges.
  const int ring = parts[0].surface.patches_u * d.max_rate;
  EXPECT_GT(open, 0);
  EXPECT_LE(open, 2 * ring);
  // Every open edge lies on an end ring (texture v = 0 or v = max), never on the θ seam.
  float v_max = 0;
  for (const auto& uv : m.uvs) v_max = std::max(v_max, uv.y());
  // edge_use numbers welded vertices in first-seen order; rebuild that order.
  std::map<std::tuple<float, float, float>, int> order;
  std::vector<float> v_by_id;
  for (size_t i = 0; i < m.positions.size(); ++i) {
    const auto key = std::make_tuple(m.positions[i].x(), m.positions[i].y(), m.positions[i].z());
    if (order.emplace(key, int(order.size())).second) v_by_id.push_back(m.uvs[i].y());
  }
  int seam_cracks = 0;
  for (const auto& [edge, n] : edge_use(m)) {
    if (n != 1) continue;
    const float va = v_by_id[edge.first], vb = v_by_id[edge.second];
    const bool on_end = (va == 0 && vb == 0) || (va == v_max && vb == v_max);
    if (!on_end) ++seam_cracks;
  }
  EXPECT_EQ(seam_cracks, 0);
}

TEST(Tessellation, DicingCameraFixesTheGeometryAndBudgetBoundsIt) {
  const char* scene = R"({
    "camera": {"position": [%s], "look_at": [0, 1, 0]},
    "render": {"resolution": [640, 480], "tessellation": {"mode": "screen", "pixels_per_edge": 1,
               "dicing_camera": {"position": [0, 1, 3], "look_at": [0, 1, 0]} %s}},
    "objects": [{"type": "tree", "axis": [[0,0,0],[0,2,0]], "radius": 0.3,
                 "displacement": {"type": "grooves", "amplitude": 0.02}}]
  })";
  auto triangles = [&](const char* cam, const char* extra) {
    char buf[2048];
    std::snprintf(buf, sizeof buf, scene, cam, extra);
    const SceneDesc d = parse_scene(buf, "<t>", ".");
    RenderScene rs(d, d.camera, 640, 480);
    return rs.stats().diced_triangles;
  };
  const long long a = triangles("0, 1, 3", ""), b = triangles("3, 2, 0", "");
  EXPECT_EQ(a, b);
  EXPECT_GT(a, 10000);
  const long long budget = triangles("0, 1, 3", ", \"max_triangles\": 5000");
  EXPECT_LE(budget, 5000 * 1.15);
  EXPECT_LT(budget, a);
  // The memory knob scales triangles down roughly quadratically.
  const long long coarse = triangles("0, 1, 3", ", \"edge_length_scale\": 2");
  EXPECT_LT(coarse, a * 0.4);
}

TEST(Tessellation, ObjectSpaceDicingHitsTheTargetEdgeLength) {
  const SceneDesc d = parse_scene(R"({
    "render": {"tessellation": {"mode": "object", "edge_length": 0.01}},
    "objects": [{"type": "tree", "axis": [[0,0,0],[0,1,0]], "radius": 0.1}]})", "<t>", ".");
  RenderScene rs(d, d.camera, 64, 48);
  // A 1 m tube of circumference 0.628 m diced to ≤1 cm edges: ≥ 63 × 100 quads.
  EXPECT_GE(rs.stats().diced_triangles, 2 * 63 * 100);
  EXPECT_LE(rs.stats().diced_triangles, 2 * 63 * 100 * 2);
}

TEST(GeneralizedCylinder, RadiusAndFrameAreConsistent) {
  bark::GeneralizedCylinder c({Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(0, 1, 0), Eigen::Vector3d(1, 2, 0)}, {0.5, 0.25});
  for (double s : {0.0, 0.3, 0.7, 1.0})
    for (double th : {0.0, 1.0, 3.0, 5.5}) {
      const Eigen::Vector3d p = c.position(s, th);
      EXPECT_NEAR((p - c.axis_point(s)).norm(), c.radius(s, th), 1e-9);
      const Eigen::Matrix3d f = c.frame(s);
      EXPECT_NEAR((f.transpose() * f - Eigen::Matrix3d::Identity()).norm(), 0, 1e-9);
      EXPECT_NEAR((p - c.axis_point(s)).dot(f.col(0)), 0, 1e-9);  // cross-sections ⟂ axis
    }
  EXPECT_NEAR(c.radius(0.5, 0), 0.375, 1e-12);
  // θ wraps without a seam.
  EXPECT_LT((c.position(0.4, 0) - c.position(0.4, 2 * M_PI)).norm(), 1e-12);
}

}  // namespace
}  // namespace phellem
