// Runs the cambial growth of one scene mesh object with `"growth"` (bark/growth/
// cambial_growth.h): its mesh in world space (file or procedural, the transform applied), the
// obstacles it names, the steps with a progress bar. Shared by `phellem simulate`,
// `phellem growth` (one frame per step it is asked for), `phellem slice` and the renderer's
// bark stage.
#pragma once

#include <functional>
#include <memory>

#include "bark/growth/cambial_growth.h"
#include "scene/scene_desc.h"

namespace phellem {

struct GrowthRun {
  std::shared_ptr<const bark::TriMesh> surface;  // the grown surface (world space, UVs when the input had them)
  std::shared_ptr<const bark::CrackedMesh> cracked;  // with stress bark (and cracks on): cracked as it grew
  std::vector<bark::GrowthRing> rings;
  bark::CambialGrowthStats stats;
  int steps = 0;
};

// The growth's surface and obstacles, tetrahedralized (TetGen) and ready to step, its cracks
// coupled when the object has stress bark; a progress line while TetGen runs when asked
// (errors name the scene).
bark::CambialGrowth start_growth(const SceneDesc& desc, size_t object_index, bool progress = false);

// All steps; `on_step(growth)` after each (time-lapse frames), when given.
GrowthRun run_growth_object(const SceneDesc& desc, size_t object_index, bool progress,
                            const std::function<void(const bark::CambialGrowth&)>& on_step = {});

// The current interface of a growth as a world-space mesh.
std::shared_ptr<const bark::TriMesh> grown_surface(const bark::CambialGrowth& g);

}  // namespace phellem
