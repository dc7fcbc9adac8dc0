#include "compare/fissure_mask.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "compare/gaussian_blur.h"
#include "compare/percentile.h"

namespace phellem {

FissureMask fissure_mask(const std::vector<float>& z, int width, int height, double px_per_cm, const CompareParams& params) {
  FissureMask f;
  // Plan §3.1: the high-pass removes the trunk's shape and slow relief; the small smoothing
  // removes pixel noise (and JPEG blocks) before thresholding.
  f.hp = gaussian_blur(z, width, height, params.highpass_sigma_cm * px_per_cm, params.blur_border);  // low-pass
  for (size_t i = 0; i < z.size(); ++i) f.hp[i] = z[i] - f.hp[i];
  f.hs = gaussian_blur(f.hp, width, height, params.smooth_sigma_cm * px_per_cm, params.blur_border);
  // Threshold halfway between the typical surface (median) and the deepest 5 % (P5): both are
  // percentiles, so the mask does not change under an affine change of the heights.
  const std::vector<double> q = percentiles(f.hs, {params.threshold_percentile, 50});
  f.threshold = 0.5 * (q[1] + q[0]);
  std::vector<uint8_t> raw(z.size());
  for (size_t i = 0; i < z.size(); ++i) raw[i] = double(f.hs[i]) < f.threshold;
  // Drop 8-connected components under min_component_cm2 (pits, noise).
  const Components all = label_components(raw, width, height);
  std::vector<int64_t> area(size_t(all.count) + 1, 0);
  for (int32_t l : all.label) ++area[size_t(l)];
  const double min_area = params.min_component_cm2 * px_per_cm * px_per_cm;
  std::vector<int32_t> renumber(area.size(), 0);
  int kept = 0;
  for (size_t l = 1; l < area.size(); ++l)
    if (double(area[l]) >= min_area) renumber[l] = ++kept;
  f.mask.assign(z.size(), 0);
  f.components.label.assign(z.size(), 0);
  f.components.count = kept;
  for (size_t i = 0; i < z.size(); ++i) {
    const int32_t l = renumber[size_t(all.label[i])];
    f.components.label[i] = l;
    f.mask[i] = l > 0;
  }
  return f;
}

std::vector<uint8_t> ridge_mask(const std::vector<uint8_t>& mask, int width, int height, double px_per_cm,
                                const CompareParams& params) {
  const int k = std::max(1, int(std::lround(params.ridge_dilation_cm * px_per_cm)));
  // k dilations by the cross = city-block distance ≤ k, which two raster passes compute
  // exactly (Rosenfeld & Pfaltz 1966).
  const size_t w = size_t(width);
  constexpr int kFar = std::numeric_limits<int>::max() / 2;
  std::vector<int> d(mask.size());
  for (size_t i = 0; i < mask.size(); ++i) d[i] = mask[i] ? 0 : kFar;
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      int& v = d[size_t(y) * w + size_t(x)];
      if (x > 0) v = std::min(v, d[size_t(y) * w + size_t(x - 1)] + 1);
      if (y > 0) v = std::min(v, d[size_t(y - 1) * w + size_t(x)] + 1);
    }
  for (int y = height - 1; y >= 0; --y)
    for (int x = width - 1; x >= 0; --x) {
      int& v = d[size_t(y) * w + size_t(x)];
      if (x < width - 1) v = std::min(v, d[size_t(y) * w + size_t(x + 1)] + 1);
      if (y < height - 1) v = std::min(v, d[size_t(y + 1) * w + size_t(x)] + 1);
    }
  std::vector<uint8_t> ridge(mask.size());
  for (size_t i = 0; i < mask.size(); ++i) ridge[i] = d[i] > k;
  return ridge;
}

}  // namespace phellem
