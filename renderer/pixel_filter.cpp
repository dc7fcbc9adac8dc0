#include "renderer/pixel_filter.h"

namespace phellem {

PixelFilter::PixelFilter(const FilterDesc& desc) : desc_(desc), radius_(desc.radius) {
  const int n = 512;
  std::vector<float> f(n);
  for (int i = 0; i < n; ++i) f[i] = evaluate(((i + 0.5f) / n * 2.0f - 1.0f) * radius_);
  dist_ = Distribution1D(std::move(f));
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
  float pdf;
  const float x = dist_.sample(u.x(), &pdf);
  const float y = dist_.sample(u.y(), &pdf);
  return Vec2f((2 * x - 1) * radius_, (2 * y - 1) * radius_);
}

}  // namespace phellem
