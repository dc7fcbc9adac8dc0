// What every rendering command loads first: the scene (or the embedded default) and the
// render settings with the command line's overrides.
#pragma once

#include "cli/options.h"
#include "io/image_output.h"
#include "renderer/camera.h"
#include "renderer/integrator.h"
#include "scene/scene_desc.h"

namespace phellem {

struct Loaded {
  SceneDesc desc;
  RenderSettings settings;
  int width = 0, height = 0;
};

// Throws UserError when the scene and the film would not fit in the memory budget
// (cli/memory_check.h), before any stage runs.
Loaded load(const cli::Options& o);
// An unknown --view is a UserError before any work starts.
void check_view(const cli::Options& o);
// The camera as a render's EXR header states it (for `compare`, which pixels face it).
ExrCamera exr_camera(const Camera& camera);

}  // namespace phellem
