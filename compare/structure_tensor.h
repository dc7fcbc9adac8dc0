// The structure tensor of a raster and the fissure orientation it gives (issue-22 plan §3.3).
#pragma once

#include <cstddef>
#include <vector>

#include "compare/gaussian_blur.h"

namespace phellem {

// J = G(σ)∗(∇h ∇hᵀ), with ∇h by central differences (one-sided on the border, as numpy's
// gradient). Components are height × width, row-major; y runs down the rows.
struct StructureTensor {
  int width = 0, height = 0;
  std::vector<double> xx, yy, xy;
  // Orientation of the fissure (the level line, eigenvector of the smaller eigenvalue) at pixel
  // i, in degrees in [0, 180), counter-clockwise from +x with y up: 90 = along the trunk.
  double fissure_angle_deg(size_t i) const;
};

StructureTensor structure_tensor(const std::vector<double>& h, int width, int height, double sigma_px,
                                 BlurBorder border);

}  // namespace phellem
