// Stage 2 of building a RenderScene (tessellate): every displaced surface diced into
// micro-triangles, for one dicing camera (screen-space rates) or in object space, under the
// scene's triangle budget (coarsened uniformly until the estimate fits).
#pragma once

#include <vector>

#include "bark/geometry/mesh_data.h"
#include "renderer/scene_contents.h"
#include "scene/dicing_params.h"
#include "scene/scene_desc.h"
#include "util/progress.h"

namespace phellem {

struct DicedMeshes {
  std::vector<MeshData> meshes;  // one per job, in order
  float dicing_scale = 1.0f;     // > 1 when the triangle budget coarsened the dicing
};

// Dices `jobs`, advancing `progress` once per job.
DicedMeshes dice_jobs(const std::vector<DicingJob>& jobs, DicingParams dicing, long long max_triangles, Progress& progress);

}  // namespace phellem
