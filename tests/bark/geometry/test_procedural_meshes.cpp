// Procedural meshes (bark/geometry/procedural_meshes.h): the log is a closed, consistently
// oriented surface once its seam copies are welded, with the volume of its cylinder.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <map>

#include "bark/geometry/procedural_meshes.h"

using namespace phellem::bark;

TEST(ProceduralMeshes, ALogIsClosedOrientedAndHasItsCylindersVolume) {
  for (int around : {6, 13, 40, 65}) {
    const double r = 0.1, h = 0.6;
    const TriMesh m = log_mesh(r, h, around, 17, 0.2, 3);
    // Weld by position (the side's seam copies), then every edge is used once each way.
    std::map<std::array<double, 3>, uint32_t> at;
    std::vector<uint32_t> id(m.positions.size());
    for (size_t i = 0; i < m.positions.size(); ++i)
      id[i] = at.emplace(std::array<double, 3>{m.positions[i].x(), m.positions[i].y(), m.positions[i].z()}, uint32_t(at.size()))
                  .first->second;
    std::map<std::pair<uint32_t, uint32_t>, int> directed;
    double volume = 0;
    for (const auto& t : m.triangles) {
      for (int e = 0; e < 3; ++e) ++directed[{id[t[size_t(e)]], id[t[size_t(e + 1) % 3]]}];
      volume += m.positions[t[0]].dot(m.positions[t[1]].cross(m.positions[t[2]])) / 6;
    }
    for (const auto& [e, n] : directed) {
      ASSERT_EQ(n, 1) << "around " << around << ": edge " << e.first << "-" << e.second;
      ASSERT_EQ(directed.count({e.second, e.first}), 1u) << "around " << around << ": edge " << e.first << "-" << e.second;
    }
    // The inscribed polygon's area × height (jitter moves side vertices within the surface).
    const double polygon = 0.5 * around * r * r * std::sin(2 * 3.141592653589793 / around);
    EXPECT_NEAR(volume, polygon * h, 0.03 * polygon * h) << "around " << around;
  }
}
