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
// normalised to sum 1. σ ≤ 0 returns `in` unchanged. T is float (the fissure statistics: every
// figure is a percentile or a ratio, and float moves none by 1e-6) or double.
template <class T>
std::vector<T> gaussian_blur(const std::vector<T>& in, int width, int height, double sigma_px,
                             BlurBorder border = BlurBorder::clamp);

// The two passes of gaussian_blur on their own, for a blur needed at a few pixels only (the
// structure tensor at the skeleton): the column pass of the whole raster, then the row pass at
// pixel x of one of its rows with the kernel gaussian_kernel(σ) (as T). Together they give
// gaussian_blur's value at that pixel, up to float rounding.
template <class T>
std::vector<T> gaussian_blur_columns(const std::vector<T>& in, int width, int height, double sigma_px,
                                     BlurBorder border = BlurBorder::clamp);
template <class T>
T gaussian_blur_row_at(const T* row, int width, int x, const std::vector<T>& kernel, BlurBorder border);

// The index `i` of a line of n pixels read with `border` (any i, also far outside).
int border_index(int i, int n, BlurBorder border);

// The normalised kernel, 2⌈4σ⌉ + 1 taps (exposed for the tests).
std::vector<double> gaussian_kernel(double sigma_px);

}  // namespace phellem
