// A growing tree's surface (scene/mesh_source.h object_trimesh): its trunk and branch, diced at
// the growth's edge band and joined at the branching with flat caps on the open ends, are one
// closed, outward-oriented 2-manifold, as cambial growth needs.
#include <gtest/gtest.h>

#include "scene/mesh_source.h"
#include "scene/scene_parser.h"
#include "tests/support/closed_surface.h"

using namespace phellem;

namespace {

const char* kTree = R"({"objects": [{"type": "tree", "name": "tree",
  "axis": [[0, 0, 0], [0.02, 0.6, 0.01], [0.0, 1.2, 0.02]], "radius": [0.12, 0.1, 0.08],
  "branches": [{"attach": 0.5, "azimuth_deg": 20, "angle_deg": 50, "length": 0.5, "radius": [0.05, 0.03]}],
  "growth": {"steps": 2, "thickness": 0.01, "edge_length": [0.012, 0.036]}}]})";

}  // namespace

TEST(GrowthTree, AGrowingTreeIsOneClosedOutwardSurfaceDicedAtItsBand) {
  const SceneDesc desc = parse_scene(kTree, "tree.json", ".");
  ASSERT_EQ(desc.objects.size(), 1u);
  ASSERT_TRUE(desc.objects[0].growth);
  const bark::TriMesh m = object_trimesh(desc.objects[0]);
  ASSERT_GT(m.triangles.size(), 100u);
  // Welded by position (the joined surface repeats a vertex per corner): closed, a 2-manifold.
  EXPECT_EQ(test::manifold_problem(m), "");
  const double volume = test::signed_volume(m);
  double edges = 0;
  for (const auto& t : m.triangles)
    for (size_t e = 0; e < 3; ++e) edges += (m.positions[t[e]] - m.positions[t[(e + 1) % 3]]).norm();
  // Outwards, and more than the thinnest trunk's cylinder alone (π 0.08² × 1.2).
  EXPECT_GT(volume, 3.14159 * 0.08 * 0.08 * 1.2);
  EXPECT_LT(volume, 3.14159 * 0.12 * 0.12 * 1.2 + 3.14159 * 0.05 * 0.05 * 0.5);
  // Diced at the band's maximum / 1.5 = 24 mm (the dicer's edges run up to that target).
  const double mean_edge = edges / (3.0 * double(m.triangles.size()));
  EXPECT_GT(mean_edge, 0.010);
  EXPECT_LT(mean_edge, 0.030);
}
