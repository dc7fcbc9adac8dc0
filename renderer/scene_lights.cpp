#include "renderer/scene_lights.h"

#include <algorithm>
#include <cmath>

#include "scene/environment_image.h"
#include "util/errors.h"

namespace phellem {

std::vector<std::unique_ptr<Light>> make_lights(const SceneDesc& desc, std::vector<AreaLights::Triangle> area_triangles) {
  std::vector<std::unique_ptr<Light>> lights;
  for (const LightDesc& l : desc.lights) {
    switch (l.type) {
      case LightType::EnvironmentUniform:
        lights.push_back(std::make_unique<UniformEnvironment>(l.color * l.intensity));
        break;
      case LightType::EnvironmentMap: {
        int w, h;
        auto rgb = load_environment_image(l, &w, &h);
        lights.push_back(std::make_unique<EnvironmentMap>(std::move(rgb), w, h, l.intensity, l.rotation_deg));
        break;
      }
      case LightType::Sun:
        lights.push_back(std::make_unique<SunLight>(l.direction, l.irradiance, l.angle_deg, l.color));
        break;
      case LightType::Sky:
        lights.push_back(make_preetham_sky(l.direction, l.turbidity, l.sky_intensity.value_or(1.0f), l.ground_albedo));
        break;
    }
  }
  if (!area_triangles.empty()) lights.push_back(std::make_unique<AreaLights>(std::move(area_triangles)));
  return lights;
}

}  // namespace phellem
