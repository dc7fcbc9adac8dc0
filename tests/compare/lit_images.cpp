#include "tests/compare/lit_images.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>

#include "compare/gaussian_blur.h"
#include "compare/percentile.h"
#include "tests/compare/synthetic_fields.h"

namespace phellem::test {
namespace {

LitImage from_log_luminance(int size, double px_per_cm, const std::vector<double>& l) {
  LitImage im{size, size, px_per_cm, std::vector<float>(3 * l.size()), {}};
  for (size_t i = 0; i < l.size(); ++i) {
    const double Y = 0.2 * std::exp(l[i]);
    im.rgb[3 * i] = im.rgb[3 * i + 1] = im.rgb[3 * i + 2] = float(Y);
  }
  return im;
}

}  // namespace

LitImage sine_stripes(int size, double px_per_cm, double period_px, double angle_deg, double amplitude) {
  const double a = angle_deg * std::numbers::pi / 180, sa = std::sin(a), ca = std::cos(a);
  std::vector<double> l(size_t(size) * size_t(size));
  for (int y = 0; y < size; ++y)
    for (int x = 0; x < size; ++x)
      l[size_t(y) * size_t(size) + size_t(x)] = amplitude * std::sin(2 * std::numbers::pi * (x * sa + y * ca) / period_px);
  return from_log_luminance(size, px_per_cm, l);
}

LitImage noise_picture(int size, double px_per_cm, double sigma_px, double amplitude, uint64_t seed) {
  HeightField n = smooth_noise(size, px_per_cm, sigma_px, seed);
  const MeanStd ms = mean_std(n.z);
  std::vector<double> l(n.z.size());
  for (size_t i = 0; i < l.size(); ++i) l[i] = amplitude * (n.z[i] - ms.mean) / ms.std;
  return from_log_luminance(size, px_per_cm, l);
}

LitImage bark_picture(int size, double px_per_cm, uint64_t seed) {
  const HeightField z = v_fissures(size, px_per_cm, size / 4, seed);
  const HeightField tint = smooth_noise(size, px_per_cm, 6, seed + 1);
  const MeanStd tint_ms = mean_std(tint.z);
  const double el = 30 * std::numbers::pi / 180;
  const double sun[3] = {std::cos(el), 0, std::sin(el)};
  LitImage im{size, size, px_per_cm, std::vector<float>(3 * z.z.size()), {}};
  for (int y = 0; y < size; ++y)
    for (int x = 0; x < size; ++x) {
      const double gx = 0.5 * (z.at(std::min(x + 1, size - 1), y) - z.at(std::max(x - 1, 0), y));
      const double gy = -0.5 * (z.at(x, std::min(y + 1, size - 1)) - z.at(x, std::max(y - 1, 0)));
      const double nx = -2 * gx, ny = -2 * gy, nn = std::sqrt(nx * nx + ny * ny + 1);
      const double shade = std::max(0.0, (nx * sun[0] + ny * sun[1] + sun[2]) / nn) + 0.05;
      const double h = z.at(x, y), t = (tint.at(x, y) - tint_ms.mean) / tint_ms.std;
      const double albedo = std::exp(2.0 * h);
      const size_t i = 3 * (size_t(y) * size_t(size) + size_t(x));
      im.rgb[i] = float(albedo * shade * (0.45 + 0.04 * t));
      im.rgb[i + 1] = float(albedo * shade * 0.33);
      im.rgb[i + 2] = float(albedo * shade * (0.24 - 0.03 * t));
    }
  return im;
}

LitImage exposed(const LitImage& im, float k) {
  LitImage o = im;
  for (float& v : o.rgb) v *= k;
  return o;
}

}  // namespace phellem::test
