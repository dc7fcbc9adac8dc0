#include "cli/render_job.h"

#include <unistd.h>

#include <cstdio>

#include "util/errors.h"
#include "io/film.h"
#include "io/image_output.h"
#include "scene/scene_parser.h"

namespace phellem {

namespace {

void check_film_fits(const cli::Options& o, int width, int height) {
  // The film, and its copy as the output file's layers, must fit in memory: a film too large
  // is refused before any work, not killed by the system at the end of the render.
  const double needed = 2.0 * double(width) * double(height) * double(Film::kChannels * sizeof(float));
  const double physical = double(sysconf(_SC_PHYS_PAGES)) * double(sysconf(_SC_PAGE_SIZE));
  if (!(physical > 0) || needed <= physical) return;
  char what[256];
  std::snprintf(what, sizeof what, "a %dx%d film needs %.1f GiB of memory (%zu floats a pixel, and the output's copy), more than this machine's %.1f GiB",
                width, height, needed / 1073741824.0, Film::kChannels, physical / 1073741824.0);
  if (o.width) throw UserError("", "--res", what);
  throw UserError(o.scene, "/render/resolution", what);
}

}  // namespace

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
  check_film_fits(o, l.width, l.height);
  return l;
}

void check_view(const cli::Options& o) {
  if (!o.view.empty()) require_view(o.view);
}

}  // namespace phellem
