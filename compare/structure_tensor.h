// The structure tensor of a raster and the fissure orientation it gives (issue-22 plan §3.3).
#pragma once

#include <cstddef>
#include <vector>

#include "compare/gaussian_blur.h"

namespace phellem {

// Orientation of the fissure (the level line, eigenvector of the smaller eigenvalue of J), in
// degrees in [0, 180), counter-clockwise from +x with y up: 90 = along the trunk. J's y runs
// down the rows.
double fissure_angle_deg(double jxx, double jyy, double jxy);

// The fissure angle at each of `pixels` (indices into h, height × width, row-major) from
// J = G(σ)∗(∇h ∇hᵀ), with ∇h by central differences (one-sided on the border, as numpy's
// gradient), in float. Only the window's column pass covers the raster; its row pass is
// evaluated at `pixels` alone (the skeleton is a few % of the pixels).
std::vector<double> fissure_angles_deg(const std::vector<float>& h, int width, int height, double sigma_px, BlurBorder border,
                                       const std::vector<size_t>& pixels);

}  // namespace phellem
