// A scene `tree` object as parametric surfaces: one displaced generalized cylinder for the
// trunk and one per branch (recursively), ready for the adaptive tessellator.
#pragma once

#include <memory>
#include <vector>

#include "bark/geometry/generalized_cylinder.h"
#include "bark/geometry/tessellation.h"
#include "scene/scene_desc.h"

namespace phellem {

struct TreePart {
  std::shared_ptr<const bark::GeneralizedCylinder> cylinder;
  ParametricSurface surface;  // u = θ / 2π (periodic), v = s
  int parent = -1;            // index of the parent part (-1: the trunk)
  float attach = 0;           // where it leaves the parent (fraction of its length)
};

// Displacement uv for trees is (θ / 2π, arc length in metres) so patterns have constant
// density along trunks of varying length. The tree's image displacement
// (TreeDesc::texture_displacement) is added at the texcoords, as the albedo is looked up.
std::vector<TreePart> build_tree(const TreeDesc& desc, const DisplacementFn& displacement);
// The same with one displacement per part (index in the returned order: trunk, then the
// branches depth-first).
std::vector<TreePart> build_tree(const TreeDesc& desc, const std::function<DisplacementFn(size_t part)>& displacement);

}  // namespace phellem
