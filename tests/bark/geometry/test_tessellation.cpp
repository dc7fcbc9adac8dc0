// Adaptive tessellation: watertight across patches refined to different levels, displaced
// exactly, fixed by the dicing camera, bounded by the triangle budget.
#include <gtest/gtest.h>

#include <map>

#include "bark/geometry/generalized_cylinder.h"
#include "bark/geometry/tessellation.h"
#include "renderer/render_scene.h"
#include "scene/displacement.h"
#include "scene/scene_parser.h"
#include "scene/tree_surface.h"
#include "tests/support/render_helpers.h"

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
  m.positions = {{-1, t, 0},  {1, t, 0},  {-1, -t, 0}, {1, -t, 0}, {0, -1, t},  {0, 1, t},
                 {0, -1, -t}, {0, 1, -t}, {t, 0, -1},  {t, 0, 1},  {-t, 0, -1}, {-t, 0, 1}};
  for (auto& p : m.positions) p.normalize();
  m.indices = {0, 11, 5, 0, 5, 1, 0, 1, 7, 0, 7, 10, 0, 10, 11, 1, 5, 9, 5, 11, 4,  11, 10, 2,  10, 7, 6, 7, 1, 8,
               3, 9,  4, 3, 4, 2, 3, 2, 6, 3, 6, 8,  3, 8,  9,  4, 9, 5, 2, 4,  11, 6,  2,  10, 8,  6, 7, 9, 8, 1};
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
    return build_render_scene(d, d.camera, 640, 480)->stats().diced_triangles;
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
    "objects": [{"type": "tree", "axis": [[0,0,0],[0,1,0]], "radius": 0.1}]})",
                                  "<t>", ".");
  const auto rs = build_render_scene(d, d.camera, 64, 48);
  // A 1 m tube of circumference 0.628 m diced to ≤1 cm edges: ≥ 63 × 100 quads.
  EXPECT_GE(rs->stats().diced_triangles, 2 * 63 * 100);
  EXPECT_LE(rs->stats().diced_triangles, 2 * 63 * 100 * 2);
}

// An open 12-sided prism of radius 1 and height 1 around y, its seam column duplicated (u = 0
// and u = 1), with the given per-vertex normals (radial when `radial`, else left empty).
MeshData prism(bool radial) {
  MeshData m;
  const int around = 12, along = 4;
  for (int j = 0; j <= along; ++j)
    for (int i = 0; i <= around; ++i) {
      const float a = 2 * kPi * float(i % around) / around;
      m.positions.emplace_back(std::cos(a), float(j) / along, std::sin(a));
      m.uvs.emplace_back(float(i) / around, float(j) / along);
      if (radial) m.normals.emplace_back(std::cos(a), 0.0f, std::sin(a));
    }
  for (int j = 0; j < along; ++j)
    for (int i = 0; i < around; ++i) {
      const uint32_t a = uint32_t(j * (around + 1) + i), b = a + 1, c = a + around + 1, d = c + 1;
      m.indices.insert(m.indices.end(), {a, c, b, b, c, d});  // outward
    }
  return m;
}

TEST(Tessellation, DicedCoarseMeshShadesWithTheBaseNormalsAndTheDisplacementSlope) {
  const MeshData base = prism(true);
  DicingParams d;
  d.screen_space = false;
  d.target = 0.02f;
  // Nothing displaced: every diced vertex has the base's interpolated normal (a diced patch
  // shades like an undiced triangle, not as the flat facet its grid lies on).
  const MeshData flat = dice(base, DisplacementFn([](const Vec2f&, const Vec3f&) { return 0.0f; }), d);
  ASSERT_GT(flat.triangle_count(), 100 * base.triangle_count());
  for (size_t k = 0; k < flat.positions.size(); ++k) {
    const Vec3f& p = flat.positions[k];
    // The interpolated normal is radial through the point's angle on the facet (for a point on a
    // facet of this prism the blend of the two radial corner normals points through it).
    const Vec3f radial = Vec3f(p.x(), 0, p.z()).normalized();
    ASSERT_GT(flat.normals[k].dot(radial), 1 - 1e-5f) << "vertex " << k;
  }
  // Displacement a·sin(k y) along the normal: the surface r(y) = r₀ + a sin(k y) has the normal
  // (1, −a k cos(k y)) / √(1 + (a k cos(k y))²) in the (radial, y) plane.
  const float amp = 0.01f, freq = 6.0f;
  const MeshData bumped =
      dice(base, DisplacementFn([&](const Vec2f&, const Vec3f& p) { return amp * std::sin(freq * p.y()); }), d);
  int checked = 0;
  for (size_t k = 0; k < bumped.positions.size(); ++k) {
    const Vec3f& p = bumped.positions[k];
    if (p.y() < 0.1f || p.y() > 0.9f) continue;  // the open ends have one-sided normals
    const float slope = -amp * freq * std::cos(freq * p.y());
    const float expected_y = slope / std::sqrt(1 + slope * slope);
    ASSERT_NEAR(bumped.normals[k].y(), expected_y, 0.004f) << "at y = " << p.y();
    ++checked;
  }
  EXPECT_GT(checked, 1000);
}

TEST(Mesh, NormalsWeldedByPositionCloseTheUVSeam) {
  MeshData m = prism(false);
  compute_vertex_normals(m);
  const size_t first = 13 * 2, last = first + 12;  // row 2: u = 0 and its copy at u = 1
  ASSERT_EQ(m.positions[first], m.positions[last]);
  EXPECT_LT(m.normals[first].dot(m.normals[last]), 0.99f) << "unwelded, each copy sees one side of the seam";
  compute_vertex_normals(m, true);
  EXPECT_EQ(m.normals[first], m.normals[last]);
  EXPECT_GT(m.normals[first].dot(Vec3f(1, 0, 0)), 1 - 1e-6f);  // radial: both sides of the seam count
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
