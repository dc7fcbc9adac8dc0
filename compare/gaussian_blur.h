// Separable Gaussian blur of a raster (issue-22 plan §2/§3.1): the high-pass, the smoothing and
// the structure tensor window of the fissure statistics.
#pragma once

#include <vector>

namespace phellem {

// `in` is height × width, row-major. Kernel: exp(−x²/2σ²) at integer offsets |x| ≤ ⌈4σ⌉,
// normalised to sum 1; pixels beyond the border take the value of the nearest border pixel
// (clamped). σ ≤ 0 returns `in` unchanged.
std::vector<double> gaussian_blur(const std::vector<double>& in, int width, int height, double sigma_px);

// The normalised kernel, 2⌈4σ⌉ + 1 taps (exposed for the tests).
std::vector<double> gaussian_kernel(double sigma_px);

}  // namespace phellem
