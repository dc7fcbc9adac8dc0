// Displacement functions for the displacement hook of the tessellator: procedural (grooves,
// noise) or a height map image (scene/displacement_map.h). The bark models add their own
// (FractureField / CrackedMesh) on top.
#pragma once

#include "bark/geometry/tessellation.h"
#include "scene/scene_desc.h"

namespace phellem {

// Displacement d(uv, p) in metres along the normal. For trees, uv = (θ / 2π, arc length in
// metres) so that the pattern is seamless around the trunk; for meshes and patches, and for an
// image on a tree (TreeDesc::texture_displacement), uv = texcoords.
DisplacementFn make_displacement(const DisplacementDesc& d);
DisplacementFn zero_displacement();

}  // namespace phellem
