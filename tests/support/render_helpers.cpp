#include "tests/support/render_helpers.h"

#include "renderer/render_scene.h"
#include "scene/scene_parser.h"

namespace phellem::test {

RenderResult render_json(const std::string& json, int threads, const std::string& base_dir) {
  const SceneDesc d = parse_scene(json, "<test>", base_dir);
  const auto scene = build_render_scene(d, d.camera, d.render.width, d.render.height);
  RenderSettings s = render_settings(d.render);
  s.threads = threads;
  return render_image(*scene, Camera(d.camera, d.render.width, d.render.height), d.render.width, d.render.height, s);
}

bool interior_pixel(const Film& f, int x, int y) {
  if (x < 1 || y < 1 || x + 1 >= f.width || y + 1 >= f.height) return false;
  for (int dy = -1; dy <= 1; ++dy)
    for (int dx = -1; dx <= 1; ++dx)
      if (f.beauty[(size_t(y + dy) * f.width + x + dx) * 4 + 3] != 1.0f) return false;
  return true;
}

double mean_beauty(const Film& f, int c, float alpha) {
  double sum = 0;
  long n = 0;
  for (int y = 1; y + 1 < f.height; ++y)
    for (int x = 1; x + 1 < f.width; ++x) {
      bool ok = true;
      for (int dy = -1; dy <= 1 && ok; ++dy)
        for (int dx = -1; dx <= 1 && ok; ++dx) ok = f.beauty[(size_t(y + dy) * f.width + x + dx) * 4 + 3] == alpha;
      if (!ok) continue;
      sum += f.beauty[(size_t(y) * f.width + x) * 4 + c];
      ++n;
    }
  return n ? sum / n : -1.0;
}

}  // namespace phellem::test
