// Stage 4 of building a RenderScene (lights): the scene's lights (environment, sun, sky) and
// the emissive triangles gathered while the geometry was attached, as one list.
#pragma once

#include <memory>
#include <vector>

#include "renderer/light.h"
#include "scene/scene_desc.h"

namespace phellem {

// The scene's lights in order, then the area lights (if any triangle emits).
std::vector<std::unique_ptr<Light>> make_lights(const SceneDesc& desc, std::vector<AreaLights::Triangle> area_triangles);

}  // namespace phellem
