// Growth turned by a stroke's direction (Kratt et al., Woodification, sec. 4.4) and the UVs of
// vertices that slide (sec. 4.6, bark/growth/texture_transport.h).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "bark/geometry/procedural_meshes.h"
#include "bark/growth/cambial_growth.h"
#include "bark/growth/texture_transport.h"

namespace phellem::bark {
namespace {

TEST(GrowthDirection, AStrokeTurnsTheNormalTowardsItsDirectionByItsWeightAndNeverInwards) {
  GrowthFunction g;
  const Vec3f n(0, 1, 0);
  EXPECT_FALSE(g.has_directions());
  EXPECT_EQ(g.growth_direction({0, 0, 0}, n), n);
  g.strokes.push_back({{0, 0, 0}, 0.1f, 0.0f, Vec3f(1, 1, 0).normalized()});
  EXPECT_TRUE(g.has_directions());
  // At the stroke's point (w = 1): its direction.
  EXPECT_TRUE(g.growth_direction({0, 0, 0}, n).isApprox(Vec3f(1, 1, 0).normalized(), 1e-6f));
  // One standard deviation away (w = e^-1/2): the blend, normalized.
  const float w = std::exp(-0.5f);
  const Vec3f blend = ((1 - w) * n + w * Vec3f(1, 1, 0).normalized()).normalized();
  EXPECT_TRUE(g.growth_direction({0.1f, 0, 0}, n).isApprox(blend, 1e-5f));
  // Far away: the normal (to float precision).
  EXPECT_TRUE(g.growth_direction({5, 0, 0}, n).isApprox(n, 1e-6f));
  // A direction pointing inwards is held to kMinNormalShare of the normal, turned towards it.
  GrowthFunction in;
  in.strokes.push_back({{0, 0, 0}, 0.1f, 0.0f, Vec3f(1, -1, 0).normalized()});
  const Vec3f d = in.growth_direction({0, 0, 0}, n);
  EXPECT_NEAR(d.norm(), 1.0f, 1e-6f);
  EXPECT_NEAR(d.dot(n), GrowthFunction::kMinNormalShare, 1e-6f);
  EXPECT_GT(d.x(), 0.9f);
}

TEST(GrowthDirection, APaintedDirectionTurnsTheGrowthByItsLengthUpToOne) {
  const Vec3f n(0, 1, 0), t(1, 0, 0);
  // Zero: nothing turns.
  EXPECT_EQ(GrowthFunction::turned_towards(n, n, Vec3f::Zero()), n);
  // Length 0.5 along the tangent: halfway, (n + t)/√2.
  EXPECT_TRUE(GrowthFunction::turned_towards(n, n, 0.5f * t).isApprox(Vec3f(1, 1, 0).normalized(), 1e-6f));
  // Length 3: the whole way (weight clamped to 1), held to kMinNormalShare of the normal.
  const Vec3f d = GrowthFunction::turned_towards(n, n, 3.0f * t);
  EXPECT_NEAR(d.norm(), 1.0f, 1e-6f);
  EXPECT_NEAR(d.dot(n), GrowthFunction::kMinNormalShare, 1e-6f);
  EXPECT_GT(d.x(), 0.97f);
  // Length 1 along the normal itself: the normal.
  EXPECT_TRUE(GrowthFunction::turned_towards(n, n, n).isApprox(n, 1e-6f));
}

TEST(TextureTransport, ATangentialMoveMovesTheUvByTheTextureJacobianAndANormalOneDoesNot) {
  // A plane z = 0 with uv = (x / 4, y / 3) (a linear map: every face's ∂u/∂x is exact) and
  // a second patch across a wrapped seam in u.
  const std::vector<Eigen::Vector3d> p = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}};
  const std::vector<Eigen::Vector2d> uv = {{0, 0}, {0.25, 0}, {0, 1.0 / 3}, {0.25, 1.0 / 3}};
  const std::vector<std::array<uint32_t, 3>> faces = {{0, 1, 3}, {0, 3, 2}};
  const auto g = texture_gradients(p, uv, faces);
  TextureGradient expected;
  expected << 0.25, 0, 0, 0, 1.0 / 3, 0;
  for (const auto& gi : g) EXPECT_TRUE(gi.isApprox(expected, 1e-12)) << gi;
  const Eigen::Vector3d n(0, 0, 1);
  const Eigen::Vector2d moved = transported_uv(uv[3], g[3], {0.1, 0.2, 0.05}, n);
  EXPECT_NEAR(moved.x(), 0.25 + 0.025, 1e-12);
  EXPECT_NEAR(moved.y(), 1.0 / 3 + 0.2 / 3, 1e-12);
  EXPECT_EQ(transported_uv(uv[3], g[3], {0, 0, 0.3}, n), uv[3]);  // along the normal: kept
  // The same patch with u wrapped at a seam (0.9 → 1.15 stored as 0.9 → 0.15): the same gradient.
  const std::vector<Eigen::Vector2d> seam = {{0.9, 0}, {0.15, 0}, {0.9, 1.0 / 3}, {0.15, 1.0 / 3}};
  for (const auto& gi : texture_gradients(p, seam, faces)) EXPECT_TRUE(gi.isApprox(expected, 1e-12)) << gi;
}

