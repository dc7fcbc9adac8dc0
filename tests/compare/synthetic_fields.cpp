#include "tests/compare/synthetic_fields.h"

#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include "compare/gaussian_blur.h"

namespace phellem::test {

HeightField stripes(int size, double px_per_cm, double P, double W, double angle_deg, double offset_px) {
  HeightField f{size, size, px_per_cm, std::vector<float>(size_t(size) * size_t(size))};
  const double a = angle_deg * std::numbers::pi / 180;
  const double sa = std::sin(a), ca = std::cos(a);
  for (int y = 0; y < size; ++y)
    for (int x = 0; x < size; ++x) {
      double u = std::fmod(x * sa + y * ca - offset_px, P);
      if (u < 0) u += P;
      f.z[size_t(y) * size_t(size) + size_t(x)] = u < W ? -1.0f : 0.0f;
    }
  return f;
}

namespace {

std::vector<double> blurred_white_noise(int size, double sigma_px, std::mt19937_64& rng) {
  std::normal_distribution<double> normal(0, 1);
  std::vector<double> n(size_t(size) * size_t(size));
  for (double& v : n) v = normal(rng);
  return gaussian_blur(n, size, size, sigma_px);
}

}  // namespace

HeightField smooth_noise(int size, double px_per_cm, double sigma_px, uint64_t seed) {
  std::mt19937_64 rng(seed);
  const std::vector<double> n = blurred_white_noise(size, sigma_px, rng);
  return HeightField{size, size, px_per_cm, std::vector<float>(n.begin(), n.end())};
}

HeightField v_fissures(int size, double px_per_cm, int count, uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::vector<double> h = blurred_white_noise(size, 4, rng);
  for (double& v : h) v *= 0.6;
  std::uniform_real_distribution<double> centre(0, size), length(50, 200), width(3, 8);
  std::normal_distribution<double> tilt(0, 0.08);
  for (int k = 0; k < count; ++k) {
    const double cx = centre(rng), cy = centre(rng), L = length(rng), W = width(rng), t = tilt(rng);
    const int y0 = std::max(0, int(std::ceil(cy - L / 2))), y1 = std::min(size - 1, int(std::floor(cy + L / 2)));
    for (int y = y0; y <= y1; ++y) {
      if (!(std::abs(y - cy) < L / 2)) continue;
      const double xc = cx + t * (y - cy);
      for (int x = std::max(0, int(xc - W)); x <= std::min(size - 1, int(xc + W)); ++x)
        h[size_t(y) * size_t(size) + size_t(x)] -= std::max(0.0, 1 - std::abs(x - xc) / (W / 2));  // V profile
    }
  }
  return HeightField{size, size, px_per_cm, std::vector<float>(h.begin(), h.end())};
}

HeightField add(const HeightField& a, const HeightField& b, double k) {
  HeightField f = a;
  for (size_t i = 0; i < f.z.size(); ++i) f.z[i] = float(a.z[i] + k * b.z[i]);
  return f;
}

}  // namespace phellem::test
