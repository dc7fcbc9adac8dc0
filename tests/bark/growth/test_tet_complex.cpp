// The labelled tetrahedral volume of cambial growth (bark/growth/tet_complex.h): TetGen keeps
// the surface as the interface between the labels, every tetrahedron is positively oriented
// by the exact predicate, the labels split the volume at the surface, and an open surface is
// refused with the object's path.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <map>
#include <set>

#include "bark/geometry/procedural_meshes.h"
#include "bark/growth/tet_complex.h"
#include "util/errors.h"

using namespace phellem;
using namespace phellem::bark;

TEST(TetComplex, TheInterfaceIsTheInputSurfaceAndEveryTetrahedronIsPositive) {
  const TriMesh sphere = icosphere(2, 0.5);  // 320 triangles
  const TetComplex c = tetrahedralize_surface(sphere, TetSettings{}, "scene.json", "/objects/0");
  EXPECT_EQ(c.first_inverted(), -1);
  EXPECT_GT(c.tets.size(), 500u);
  // The interface: the input's triangles, on its vertices (kept first and unchanged by Y),
  // oriented outwards as the input.
  auto faces = c.interface_faces();
  ASSERT_EQ(faces.size(), sphere.triangles.size());
  std::set<std::array<uint32_t, 3>> input;
  auto canonical = [](std::array<uint32_t, 3> f) {  // the rotation starting at the smallest index
    while (f[0] > f[1] || f[0] > f[2]) f = {f[1], f[2], f[0]};
    return f;
  };
  for (const auto& t : sphere.triangles) input.insert(canonical(t));
  for (const auto& f : faces) EXPECT_TRUE(input.count(canonical(f))) << f[0] << " " << f[1] << " " << f[2];
  for (size_t i = 0; i < sphere.positions.size(); ++i) {
    EXPECT_EQ(c.points[i], sphere.positions[i]);
    EXPECT_EQ(c.on_interface[i], 1);
  }
  // The inside volume is the polyhedron's (divergence theorem), the outside the box's rest.
  double enclosed = 0;
  for (const auto& t : sphere.triangles)
    enclosed += sphere.positions[t[0]].dot(sphere.positions[t[1]].cross(sphere.positions[t[2]])) / 6;
  EXPECT_NEAR(c.volume(1), enclosed, 1e-9);
  EXPECT_NEAR(c.volume(0) + c.volume(1), 2.0 * 2.0 * 2.0, 1e-9);  // the box: 1 m padded by 0.5 on every side
  EXPECT_GT(std::count(c.on_box.begin(), c.on_box.end(), 1), 7);
}

TEST(TetComplex, AGradedLatticeAddsOnlyFreePointsAwayFromTheSurface) {
  const TriMesh sphere = icosphere(3, 0.5);
  TetSettings graded;
  graded.lattice = 0.5;  // from 0.25 m (half the 0.5 m padding) out
  TetSettings none;
  none.lattice = 0;
  const TetComplex plain = tetrahedralize_surface(sphere, none, "scene.json", "/objects/0");
  const TetComplex c = tetrahedralize_surface(sphere, graded, "scene.json", "/objects/0");
  EXPECT_EQ(c.first_inverted(), -1);
  auto canonical = [](std::vector<std::array<uint32_t, 3>> faces) {  // each from its smallest index, sorted
    for (auto& f : faces)
      while (f[0] > f[1] || f[0] > f[2]) f = {f[1], f[2], f[0]};
    std::sort(faces.begin(), faces.end());
    return faces;
  };
  EXPECT_EQ(canonical(c.interface_faces()), canonical(plain.interface_faces()));  // the same surface and indices
  EXPECT_GT(c.points.size(), plain.points.size());
  for (size_t i = 0; i < sphere.positions.size(); ++i) EXPECT_EQ(c.points[i], sphere.positions[i]);
  EXPECT_NEAR(c.volume(0) + c.volume(1), 2.0 * 2.0 * 2.0, 1e-9);
  // The points after the input's and the box's 8 corners (the lattice's, then TetGen's) are
  // free: off the surface and off the box (switch Y adds none on facets).
  for (size_t i = sphere.positions.size() + 8; i < c.points.size(); ++i) {
    EXPECT_EQ(c.on_interface[i], 0) << i;
    EXPECT_EQ(c.on_box[i], 0) << i;
  }
}

TEST(TetComplex, TwoComponentsAreBothInside) {
  TriMesh two = icosphere(1, 0.3);
  const TriMesh other = icosphere(1, 0.3);
  const uint32_t base = uint32_t(two.positions.size());
  for (const auto& p : other.positions) two.positions.push_back(p + Eigen::Vector3d(1, 0, 0));
  for (const auto& t : other.triangles) two.triangles.push_back({t[0] + base, t[1] + base, t[2] + base});
  const TetComplex c = tetrahedralize_surface(two, TetSettings{}, "s.json", "/objects/1");
  EXPECT_EQ(c.interface_faces().size(), two.triangles.size());
  EXPECT_EQ(c.first_inverted(), -1);
}

TEST(TetComplex, AnOpenSurfaceIsRefusedAtTheObjectsPath) {
  TriMesh open = icosphere(1, 0.5);
  open.triangles.pop_back();
  try {
    tetrahedralize_surface(open, TetSettings{}, "scene.json", "/objects/2");
    FAIL() << "no error";
  } catch (const UserError& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find("scene.json"), std::string::npos) << msg;
    EXPECT_NE(msg.find("/objects/2"), std::string::npos) << msg;
    EXPECT_NE(msg.find("must be closed"), std::string::npos) << msg;
  }
}

TEST(TetComplex, ATetrahedralizationPastItsTimeLimitIsStoppedAndRefusedNamingTheKnob) {
  // TetGen looped for ever on a grown interface folded within rounding; the child it runs in
  // is killed at the limit. A limit far below what the mesh needs stands in for that here.
  TetSettings s;
  s.time_limit = 1e-4;
  const auto start = std::chrono::steady_clock::now();
  try {
    tetrahedralize_surface(icosphere(5, 0.5), s, "scene.json", "/objects/0/growth");
    FAIL() << "no error";
  } catch (const UserError& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find("/objects/0/growth"), std::string::npos) << msg;
    EXPECT_NE(msg.find("did not finish within 0.0001 s"), std::string::npos) << msg;
    EXPECT_NE(msg.find("time_limit"), std::string::npos) << msg;
  }
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 5.0);
  // The same mesh with the default limit is made.
  EXPECT_GT(tetrahedralize_surface(icosphere(5, 0.5), TetSettings{}, "scene.json", "/objects/0/growth").tets.size(), 1000u);
}
