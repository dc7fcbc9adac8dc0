#include "compare/colour_statistics.h"

#include <Eigen/Dense>

#include <cmath>

#include "compare/percentile.h"

namespace phellem {

Eigen::Vector3d linear_srgb_to_oklab(const Eigen::Vector3d& rgb) {
  // Ottosson 2020, the two matrices of the reference implementation (linear_srgb_to_oklab).
  static const Eigen::Matrix3d M1 = (Eigen::Matrix3d() << 0.4122214708, 0.5363325363, 0.0514459929,  //
                                     0.2119034982, 0.6806995451, 0.1073969566,                        //
                                     0.0883024619, 0.2817188376, 0.6299787005)
                                        .finished();
  static const Eigen::Matrix3d M2 = (Eigen::Matrix3d() << 0.2104542553, 0.7936177850, -0.0040720468,  //
                                     1.9779984951, -2.4285922050, 0.4505937099,                         //
                                     0.0259040371, 0.7827717662, -0.8086757660)
                                        .finished();
  const Eigen::Vector3d lms = M1 * rgb;
  const Eigen::Vector3d lms_ = lms.unaryExpr([](double v) { return std::cbrt(v); });
  return M2 * lms_;
}

ColourStats colour_statistics(const AlbedoField& albedo, const std::vector<uint8_t>& mask,
                              const std::vector<uint8_t>& ridge) {
  const size_t n = size_t(albedo.width) * size_t(albedo.height);
  std::vector<double> L(n), a(n), b(n), L_ridge, L_mask;
  for (size_t i = 0; i < n; ++i) {
    const Eigen::Vector3d lab = linear_srgb_to_oklab(
        Eigen::Vector3d(albedo.rgb[3 * i], albedo.rgb[3 * i + 1], albedo.rgb[3 * i + 2]));
    L[i] = lab[0];
    a[i] = lab[1];
    b[i] = lab[2];
    if (ridge[i]) L_ridge.push_back(lab[0]);
    if (mask[i]) L_mask.push_back(lab[0]);
  }
  ColourStats c;
  const MeanStd ml = mean_std(L), ma = mean_std(a), mb = mean_std(b);
  c.L_mean = ml.mean;
  c.L_std = ml.std;
  c.a_mean = ma.mean;
  c.a_std = ma.std;
  c.b_mean = mb.mean;
  c.b_std = mb.std;
  c.contrast = median(L_ridge) - median(L_mask);
  return c;
}

}  // namespace phellem
