// A scene `tree` object as parametric surfaces: one displaced generalized cylinder for the
// trunk and one per branch (recursively), ready for the adaptive tessellator.
#pragma once

#include <memory>
#include <vector>

#include "bark/geometry/generalized_cylinder.h"
#include "renderer/scene_desc.h"
#include "renderer/tessellation.h"

namespace phellem {

struct TreePart {
  std::shared_ptr<const bark::GeneralizedCylinder> cylinder;
  ParametricSurface surface;  // u = θ / 2π (periodic), v = s
};

// Displacement uv for trees is (θ / 2π, arc length in metres) so patterns have constant
// density along trunks of varying length.
std::vector<TreePart> build_tree(const TreeDesc& desc, const DisplacementFn& displacement);

}  // namespace phellem
