#include "compare/structure_tensor.h"

#include <tbb/parallel_for.h>

#include <cmath>
#include <numbers>
#include <stdexcept>

#include "compare/gaussian_blur.h"

namespace phellem {

StructureTensor structure_tensor(const std::vector<double>& h, int width, int height, double sigma_px,
                                 BlurBorder border) {
  if (h.size() != size_t(width) * size_t(height) || width < 2 || height < 2)
    throw std::invalid_argument("structure_tensor: size mismatch or raster under 2×2");
  const size_t w = size_t(width);
  StructureTensor j;
  j.width = width;
  j.height = height;
  std::vector<double> xx(h.size()), yy(h.size()), xy(h.size());
  tbb::parallel_for(0, height, [&](int y) {
    const int y0 = y > 0 ? y - 1 : 0, y1 = y < height - 1 ? y + 1 : height - 1;
    for (int x = 0; x < width; ++x) {
      const int x0 = x > 0 ? x - 1 : 0, x1 = x < width - 1 ? x + 1 : width - 1;
      // Central difference inside, one-sided at the border (numpy.gradient).
      const double gx = (h[size_t(y) * w + size_t(x1)] - h[size_t(y) * w + size_t(x0)]) / double(x1 - x0);
      const double gy = (h[size_t(y1) * w + size_t(x)] - h[size_t(y0) * w + size_t(x)]) / double(y1 - y0);
      const size_t i = size_t(y) * w + size_t(x);
      xx[i] = gx * gx;
      yy[i] = gy * gy;
      xy[i] = gx * gy;
    }
  });
  j.xx = gaussian_blur(xx, width, height, sigma_px, border);
  j.yy = gaussian_blur(yy, width, height, sigma_px, border);
  j.xy = gaussian_blur(xy, width, height, sigma_px, border);
  return j;
}

double StructureTensor::fissure_angle_deg(size_t i) const {
  // Plan §3.3: the gradient's orientation is ½·atan2(2Jxy, Jxx − Jyy) (x right, y down); the
  // fissure runs across it (+90°); negating flips y to point up, and mod 180 folds directions.
  const double gradient = 0.5 * std::atan2(2 * xy[i], xx[i] - yy[i]);
  const double phi = (gradient + std::numbers::pi / 2) * (180 / std::numbers::pi);
  double a = std::fmod(-phi, 180.0);
  if (a < 0) a += 180;
  if (a >= 180) a -= 180;
  return a;
}

}  // namespace phellem
