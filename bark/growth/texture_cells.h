// Texture cells of a grown surface (Kratt et al., Woodification, sec. 4.6): "As the cambial
// surface grows, so will the texture Jacobian, which magnifies the texture. This growth is
// primarily due to the insertion of new cells of the same size, so cellular details in the
// base texture should not greatly expand. We realize this phenomenon with a mip-map of textures
// of increasing resolution that maintain a constant pixel resolution of cellular details."
//
// Here the chain's level L along an axis is the texture repeated 2^L times over the same span of
// texture coordinates (a tiling texture at 2^L times the resolution: the same cells, more of
// them). A face's level along u is log2 of how much the surface has stretched along u since the
// start at the same texture coordinates (the length of the texture Jacobian's column ∂x/∂u now
// over its length then, looked up where the face's UV centroid lay on the surface before it
// grew), the same along v; the renderer blends the two whole levels around it. A trunk that
// doubled its girth shows twice as many cells around, each as wide as before, and as many
// along its length.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "bark/geometry/tri_mesh.h"

namespace phellem::bark {

// The texture Jacobian's column lengths |∂x/∂u|, |∂x/∂v| (metres per unit of texture
// coordinate) of a surface before growth, looked up by texture coordinates.
class TextureScaleField {
 public:
  // `start`: the surface before growth, with UVs (seams are cut here). Without UVs, empty().
  explicit TextureScaleField(const TriMesh& start);
  bool empty() const { return faces_.empty(); }
  // The scales of the start face whose UVs contain `uv` (tried also a period away along u
  // and v, for wrapped parametrizations), else of the start face nearest it in UV (by its
  // UV centroid within the lookup cell and its neighbours), else the medians.
  Eigen::Vector2d at(const Eigen::Vector2d& uv) const;
  Eigen::Vector2d median() const { return median_; }

 private:
  struct Face {
    Eigen::Vector2d a, b, c;  // UVs
    Eigen::Vector2d scale;
  };
  std::vector<Face> faces_;
  Eigen::Vector2d lo_{0, 0}, cell_{1, 1};
  int nx_ = 0, ny_ = 0;
  std::vector<std::vector<uint32_t>> grid_;  // per cell, the faces whose UV box overlaps it (ascending)
  Eigen::Vector2d median_{0, 0};
  const Face* containing(const Eigen::Vector2d& uv) const;
};

// Per vertex of `m` (UV seams cut: uv_seams.h), the levels along u and v against `start`: the
// area-weighted mean of its faces' log2 stretch, then clamped to [0, kMaxTextureCellLevel].
// Empty without UVs or an empty start.
constexpr double kMaxTextureCellLevel = 8;
std::vector<Eigen::Vector2f> texture_cell_levels(const TriMesh& m, const TextureScaleField& start);

}  // namespace phellem::bark
