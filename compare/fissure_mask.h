// The fissure mask of a normalised height field (issue-22 plan §3.1) and the ridge region
// that excludes its surroundings (§3.7).
#pragma once

#include <cstdint>
#include <vector>

#include "compare/compare_params.h"
#include "compare/connected_components.h"

namespace phellem {

struct FissureMask {
  std::vector<float> hp;      // high-pass z − G(σ_hp)∗z
  std::vector<float> hs;      // smoothed high-pass G(σ_s)∗hp
  double threshold = 0;       // ½(median(hs) + P5(hs))
  std::vector<uint8_t> mask;  // 1 = fissure: hs < threshold, small components dropped
  Components components;      // of `mask` (the kept components, renumbered)
};

// `z` is height × width (normalised heights, high = high) at `px_per_cm`.
FissureMask fissure_mask(const std::vector<float>& z, int width, int height, double px_per_cm, const CompareParams& params);

// Plan §3.7: NOT(mask dilated by max(1, round(dilation_cm · px_per_cm)) iterations of the
// 4-neighbour cross), i.e. the pixels farther than that city-block distance from any fissure.
std::vector<uint8_t> ridge_mask(const std::vector<uint8_t>& mask, int width, int height, double px_per_cm,
                                const CompareParams& params);

}  // namespace phellem
