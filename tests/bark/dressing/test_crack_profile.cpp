// The V-profile of stress-bark cracks (Spicker 2014 sec. 4.2 as real geometry,
// bark/dressing/crack_profile.h): never deeper than the local thickness allows, fast on meshes
// far larger than their cracks, widened by the relaxation's gap (sec. 3.1.6).
#include <gtest/gtest.h>

#include "tests/bark/dressing/cracked_square.h"

#include <chrono>

#include "bark/dressing/crack_profile.h"

using namespace phellem;

TEST(CrackProfile, NeverDeeperThanAFractionOfTheLocalThickness) {
  // A closed slab 4 mm thick with a crack edge across its top face: the V-profile would carve
  // 1 cm, but the ray cast limits it to 45 % of the thickness; on a thick slab it is not limited.
  auto slab = [](double thickness) {
    bark::CrackedMesh c;
    const double h = thickness;
    c.mesh.positions = {{-0.05, -0.05, 0},  {0.05, -0.05, 0},  {0.05, 0.05, 0},  {-0.05, 0.05, 0},
                        {-0.05, -0.05, -h}, {0.05, -0.05, -h}, {0.05, 0.05, -h}, {-0.05, 0.05, -h},
                        {0.0, -0.05, 0},    {0.0, 0.05, 0}};         // 8, 9: the crack's ends on the top face
    c.mesh.triangles = {{0, 8, 9}, {0, 9, 3}, {8, 1, 2}, {8, 2, 9},  // top (+z), split along x = 0
                        {4, 6, 5}, {4, 7, 6},                        // bottom
                        {0, 4, 5}, {0, 5, 8}, {8, 5, 1}, {1, 5, 6}, {1, 6, 2},
                        {2, 6, 7}, {2, 7, 9}, {9, 7, 3}, {3, 7, 4}, {3, 4, 0}};
    c.crack_edges = {{8, 9}};
    c.crack_width.assign(c.mesh.positions.size(), 0.0f);
    c.crack_width[8] = c.crack_width[9] = 4;  // wide: half-width at the cap
    c.component.assign(c.mesh.positions.size(), -1);
    c.component[8] = c.component[9] = 0;
    c.displacement.assign(c.mesh.positions.size(), Eigen::Vector3f::Zero());
    return c;
  };
  CrackLook look;
  look.width_per_edge = 0.003f;
  look.max_width = 0.006f;
  look.depth_per_width = 2.0f;
  look.max_depth = 0.01f;
  look.noise = 0;
  const Vec3f on_crack(0.0f, 0.0f, 0.0f), up(0, 0, 1);
  const CrackProfile thin(slab(0.004), look, 1), thick(slab(0.1), look, 1);
  EXPECT_NEAR(thick.at(on_crack, up).depth, 0.01f, 1e-6f);  // min(max_depth, 2 × 6 mm)
  EXPECT_NEAR(thin.at(on_crack, up).depth, 0.45f * 0.004f, 2e-5f);
  // Away from the crack, nothing; half-way across its width, half the depth (V-profile).
  EXPECT_EQ(thick.at(Vec3f(0.02f, 0, 0), up).depth, 0.0f);
  EXPECT_NEAR(thick.at(Vec3f(0.003f, 0, 0), up).depth, 0.005f, 1e-5f);
}

TEST(CrackProfile, MeshFarLargerThanItsCracksAnswersAtOnce) {
  // A 100 km sheet with a crack along it: its segment would fill 10^13 grid cells of the crack's
  // width (and overflow their indices); such segments are visited by every query instead, and
  // a query box spanning too many cells visits every segment. (This hung: a fuzzed radius.)
  bark::CrackedMesh c;
  const double L = 1e5;
  c.mesh.positions = {{-L, -L, 0}, {L, -L, 0}, {L, L, 0}, {-L, L, 0}, {0.0, -L, 0}, {0.0, L, 0}};
  c.mesh.triangles = {{0, 4, 5}, {0, 5, 3}, {4, 1, 2}, {4, 2, 5}};
  c.crack_edges = {{4, 5}};
  c.crack_width = {0, 0, 0, 0, 1, 1};
  c.component = {-1, -1, -1, -1, 0, 0};
  c.displacement.assign(6, Eigen::Vector3f::Zero());
  CrackLook look;
  look.noise = 0;
  const auto start = std::chrono::steady_clock::now();
  const CrackProfile profile(c, look, 1);
  const Vec3f up(0, 0, 1);
  EXPECT_GT(profile.at(Vec3f(0, 1000, 0), up).depth, 0.0f);                    // on the crack, far along it
  EXPECT_EQ(profile.at(Vec3f(0.05f, 1000, 0), up).depth, 0.0f);                // 5 cm beside it
  EXPECT_TRUE(profile.reaches(Vec3f(-5e4f, 0, 0), Vec3f(5e4f, 0, 0)));         // an edge across it
  EXPECT_FALSE(profile.reaches(Vec3f(2e4f, -5e4f, 0), Vec3f(2e4f, 5e4f, 0)));  // a long one 20 km beside it
  EXPECT_FALSE(profile.reaches(Vec3f(1e3f, 0, 0), Vec3f(1e3f, 0.01f, 0)));     // a short one 1 km beside it
  EXPECT_TRUE(profile.reaches(Vec3f(0.001f, 0, 0), Vec3f(0.002f, 0, 0)));      // a short one on it
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 5.0);
}

TEST(CrackProfile, GapWidensByTheVirtualDisplacement) {
  // Sec. 3.1.6: the crack opens by the summed relaxation movement of its vertices. A crack of
  // Algorithm 1 width 1 (half-width 1 mm + 0.5 mm) whose ends moved 10 mm: with gap 0.2 the
  // half-width is 3.5 mm, so a point 2.5 mm off the crack is carved (depth × (1 − 2.5/3.5)).
  bark::CrackedMesh c = test::cracked_square();
  c.displacement[4] = c.displacement[5] = Eigen::Vector3f(0.006f, 0.008f, 0);  // 10 mm
  CrackLook look;
  look.min_width = 0.001f;
  look.width_per_edge = 0.0005f;
  look.max_width = 0.02f;
  look.depth_per_width = 1.0f;
  look.max_depth = 0.05f;
  look.noise = 0;
  const Vec3f off(0.0025f, 0, 0), up(0, 0, 1);
  EXPECT_EQ(CrackProfile(c, look, 1).at(off, up).depth, 0.0f);  // no gap: 1.5 mm wide, 2.5 mm away
  look.gap = 0.2f;
  EXPECT_NEAR(CrackProfile(c, look, 1).at(off, up).depth, 0.0035f * (1 - 2.5f / 3.5f), 1e-5f);
}
