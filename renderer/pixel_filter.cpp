#include "renderer/pixel_filter.h"

namespace phellem {

PixelFilter::PixelFilter(const FilterDesc& desc) : desc_(desc), radius_(desc.radius) {
  // Tabulate the cdf finely, then invert it onto an evenly spaced table.
  const int n = 4096;
  std::vector<double> cdf(n + 1, 0.0);
  for (int i = 0; i < n; ++i) cdf[i + 1] = cdf[i] + evaluate(((i + 0.5f) / n * 2.0f - 1.0f) * radius_);
  for (auto& c : cdf) c /= cdf[n];
  const int m = 2048;
  inverse_cdf_.resize(m + 1);
  int j = 0;
  for (int k = 0; k <= m; ++k) {
    const double target = double(k) / m;
    while (j < n - 1 && cdf[j + 1] < target) ++j;
    const double w = cdf[j + 1] - cdf[j];
    const double f = w > 0 ? std::clamp((target - cdf[j]) / w, 0.0, 1.0) : 0.0;
    inverse_cdf_[k] = float((j + f) / n);
  }
}

float PixelFilter::evaluate(float x) const {
  const float t = std::abs(x) / radius_;
  if (t >= 1.0f) return 0.0f;
  switch (desc_.type) {
    case FilterType::Box:
      return 1.0f;
    case FilterType::Gaussian: {
      // σ = radius / 3, shifted to reach zero at the radius.
      const float s = radius_ / 3.0f;
      return std::max(0.0f, std::exp(-x * x / (2 * s * s)) - std::exp(-radius_ * radius_ / (2 * s * s)));
    }
    case FilterType::BlackmanHarris: {
      // 4-term Blackman–Harris window over [-radius, radius].
      const float p = kTwoPi * (0.5f + 0.5f * x / radius_);
      return 0.35875f - 0.48829f * std::cos(p) + 0.14128f * std::cos(2 * p) - 0.01168f * std::cos(3 * p);
    }
  }
  return 0.0f;
}

Vec2f PixelFilter::sample(const Vec2f& u) const {
  auto invert = [&](float v) {
    const float t = v * float(inverse_cdf_.size() - 1);
    const int i = std::min(int(t), int(inverse_cdf_.size()) - 2);
    const float f = t - float(i);
    return inverse_cdf_[i] * (1 - f) + inverse_cdf_[i + 1] * f;
  };
  return Vec2f((2 * invert(u.x()) - 1) * radius_, (2 * invert(u.y()) - 1) * radius_);
}

}  // namespace phellem
