// TriMesh: an indexed triangle mesh as it comes from a file or a tessellator (DESIGN.md,
// bark/geometry): positions, optional per-vertex texture coordinates, triangles.
#pragma once

#include <Eigen/Core>
#include <array>
#include <cstdint>
#include <vector>

namespace phellem::bark {

struct TriMesh {
  std::vector<Eigen::Vector3d> positions;
  std::vector<Eigen::Vector2d> uvs;  // empty, or one per position
  std::vector<std::array<uint32_t, 3>> triangles;

  bool has_uvs() const { return !uvs.empty(); }
  double area() const;
};

// Barycentric coordinates of q's projection onto the plane of triangle (a, b, c), extrapolated
// outside it; (1, 0, 0) for a degenerate triangle.
Eigen::Vector3d barycentric(const Eigen::Vector3d& q, const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                            const Eigen::Vector3d& c);

// A triangle's area over its longest edge squared (at most √3/4 ≈ 0.43 for an equilateral
// one; 0 for collinear corners): the measure by which meshes are refused or repaired as
// degenerate.
double triangle_shape(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c);

}  // namespace phellem::bark
