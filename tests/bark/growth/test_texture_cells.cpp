// UV seams cut open (bark/geometry/uv_seams.h) and the texture cell levels of a grown surface
// (bark/growth/texture_cells.h; Kratt et al., Woodification, sec. 4.6).
#include <gtest/gtest.h>

#include <cmath>

#include "bark/geometry/procedural_meshes.h"
#include "bark/geometry/uv_seams.h"
#include "bark/growth/texture_cells.h"

namespace phellem::bark {
namespace {

// A closed-around tube (no caps) of `around` × `along` quads, u around (wrapping: the last
// column's faces go from u = (around-1)/around back to u = 0 on the first column's vertices),
// v along its length: as a growth holds a welded log.
TriMesh wrapped_tube(int around, int along, double radius, double height) {
  TriMesh m;
  for (int j = 0; j <= along; ++j)
    for (int i = 0; i < around; ++i) {
      const double a = 2 * M_PI * i / around;
      m.positions.emplace_back(radius * std::cos(a), height * j / along, -radius * std::sin(a));
      m.uvs.emplace_back(double(i) / around, double(j) / along);
    }
  for (int j = 0; j < along; ++j)
    for (int i = 0; i < around; ++i) {
      const uint32_t a = uint32_t(j * around + i), b = uint32_t(j * around + (i + 1) % around);
      const uint32_t c = a + uint32_t(around), d = b + uint32_t(around);
      m.triangles.push_back({a, b, d});
      m.triangles.push_back({a, d, c});
    }
  return m;
}

// The largest difference of u between a face's corners.
double max_u_span(const TriMesh& m) {
  double span = 0;
  for (const auto& f : m.triangles)
    for (int k = 1; k < 3; ++k) span = std::max(span, std::abs(m.uvs[f[k]].x() - m.uvs[f[0]].x()));
  return span;
}

TEST(UvSeams, FacesAcrossAWrappedSeamGetShiftedCopiesAndNothingElseChanges) {
  const TriMesh tube = wrapped_tube(16, 4, 0.1, 0.3);
  ASSERT_GT(max_u_span(tube), 0.9);  // the seam column spans the texture backwards
  std::vector<uint32_t> source;
  const TriMesh cut = cut_uv_seams(tube, &source);
  EXPECT_LT(max_u_span(cut), 1.0 / 16 + 1e-12);  // every face spans its own column of the grid
  // One copy per vertex on the seam's first column (5 rows), at u + 1 or the last column's at u − 1.
  EXPECT_EQ(cut.positions.size(), tube.positions.size() + 5);
  ASSERT_EQ(source.size(), cut.positions.size());
  for (size_t v = 0; v < cut.positions.size(); ++v) {
    EXPECT_EQ(cut.positions[v], tube.positions[source[v]]);
    const Eigen::Vector2d d = cut.uvs[v] - tube.uvs[source[v]];
    EXPECT_EQ(d.x(), std::round(d.x()));  // whole periods only
    EXPECT_EQ(d.y(), 0.0);
    if (v < tube.positions.size()) {
      EXPECT_EQ(source[v], v);
    }
  }
  ASSERT_EQ(cut.triangles.size(), tube.triangles.size());
  for (size_t f = 0; f < cut.triangles.size(); ++f)
    for (int k = 0; k < 3; ++k) EXPECT_EQ(source[cut.triangles[f][k]], tube.triangles[f][k]);
  // Cutting again changes nothing.
  EXPECT_EQ(cut_uv_seams(cut).positions.size(), cut.positions.size());
}

TEST(TextureCells, ALevelIsLog2OfTheStretchAlongEachAxisAndZeroWhereNothingGrew) {
  const TriMesh tube = wrapped_tube(32, 8, 0.1, 0.4);
  const TextureScaleField start(tube);  // seams cut inside
  EXPECT_NEAR(start.median().x(), 2 * 32 * 0.1 * std::sin(M_PI / 32), 1e-9);  // the polygon's perimeter per unit u
  EXPECT_NEAR(start.median().y(), 0.4, 1e-9);
  EXPECT_NEAR(start.at({0.99, 0.5}).x(), start.median().x(), 1e-9);  // in the seam's column
  EXPECT_NEAR(start.at({-0.01, 0.5}).x(), start.median().x(), 1e-9);  // a period away
  for (const auto& l : texture_cell_levels(cut_uv_seams(tube), start)) {
    EXPECT_NEAR(l.x(), 0.0f, 1e-9f);  // rounding of the Jacobians, no more
    EXPECT_NEAR(l.y(), 0.0f, 1e-9f);
  }
  // Girth ×2.5 (the cells around must repeat 2.5 times as often), length ×1.
  TriMesh grown = cut_uv_seams(tube);
  for (auto& p : grown.positions) p.x() *= 2.5, p.z() *= 2.5;
  const auto levels = texture_cell_levels(grown, start);
  ASSERT_EQ(levels.size(), grown.positions.size());
  // The vertex's mean Jacobian column spans its ring of faces, which turns by 2 × 360°/32
  // around this tube: the mean is shorter by about cos(11.25°/2)... at most 0.01 in level here.
  for (const auto& l : levels) {
    EXPECT_NEAR(l.x(), std::log2(2.5), 0.01);
    EXPECT_NEAR(l.y(), 0.0, 1e-6);
  }
  // Shrinking does not go below level 0; stretching beyond the chain stops at its top.
  TriMesh other = cut_uv_seams(tube);
  for (auto& p : other.positions) p.x() *= 0.5, p.z() *= 0.5, p.y() *= 1000;
  for (const auto& l : texture_cell_levels(other, start)) {
    EXPECT_EQ(l.x(), 0.0f);
    EXPECT_EQ(l.y(), float(kMaxTextureCellLevel));
  }
  // A parametrization that is not uniform (u crowded on one side of the tube): every face is
  // measured against where its UVs lay before, so girth ×2 is level 1 everywhere.
  TriMesh uneven = tube;
  for (auto& uv : uneven.uvs) uv.x() += 0.4 * std::sin(2 * M_PI * uv.x()) / (2 * M_PI);
  const TextureScaleField uneven_start(uneven);
  TriMesh doubled = cut_uv_seams(uneven);
  for (auto& p : doubled.positions) p.x() *= 2, p.z() *= 2;
  for (const auto& l : texture_cell_levels(doubled, uneven_start)) {
    EXPECT_NEAR(l.x(), 1.0, 0.01);
    EXPECT_NEAR(l.y(), 0.0, 1e-6);
  }
  // No UVs, or no start: no levels.
  TriMesh bare = tube;
  bare.uvs.clear();
  EXPECT_TRUE(texture_cell_levels(bare, start).empty());
  EXPECT_TRUE(texture_cell_levels(tube, TextureScaleField(bare)).empty());
}

}  // namespace
}  // namespace phellem::bark
