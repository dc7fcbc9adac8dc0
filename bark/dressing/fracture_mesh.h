// The bark mesh with the fracture geometry inserted (Lefebvre & Neyret 2002, sec. 3.3; 2001
// sec. 5 "polygonisation"). Fracture silhouettes are the closed iso-contours of the rasterized
// skeleton (FractureField::opening = 1/2: the union of the linked trapezoids and tip caps, so
// connections and merges are already resolved), the depth iso-lines are contours of the depth
// profile, and a constrained Delaunay triangulation (CGAL) of the (θ, s) domain honours both.
// Each vertex then sinks by the field's depth.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "bark/strips/fracture_field.h"

namespace phellem::bark {

// Closed iso-contours of a field that is periodic across x (W columns, H rows, texel centres
// at (i + ½, j + ½)); outside the rows the field counts as below `level`, so every contour
// closes. Points are in texel units with x in [0, W); a loop may cross the seam x = 0 ≡ W.
// Saddles are resolved by the cell mean, so contours never cross each other.
std::vector<std::vector<Eigen::Vector2d>> contour_loops(const std::vector<float>& values, int W, int H, float level);

struct FractureMesh {
  int width = 0, height = 0;                              // the domain [0, W] × [0, H] in texel units
  std::vector<Eigen::Vector2d> param;                     // per vertex (x, y); x = W is the seam's right side
  std::vector<float> depth;                               // per vertex (m below the epidermis)
  std::vector<Eigen::Vector3i> triangles;                 // counter-clockwise in (x, y)
  std::vector<uint8_t> fracture;                          // per triangle: 1 inside a fracture silhouette
  std::vector<std::vector<Eigen::Vector2d>> silhouettes;  // the fracture polygons
};

// `depth_levels` are fractions of `max_depth` whose iso-lines become mesh edges; `grid` is the
// spacing (texels) of the Steiner points that keep flat bark triangles small enough to follow
// the cylinder.
FractureMesh mesh_fracture_field(const FractureField& field, double max_depth,
                                 const std::vector<double>& depth_levels = {0.25, 0.5, 0.75}, int grid = 8);

}  // namespace phellem::bark
