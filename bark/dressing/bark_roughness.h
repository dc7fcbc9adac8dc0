// Roughness that varies over a bark surface (issue 22): the GGX roughness of the bark coat
// differs between the weathered ridges and the fresh, fibrous fissure interiors, and varies
// with noise. Off (ridge < 0) the material's own roughness is used everywhere.
#pragma once

#include <algorithm>
#include <cstdint>

namespace phellem::bark {

struct BarkRoughness {
  float ridge = -1;           // GGX roughness on the ridges (< 0: off)
  float fissure = -1;         // ... in the fissure interiors
  float noise = 0;            // relative variation: × (1 + noise · n), n ∈ [−1, 1]
  double noise_size = 0.01;   // m, the noise's feature size
  uint32_t seed = 1;
  bool enabled() const { return ridge >= 0; }
  // `fissure_weight` ∈ [0, 1] (coverage or normalized depth), `n` ∈ [−1, 1].
  float at(float fissure_weight, float n) const {
    const float r = ridge + std::clamp(fissure_weight, 0.0f, 1.0f) * (fissure - ridge);
    return std::clamp(r * (1.0f + noise * n), 0.0f, 1.0f);
  }
};

}  // namespace phellem::bark
