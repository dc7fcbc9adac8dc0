// Unidirectional path tracing with next-event estimation and multiple importance sampling
// (Veach 1997, power heuristic) for every light type, Russian roulette, tiled over TBB.
#pragma once

#include "io/film.h"
#include "renderer/camera.h"
#include "renderer/render_scene.h"

namespace phellem {

struct RenderSettings {
  int spp = 16;
  int max_depth = 8;
  uint64_t seed = 0;  // folded to the sampler's 32 bits by fold_seed (identity below 2^32)
  FilterDesc filter;
  int threads = 0;  // 0: all cores
  bool progress = false;
  std::string progress_label = "render";
};

// A scene's render settings (spp, max_depth, seed, filter) on all cores, no progress.
RenderSettings render_settings(const RenderDesc& r);

struct RenderResult {
  Film film;
  long long rays = 0;             // camera + bounce + shadow rays traced
  long long invalid_samples = 0;  // NaN/Inf path contributions discarded
  double seconds = 0;
};

RenderResult render_image(const RenderScene& scene, const Camera& camera, int width, int height, const RenderSettings& s);

}  // namespace phellem
