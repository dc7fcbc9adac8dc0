#include "renderer/scene_dicing.h"

#include <cmath>

namespace phellem {

DicedMeshes dice_jobs(const std::vector<DicingJob>& jobs, DicingParams dicing, long long max_triangles, Progress& progress) {
  DicedMeshes out;
  if (jobs.empty()) return out;
  auto with_refine = [&](const DicingJob& j) {
    DicingParams dj = dicing;
    dj.refine_edge = j.refine;
    return dj;
  };
  for (int iter = 0; iter < 8; ++iter) {
    long long estimate = 0;
    for (const auto& j : jobs)
      estimate += !j.base       ? estimate_triangles(j.surface, dicing)
                  : j.bark_disp ? estimate_triangles(*j.base, j.bark_disp, with_refine(j))
                                : estimate_triangles(*j.base, j.disp, dicing);
    if (estimate <= max_triangles) break;
    const float grow = std::sqrt(float(estimate) / float(max_triangles)) * 1.05f;
    dicing.scale *= grow;
    out.dicing_scale *= grow;
  }
  out.meshes.reserve(jobs.size());
  for (const auto& j : jobs) {
    out.meshes.push_back(!j.base       ? dice(j.surface, dicing)
                         : j.bark_disp ? dice(*j.base, j.bark_disp, with_refine(j), true)
                                       : dice(*j.base, j.disp, dicing));
    progress.advance();
  }
  return out;
}

}  // namespace phellem