TEST(TextureTransport, ADirectionPaintedInTextureSpaceLiesAlongTheSurfaceDirectionsOfUAndVWithItsLength) {
  // A plane z = 0 with uv = (x / 4, y / 3): u grows along +x, v along +y.
  const std::vector<Eigen::Vector3d> p = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}};
  const std::vector<Eigen::Vector2d> uv = {{0, 0}, {0.25, 0}, {0, 1.0 / 3}, {0.25, 1.0 / 3}};
  const std::vector<std::array<uint32_t, 3>> faces = {{0, 1, 3}, {0, 3, 2}};
  for (const TextureAxes& a : texture_axes(p, uv, faces)) {
    EXPECT_TRUE(a.u.isApprox(Eigen::Vector3d(1, 0, 0), 1e-12)) << a.u.transpose();
    EXPECT_TRUE(a.v.isApprox(Eigen::Vector3d(0, 1, 0), 1e-12)) << a.v.transpose();
    // Along u by 0.6 and against v by 0.3: that direction, length √0.45.
    EXPECT_TRUE(texture_direction(a, {0.6, -0.3}).isApprox(Eigen::Vector3d(0.6, -0.3, 0), 1e-12));
  }
  // Mirrored (u = 1 − x / 4), across a wrapped seam, and rotated a quarter in the plane (u
  // along +y, v along −x): the axes follow the parametrization, not the vertex order.
  const std::vector<Eigen::Vector2d> mirrored = {{0.05, 0}, {0.8, 0}, {0.05, 1.0 / 3}, {0.8, 1.0 / 3}};
  for (const TextureAxes& a : texture_axes(p, mirrored, faces)) EXPECT_TRUE(a.u.isApprox(Eigen::Vector3d(-1, 0, 0), 1e-12));
  const std::vector<Eigen::Vector2d> turned = {{0, 0}, {0, -0.25}, {1.0 / 3, 0}, {1.0 / 3, -0.25}};
  for (const TextureAxes& a : texture_axes(p, turned, faces)) {
    EXPECT_TRUE(a.u.isApprox(Eigen::Vector3d(0, 1, 0), 1e-12)) << a.u.transpose();
    EXPECT_TRUE(a.v.isApprox(Eigen::Vector3d(-1, 0, 0), 1e-12)) << a.v.transpose();
  }
  // A skewed map (v along the diagonal) turns a painted direction but keeps its length; a
  // point on no face, or a face with no texture area, has no axes and turns nothing.
  const std::vector<Eigen::Vector2d> skewed = {{0, 0}, {0.25, -0.25}, {0, 0.25}, {0.25, 0}};
  const auto s = texture_axes(p, skewed, faces);
  EXPECT_NEAR(texture_direction(s[0], {0.3, 0.4}).norm(), 0.5, 1e-12);
  const std::vector<Eigen::Vector2d> flat = {{0, 0}, {0, 0}, {0, 0}, {0, 0}};
  const auto none = texture_axes({p[0], p[1], p[2], p[3], {5, 5, 5}}, {flat[0], flat[1], flat[2], flat[3], {0, 0}}, faces);
  for (const TextureAxes& a : none) EXPECT_EQ(texture_direction(a, {1, 0}), Eigen::Vector3d::Zero());
}

