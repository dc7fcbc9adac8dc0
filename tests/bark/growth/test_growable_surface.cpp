// What a surface must be to grow (bark/growth/growable_surface.h): an inside-out surface and a
// self-intersecting one are refused as UserErrors at the growth's path before TetGen runs,
// naming what is wrong (the winding; one pair of faces that intersect), and a valid 82k-triangle
// sphere passes the checks in a reasonable time.
#include <gtest/gtest.h>

#include <array>
#include <chrono>
#include <cstdio>
#include <map>
#include <string>

#include "bark/geometry/procedural_meshes.h"
#include "bark/growth/cambial_growth.h"
#include "bark/growth/growable_surface.h"
#include "util/errors.h"

using namespace phellem;
using namespace phellem::bark;

namespace {

CambialGrowthSettings short_growth() {
  CambialGrowthSettings s;
  s.steps = 2;
  s.function.thickness = 0.01f;
  s.tet.time_limit = 10;  // the old code handed a self-intersecting surface to TetGen, which may loop
  return s;
}

// The message of the UserError that starting a growth of `m` throws at (s.json,
// /objects/0/growth), or "" (with a failure) when it throws none or another.
std::string refusal(const TriMesh& m) {
  try {
    CambialGrowth g(m, {}, short_growth(), "s.json", "/objects/0/growth");
  } catch (const UserError& e) {
    const std::string what = e.what();
    EXPECT_EQ(what.rfind("s.json: /objects/0/growth: ", 0), 0u) << what;
    return what;
  }
  ADD_FAILURE() << "the growth started";
  return "";
}

TriMesh inverted(TriMesh m) {
  for (auto& t : m.triangles) std::swap(t[1], t[2]);
  return m;
}

// `b`'s triangles appended to `a`'s, as one mesh of two components.
TriMesh joined(TriMesh a, const TriMesh& b, const Eigen::Vector3d& shift) {
  const uint32_t n = uint32_t(a.positions.size());
  for (const auto& p : b.positions) a.positions.push_back(p + shift);
  for (const auto& uv : b.uvs) a.uvs.push_back(uv);
  for (const auto& t : b.triangles) a.triangles.push_back({t[0] + n, t[1] + n, t[2] + n});
  return a;
}

// The two face indices of "faces I and J intersect" in `what`, or {-1, -1}.
std::pair<long, long> named_faces(const std::string& what) {
  long i = -1, j = -1;
  const size_t at = what.find("faces ");
  if (at == std::string::npos || std::sscanf(what.c_str() + at, "faces %ld and %ld intersect", &i, &j) != 2) return {-1, -1};
  return {i, j};
}

}  // namespace

TEST(GrowableSurface, AnInsideOutSphereIsRefused) {
  const std::string what = refusal(inverted(icosphere(2, 0.5)));
  EXPECT_NE(what.find("the mesh is inside out (faces wound clockwise seen from outside)"), std::string::npos) << what;
}

TEST(GrowableSurface, OneInsideOutComponentAmongTwoIsRefused) {
  // Two spheres apart, the second wound the wrong way: their total volume is 0, each part's is not.
  const TriMesh two = joined(icosphere(2, 0.3), inverted(icosphere(2, 0.3)), {1, 0, 0});
  const std::string what = refusal(two);
  EXPECT_NE(what.find("inside out"), std::string::npos) << what;
  EXPECT_NE(what.find("its part with face 320 "), std::string::npos) << what;  // the second sphere's first face
}

TEST(GrowableSurface, ASurfaceFoldedThroughItselfIsRefusedNamingTwoFacesThatIntersect) {
  // A bow-tie: one vertex of a sphere pulled through the centre and out the other side, so
  // its fan of triangles crosses the far side. Closed, manifold, consistently wound.
  TriMesh m = icosphere(2, 0.5);
  m.positions[0] *= -1.5;
  const std::string what = refusal(m);
  EXPECT_NE(what.find("intersects itself"), std::string::npos) << what;
  const auto [i, j] = named_faces(what);
  ASSERT_GE(i, 0) << what;
  ASSERT_LT(i, j) << what;
  ASSERT_LT(j, long(m.triangles.size())) << what;
  // Only the moved vertex's triangles moved: every intersecting pair has one of them.
  auto has_moved_vertex = [&](long f) {
    for (uint32_t v : m.triangles[size_t(f)])
      if (m.positions[v] == m.positions[0]) return true;
    return false;
  };
  EXPECT_TRUE(has_moved_vertex(i) || has_moved_vertex(j)) << what;
}

TEST(GrowableSurface, TwoOverlappingSpheresAreRefused) {
  const std::string what = refusal(joined(icosphere(2, 0.5), icosphere(2, 0.5), {0.6, 0, 0}));
  EXPECT_NE(what.find("intersects itself: faces "), std::string::npos) << what;
}

TEST(GrowableSurface, An82kTriangleSphereIsCheckedInReasonableTime) {
  const TriMesh sphere = icosphere(6, 0.5);  // 81920 triangles
  ASSERT_EQ(sphere.triangles.size(), 81920u);
  // The icosphere's UV seam duplicates vertices; the check sees the welded mesh, as the growth does.
  TriMesh m;
  std::map<std::array<double, 3>, uint32_t> at;
  std::vector<uint32_t> index;
  for (const auto& p : sphere.positions) {
    const auto [it, added] = at.emplace(std::array<double, 3>{p.x(), p.y(), p.z()}, uint32_t(m.positions.size()));
    if (added) m.positions.push_back(p);
    index.push_back(it->second);
  }
  for (const auto& t : sphere.triangles) m.triangles.push_back({index[t[0]], index[t[1]], index[t[2]]});
  const auto t0 = std::chrono::steady_clock::now();
  EXPECT_NO_THROW(require_growable(m, "s.json", "/objects/0/growth"));
  const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  std::printf("closed, manifold, embedded and outward checks of 81920 triangles: %.3f s\n", s);
  // Measured 0.36-0.41 s beside 9.2 s of TetGen set-up for the same sphere (a machine loaded
  // about 6 times over): the checks cost a few per cent of the growth's start.
  EXPECT_LT(s, 20.0);
}
