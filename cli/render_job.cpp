#include "cli/render_job.h"

#include "cli/memory_check.h"
#include "io/image_output.h"
#include "scene/scene_parser.h"
#include "util/errors.h"

namespace phellem {

Loaded load(const cli::Options& o) {
  Loaded l{o.scene.empty() ? default_scene() : load_scene_file(o.scene), {}, 0, 0};
  const RenderDesc& r = l.desc.render;
  l.width = o.width.value_or(r.width);
  l.height = o.height.value_or(r.height);
  l.settings.spp = o.spp.value_or(r.spp);
  l.settings.max_depth = r.max_depth;
  l.settings.seed = o.seed.value_or(r.seed);
  l.settings.filter = r.filter;
  l.settings.threads = o.threads.value_or(0);
  l.settings.progress = !o.quiet;
  check_scene_memory(o, l.desc, l.width, l.height);
  return l;
}

ExrCamera exr_camera(const Camera& camera) { return {camera.position(), camera.model().view()}; }

void check_view(const cli::Options& o) {
  if (!o.view.empty()) require_view(o.view);
}

}  // namespace phellem