// The icosphere's parametrization (procedural_meshes.h) at a direction: longitude, colatitude.
Eigen::Vector2d lat_long(const Eigen::Vector3d& p) {
  const Eigen::Vector3d v = p.normalized();
  return {0.5 + std::atan2(v.z(), v.x()) / (2 * M_PI), std::acos(std::clamp(v.y(), -1.0, 1.0)) / M_PI};
}

TEST(GrowthDirection, ASphereGrownWithATurningStrokeLeansThatWayAndItsSlidingVerticesCarryTheirUvs) {
  const TriMesh sphere = icosphere(3, 0.2);
  CambialGrowthSettings s;
  s.steps = 6;
  s.age_start = 0;
  s.age_end = 6;
  s.function.weibull_c = 1;
  s.function.age_scale = 6;
  s.function.thickness = 0.05f;
  // Points keep their index in the complex for good: each grown vertex that was there at the
  // start is followed by identity to where it started and the UV it had.
  struct Grown {
    GrowthSurface surface;
    std::vector<Eigen::Vector3d> start_points;
    std::vector<Eigen::Vector2d> start_uv;
    bool was_there(size_t v) const { return surface.point[v] < start_points.size(); }
    const Eigen::Vector3d& was(size_t v) const { return start_points[surface.point[v]]; }
  };
  const auto grow = [&](const std::vector<GrowthStroke>& strokes) {
    CambialGrowthSettings t = s;
    t.function.strokes = strokes;
    CambialGrowth g(sphere, {}, t, "s.json", "/objects/0/growth");
    Grown out{{}, g.complex().points, g.complex().uv};
    while (g.step()) EXPECT_EQ(g.complex().first_inverted(), -1);
    out.surface = extract_interface(g.complex());
    return out;
  };
  // On the equator at +x (far from the poles and the u seam), the growth turned upwards.
  const Eigen::Vector3d at(0.2, 0, 0);
  const Grown plain = grow({}), turned = grow({{at.cast<float>(), 0.06f, 0.0f, Vec3f(0, 1, 0)}});
  // The vertices that started near the stroke (followed by identity) rise with the turned
  // growth; with the plain growth they move out radially, as many up as down.
  const auto mean_rise_near = [&](const Grown& g) {
    double rise = 0;
    int n = 0;
    for (size_t v = 0; v < g.surface.mesh.positions.size(); ++v) {
      if (!g.was_there(v) || (g.was(v) - at).norm() > 0.06) continue;
      rise += g.surface.mesh.positions[v].y() - g.was(v).y();
      ++n;
    }
    EXPECT_GT(n, 5);
    return rise / std::max(1, n);
  };
  EXPECT_NEAR(mean_rise_near(plain), 0.0, 0.002);
  EXPECT_GT(mean_rise_near(turned), 0.008);
  // The sphere grows radially except where the stroke turns it: there the vertices slide up
  // the surface. The texture stays on the surface when their UVs follow (sec. 4.6): a slid
  // vertex's UV is then the sphere's parametrization at its new direction, not at its old one.
  const TriMesh& m = turned.surface.mesh;
  ASSERT_TRUE(m.has_uvs());
  double kept = 0, carried = 0;
  int n = 0;
  for (size_t v = 0; v < m.positions.size(); ++v) {
    if (!turned.was_there(v) || (turned.was(v) - at).norm() > 0.06) continue;
    ASSERT_LT((lat_long(turned.was(v)) - turned.start_uv[turned.surface.point[v]]).norm(), 1e-9);  // the identity holds
    const Eigen::Vector2d truth = lat_long(m.positions[v]);
    kept += (turned.start_uv[turned.surface.point[v]] - truth).norm();  // had the UV stayed with the vertex
    carried += (m.uvs[v] - truth).norm();
    ++n;
  }
  ASSERT_GT(n, 5);
  kept /= n, carried /= n;
  EXPECT_GT(kept, 0.005) << "the vertices barely slid";
  EXPECT_LT(carried, 0.3 * kept) << "kept " << kept << ", carried " << carried;
}

}  // namespace
}  // namespace phellem::bark
