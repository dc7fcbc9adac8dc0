// How finely displaced surfaces are diced for a scene: the renderer's tessellation and the
// memory estimate's triangle count use the same rates.
#pragma once

#include "bark/geometry/tessellation.h"
#include "scene/scene_desc.h"

namespace phellem {

// The dicing rates of a scene for a camera of `height` pixels (the scene's own dicing camera
// when it names one).
DicingParams dicing_params(const TessellationDesc& tess, const CameraDesc& camera, int height);

}  // namespace phellem
