// A flat patch of stress-model bark as a height field: a jittered sheet the size of the photo
// plus a margin, remeshed as a scene's preprocessing does, cracked (Spicker 2014), and its
// crack V-profiles (bark/dressing/crack_profile.h) sampled at every pixel, z = −depth.
#pragma once

#include <cstdint>

#include "bark/dressing/crack_profile.h"
#include "bark/stress/stress_params.h"
#include "compare/height_field.h"
#include "compare/patch_size.h"

namespace phellem {

struct StressPatchParams {
  bark::StressParams params;  // the seed is set by stress_patch
  double edge_length = 0.01;  // preprocessing target edge length (m)
  double jitter = 0.3;        // preprocessing jitter (fraction of the edge length)
  CrackLook look;
};

inline constexpr double kStressPatchMarginM = 0.05;

// Throws bark::StressParamError / bark::MeshError for parameters the model refuses.
HeightField stress_patch(const StressPatchParams& p, const PatchSize& size, uint64_t seed);

}  // namespace phellem
