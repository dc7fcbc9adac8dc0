// Pixel reconstruction by filter importance sampling (Ernst et al. 2006): camera rays are
// offset from the pixel centre with density proportional to the (separable, non-negative)
// filter, so every sample has weight 1 and pixels are plain averages.
#pragma once

#include "renderer/sampling.h"
#include "scene/scene_desc.h"

namespace phellem {

class PixelFilter {
 public:
  explicit PixelFilter(const FilterDesc& desc);
  // Offset from the pixel centre, in pixels, distributed ∝ filter(x)·filter(y).
  Vec2f sample(const Vec2f& u) const;
  float evaluate(float x) const;  // 1D profile (unnormalized)
  float radius() const { return radius_; }

 private:
  FilterDesc desc_;
  float radius_;
  std::vector<float> inverse_cdf_;  // x ∈ [0,1] at evenly spaced cdf values (O(1) sampling)
};

}  // namespace phellem
