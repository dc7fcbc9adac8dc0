// compare/gaussian_blur: the separable blur equals the direct 2-D convolution with clamped
// borders, keeps the sum of content away from the borders, and has radius ⌈4σ⌉.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "compare/gaussian_blur.h"

namespace phellem {
namespace {

// The textbook double sum over the (2r+1)² window, reading clamped pixels.
std::vector<double> direct_blur(const std::vector<double>& in, int w, int h, double sigma) {
  const int r = int(std::ceil(4 * sigma));
  double norm = 0;
  for (int dy = -r; dy <= r; ++dy)
    for (int dx = -r; dx <= r; ++dx) norm += std::exp(-(dx * dx + dy * dy) / (2 * sigma * sigma));
  std::vector<double> out(in.size());
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      double s = 0;
      for (int dy = -r; dy <= r; ++dy)
        for (int dx = -r; dx <= r; ++dx) {
          const int xx = std::clamp(x + dx, 0, w - 1), yy = std::clamp(y + dy, 0, h - 1);
          s += std::exp(-(dx * dx + dy * dy) / (2 * sigma * sigma)) * in[size_t(yy) * size_t(w) + size_t(xx)];
        }
      out[size_t(y) * size_t(w) + size_t(x)] = s / norm;
    }
  return out;
}

TEST(GaussianBlur, EqualsTheDirectTwoDimensionalConvolution) {
  const int w = 37, h = 23;  // smaller than the kernel in places: the clamping matters
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-1, 1);
  std::vector<double> in(size_t(w) * h);
  for (double& v : in) v = u(rng);
  for (double sigma : {0.6, 1.0, 2.5, 4.0}) {
    const std::vector<double> a = gaussian_blur(in, w, h, sigma), b = direct_blur(in, w, h, sigma);
    double worst = 0;
    for (size_t i = 0; i < in.size(); ++i) worst = std::max(worst, std::abs(a[i] - b[i]));
    EXPECT_LT(worst, 1e-12) << "sigma " << sigma;
  }
}

TEST(GaussianBlur, PreservesTheSumAwayFromTheBordersAndHasRadiusFourSigma) {
  const int w = 64, h = 64;
  std::vector<double> in(size_t(w) * h, 0.0);
  in[size_t(32) * w + 30] = 5;
  in[size_t(30) * w + 33] = -2;
  in[size_t(31) * w + 31] = 1.5;
  const std::vector<double> out = gaussian_blur(in, w, h, 3.0);
  double sum = 0;
  for (double v : out) sum += v;
  EXPECT_NEAR(sum, 4.5, 1e-12);
  EXPECT_EQ(gaussian_kernel(3.0).size(), 25u);  // radius ⌈12⌉
  EXPECT_EQ(gaussian_kernel(1.01).size(), 11u);  // radius ⌈4.04⌉ = 5
  // A single impulse spreads symmetrically and peaks where it was (a blur, not a shift).
  std::vector<double> one(size_t(w) * h, 0.0);
  one[size_t(32) * w + 32] = 1;
  const std::vector<double> g = gaussian_blur(one, w, h, 2.0);
  EXPECT_NEAR(g[size_t(32) * w + 29], g[size_t(32) * w + 35], 1e-15);
  EXPECT_NEAR(g[size_t(29) * w + 32], g[size_t(32) * w + 35], 1e-15);
  EXPECT_GT(g[size_t(32) * w + 32], g[size_t(32) * w + 33]);
  EXPECT_NEAR(g[size_t(32) * w + 32], 1 / (2 * 3.14159265358979 * 4), 2e-4);  // ≈ 1/(2πσ²)
}

}  // namespace
}  // namespace phellem
