// Joining a tree's tubes at their branchings (bark/geometry/tube_junctions): one closed
// manifold surface, nothing left inside either tube, UVs from the part each face lies on.
#include <CGAL/Polygon_mesh_processing/border.h>
#include <CGAL/Polygon_mesh_processing/connected_components.h>
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <memory>

#include "bark/geometry/procedural_meshes.h"
#include "bark/geometry/tube_junctions.h"
#include "bark/stress/stress_mesh.h"

namespace phellem::bark {
namespace {

constexpr double kPi = 3.141592653589793;

// A trunk of radius 0.2 along +Y (y in [0, 1]) and a branch of radius 0.08 along +X from the
// trunk's axis at y = 0.5 (x in [start, start + 0.6]).
struct TJunction {
  std::vector<TriMesh> parts;
  std::vector<int> parent{-1, 0};
};

TJunction t_junction(double start) {
  TJunction t;
  t.parts.push_back(cylinder_mesh(0.2, 1.0, 64, 40, 0.0, 1));
  TriMesh branch = cylinder_mesh(0.08, 0.6, 32, 30, 0.0, 1);
  const Eigen::Matrix3d r = Eigen::AngleAxisd(-kPi / 2, Eigen::Vector3d::UnitZ()).toRotationMatrix();  // +Y -> +X
  for (auto& p : branch.positions) p = r * p + Eigen::Vector3d(start, 0.5, 0);
  t.parts.push_back(branch);
  return t;
}

int border_loops(const StressMesh& m) {
  std::vector<SurfaceMesh::Halfedge_index> cycles;
  CGAL::Polygon_mesh_processing::extract_boundary_cycles(m.mesh(), std::back_inserter(cycles));
  return int(cycles.size());
}

int face_components(const StressMesh& m) {
  SurfaceMesh g = m.mesh();  // a copy to hang the component map on
  auto component = g.add_property_map<FaceId, std::size_t>("f:component").first;
  return int(CGAL::Polygon_mesh_processing::connected_components(g, component));
}

TEST(TubeJunctions, BranchIsStitchedIntoItsParentWithNothingInside) {
  const TJunction t = t_junction(0.0);
  const JoinedTubes j = join_tubes(t.parts, t.parent);
  EXPECT_TRUE(j.not_joined.empty()) << j.not_joined.front();
  const StressMesh m = StressMesh::from(j.mesh);  // throws on a non-manifold edge
  EXPECT_TRUE(m.mesh().is_valid(false));
  // The junction is stitched and the three open ends (the trunk's two, the branch's tip) are
  // capped: a closed surface, trunk and branch one connected piece (a crack can run across).
  EXPECT_EQ(j.caps, 3);
  EXPECT_EQ(border_loops(m), 0);
  EXPECT_EQ(face_components(m), 1);
  ASSERT_EQ(j.mesh.uvs.size(), j.mesh.positions.size());
  int on_branch = 0;
  for (size_t f = 0; f < j.mesh.triangles.size(); ++f) {
    const auto& tri = j.mesh.triangles[f];
    const Eigen::Vector3d c = (j.mesh.positions[tri[0]] + j.mesh.positions[tri[1]] + j.mesh.positions[tri[2]]) / 3;
    const double from_trunk_axis = std::hypot(c.x(), c.z()), from_branch_axis = std::hypot(c.y() - 0.5, c.z());
    // Nothing of the branch inside the trunk, nothing of the trunk inside the branch (faces are
    // flat, so their centres lie up to a sagitta inside the round surface they belong to).
    EXPECT_FALSE(from_trunk_axis < 0.19 && from_branch_axis < 0.075) << "face " << f << " at " << c.transpose();
    if (from_branch_axis > 0.07 && c.x() > 0.3) {
      // A branch face: its corners carry the branch's (u, v) = (θ / 2π, distance along / 0.6).
      ++on_branch;
      for (uint32_t k : tri) EXPECT_NEAR(j.mesh.uvs[k].y(), j.mesh.positions[k].x() / 0.6, 1e-6);
    } else if (from_trunk_axis > 0.19 && std::abs(c.y() - 0.5) > 0.15) {
      for (uint32_t k : tri) EXPECT_NEAR(j.mesh.uvs[k].y(), j.mesh.positions[k].y(), 1e-6);  // the trunk's v = y / 1
    }
  }
  EXPECT_GT(on_branch, 500);
}

TEST(TubeJunctions, ABranchThatMissesItsParentIsKeptApartAndNamed) {
  const TJunction t = t_junction(0.3);  // starts outside the trunk
  const JoinedTubes j = join_tubes(t.parts, t.parent);
  ASSERT_EQ(j.not_joined.size(), 1u);
  EXPECT_NE(j.not_joined[0].find("branch 1"), std::string::npos);
  EXPECT_NE(j.not_joined[0].find("closed curve"), std::string::npos) << j.not_joined[0];
  size_t faces = 0;
  for (const TriMesh& p : t.parts) faces += p.triangles.size();
  EXPECT_GT(j.mesh.triangles.size(), faces);  // both tubes whole, and their four ends capped
  EXPECT_EQ(j.caps, 4);
  const StressMesh m = StressMesh::from(j.mesh);
  EXPECT_EQ(face_components(m), 2);
  EXPECT_EQ(border_loops(m), 0);
}

TEST(TubeJunctions, SameTubesGiveTheSameSurfaceWhateverTheHeap) {
  // Determinism: nothing in the join may depend on where its buffers happen to be allocated
  // (CGAL orders corefinement boxes by their address) or on state left by an earlier call.
  const TJunction t = t_junction(0.0);
  const JoinedTubes a = join_tubes(t.parts, t.parent);
  std::vector<std::unique_ptr<std::vector<char>>> clutter;  // moves later allocations around
  for (int round = 0; round < 8; ++round) {
    for (size_t k = 0; k < 64; ++k) clutter.push_back(std::make_unique<std::vector<char>>(size_t(1000 * (k % 7 + 1)) << round));
    for (size_t k = 0; k < clutter.size(); k += 3) clutter[k].reset();
    const JoinedTubes b = join_tubes(t.parts, t.parent);
    ASSERT_EQ(a.mesh.triangles.size(), b.mesh.triangles.size()) << round;
    ASSERT_EQ(a.mesh.triangles, b.mesh.triangles);
    EXPECT_EQ(a.mesh.positions, b.mesh.positions);
    EXPECT_EQ(a.mesh.uvs, b.mesh.uvs);
  }
}

}  // namespace
}  // namespace phellem::bark
