// Separable Gaussian blur of a raster (issue-22 plan §2/§3.1): the high-pass, the smoothing and
// the structure tensor window of the fissure statistics.
#pragma once

#include <vector>

namespace phellem {

// How pixels beyond the border are read.
enum class BlurBorder {
  clamp,    // the nearest border pixel (a a a | a b c)
  reflect,  // mirrored about the border's outer edge (c b a | a b c), scipy.ndimage's "reflect"
};

// `in` is height × width, row-major. Kernel: exp(−x²/2σ²) at integer offsets |x| ≤ ⌈4σ⌉,
// normalised to sum 1. σ ≤ 0 returns `in` unchanged.
std::vector<double> gaussian_blur(const std::vector<double>& in, int width, int height, double sigma_px,
                                  BlurBorder border = BlurBorder::clamp);

// The index `i` of a line of n pixels read with `border` (any i, also far outside).
int border_index(int i, int n, BlurBorder border);

// The normalised kernel, 2⌈4σ⌉ + 1 taps (exposed for the tests).
std::vector<double> gaussian_kernel(double sigma_px);

}  // namespace phellem
