// Persistent texture coordinates under tangential motion (Kratt et al., Woodification,
// sec. 4.6): "When a vertex moves, we decompose the motion into the tangent and the bi-normal
// components, by using the Gram-Schmidt process, with respect to the vertex normal. Normal
// motion preserves texture coordinates, whereas tangential space spatial motion requires a
// proportional movement of the corresponding texture coordinates ... computed from the
// spatial motion using the texture Jacobian ∂u/∂x". A vertex that slides along the surface
// (growth turned by a stroke's direction, sec. 4.4) moves its UV with it, so the texture
// stays where it was on the surface instead of being dragged along.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include <Eigen/Core>

namespace phellem::bark {

using TextureGradient = Eigen::Matrix<double, 2, 3>;  // ∂u/∂x: a displacement on the surface to a UV change

// Per point, the area-weighted mean of its faces' ∂u/∂x (zero for points on no face). A face's
// is T (EᵀE)⁻¹ Eᵀ with E its edges from its first corner and T their UV differences, each UV
// difference taken to the nearest whole period (a face across a wrapped seam counts as the
// short stretch it is). Faces degenerate in space are skipped.
std::vector<TextureGradient> texture_gradients(const std::vector<Eigen::Vector3d>& points,
                                               const std::vector<Eigen::Vector2d>& uv,
                                               const std::vector<std::array<uint32_t, 3>>& faces);

// Per point, the unit surface directions in which u and v grow (the columns of ∂x/∂u, each
// face's E T⁻¹, normalised, area-weighted over the point's faces, normalised again; zero
// where no face gives one). The frame a direction painted in texture space (a flow map) is
// read in.
struct TextureAxes {
  Eigen::Vector3d u = Eigen::Vector3d::Zero(), v = Eigen::Vector3d::Zero();
};
std::vector<TextureAxes> texture_axes(const std::vector<Eigen::Vector3d>& points, const std::vector<Eigen::Vector2d>& uv,
                                      const std::vector<std::array<uint32_t, 3>>& faces);

// A direction painted in texture space, d = (along u, along v), as a vector on the surface:
// d.x·axes.u + d.y·axes.v, of d's length (a skewed map turns it, never lengthens it); zero
// where the axes are.
Eigen::Vector3d texture_direction(const TextureAxes& axes, const Eigen::Vector2d& d);

// Gram–Schmidt against the unit normal n: the tangential part of the move Δx, through the
// gradient, is the UV's move: uv + G (Δx − (Δx·n) n).
Eigen::Vector2d transported_uv(const Eigen::Vector2d& uv, const TextureGradient& g, const Eigen::Vector3d& move,
                               const Eigen::Vector3d& normal);

}  // namespace phellem::bark
