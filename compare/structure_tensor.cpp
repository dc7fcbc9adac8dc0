#include "compare/structure_tensor.h"

#include <tbb/parallel_for.h>

#include <cmath>
#include <numbers>
#include <stdexcept>

namespace phellem {

double fissure_angle_deg(double jxx, double jyy, double jxy) {
  // Plan §3.3: the gradient's orientation is ½·atan2(2Jxy, Jxx − Jyy) (x right, y down); the
  // fissure runs across it (+90°); negating flips y to point up, and mod 180 folds directions.
  const double gradient = 0.5 * std::atan2(2 * jxy, jxx - jyy);
  const double phi = (gradient + std::numbers::pi / 2) * (180 / std::numbers::pi);
  double a = std::fmod(-phi, 180.0);
  if (a < 0) a += 180;
  if (a >= 180) a -= 180;
  return a;
}

std::vector<double> fissure_angles_deg(const std::vector<float>& h, int width, int height, double sigma_px, BlurBorder border,
                                       const std::vector<size_t>& pixels) {
  if (h.size() != size_t(width) * size_t(height) || width < 2 || height < 2)
    throw std::invalid_argument("fissure_angles_deg: size mismatch or raster under 2×2");
  const size_t w = size_t(width);
  std::vector<float> xx(h.size()), yy(h.size()), xy(h.size());
  tbb::parallel_for(0, height, [&](int y) {
    const int y0 = y > 0 ? y - 1 : 0, y1 = y < height - 1 ? y + 1 : height - 1;
    for (int x = 0; x < width; ++x) {
      const int x0 = x > 0 ? x - 1 : 0, x1 = x < width - 1 ? x + 1 : width - 1;
      // Central difference inside, one-sided at the border (numpy.gradient).
      const float gx = (h[size_t(y) * w + size_t(x1)] - h[size_t(y) * w + size_t(x0)]) / float(x1 - x0);
      const float gy = (h[size_t(y1) * w + size_t(x)] - h[size_t(y0) * w + size_t(x)]) / float(y1 - y0);
      const size_t i = size_t(y) * w + size_t(x);
      xx[i] = gx * gx;
      yy[i] = gy * gy;
      xy[i] = gx * gy;
    }
  });
  xx = gaussian_blur_columns(xx, width, height, sigma_px, border);
  yy = gaussian_blur_columns(yy, width, height, sigma_px, border);
  xy = gaussian_blur_columns(xy, width, height, sigma_px, border);
  const std::vector<double> kernel = gaussian_kernel(sigma_px);
  const std::vector<float> k(kernel.begin(), kernel.end());
  std::vector<double> angles(pixels.size());
  tbb::parallel_for(tbb::blocked_range<size_t>(0, pixels.size(), 1024), [&](const tbb::blocked_range<size_t>& r) {
    for (size_t n = r.begin(); n < r.end(); ++n) {
      const size_t row = pixels[n] / w * w;
      const int x = int(pixels[n] % w);
      auto at = [&](const std::vector<float>& j) { return double(gaussian_blur_row_at(&j[row], width, x, k, border)); };
      angles[n] = fissure_angle_deg(at(xx), at(yy), at(xy));
    }
  });
  return angles;
}

}  // namespace phellem
