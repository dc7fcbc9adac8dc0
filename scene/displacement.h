// Procedural displacement functions for the displacement hook of the tessellator.
// The bark models later replace these with displacement from FractureField / CrackedMesh.
#pragma once

#include "bark/geometry/tessellation.h"
#include "scene/scene_desc.h"

namespace phellem {

// Displacement d(uv, p) in metres along the normal. For trees, uv = (θ / 2π, arc length in
// metres) so that the pattern is seamless around the trunk; for meshes, uv = texcoords.
DisplacementFn make_displacement(const DisplacementDesc& d);

}  // namespace phellem
