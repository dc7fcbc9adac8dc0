// The same cracks in both renderers (issue 23): the preview's crack mask and distance against
// the path tracer's crack coverage and hit distance from unjittered primary rays through the
// pixel centres of the shared camera model, for stress bark and for strip bark.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "preview/preview_renderer.h"
#include "preview/preview_scene.h"
#include "renderer/camera.h"
#include "renderer/render_scene.h"
#include "scene/bark_results.h"
#include "scene/scene_parser.h"
#include "tests/preview/gl_context_for_tests.h"

using namespace phellem;
using namespace phellem::preview;

namespace {

struct Agreement {
  double iou = 0, median_depth_error = 1;
  int crack_pixels = 0, both_hit = 0;
};

Agreement compare_renderers(const std::string& json, int width, int height) {
  const SceneDesc desc = parse_scene(json, "scene.json", ".");
  const BarkResults bark = simulate_bark(desc, false);
  // The path tracer: unjittered primary rays through the pixel centres.
  const auto rs = build_render_scene(desc, bark, desc.camera, width, height);
  const Camera camera(desc.camera, width, height);
  // The preview, on the same camera model.
  const PreviewScene scene = build_preview_scene(desc, bark);
  PreviewRenderer renderer(scene);
  PreviewSettings settings;
  settings.target_near_px = 1.5f;
  const PreviewFrame f = renderer.render(camera.model(), settings);
  Agreement a;
  int inter = 0, uni = 0;
  std::vector<double> errors;
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const Ray ray = camera.generate(Vec2f(float(x) + 0.5f, float(y) + 0.5f), Vec2f(0, 0));
      SurfaceHit hit;
      const bool traced = rs->intersect(ray, std::numeric_limits<float>::infinity(), &hit);
      const size_t p = size_t(y) * size_t(width) + size_t(x);
      const bool previewed = std::isfinite(f.distance[p]);
      if (!traced || !previewed) continue;
      ++a.both_hit;
      const bool crack_pt = hit.crack_mask > 0.5f, crack_pv = f.mask[p] > 0.5f;
      inter += crack_pt && crack_pv;
      uni += crack_pt || crack_pv;
      a.crack_pixels += crack_pt;
      errors.push_back(std::abs(f.distance[p] - hit.t) / hit.t);
    }
  a.iou = uni > 0 ? double(inter) / uni : 0;
  ::testing::Test::RecordProperty("crack_pixels", a.crack_pixels);
  if (!errors.empty()) {
    std::nth_element(errors.begin(), errors.begin() + long(errors.size() / 2), errors.end());
    a.median_depth_error = errors[errors.size() / 2];
  }
  ::testing::Test::RecordProperty("iou", std::to_string(a.iou));
  ::testing::Test::RecordProperty("median_depth_error", std::to_string(a.median_depth_error));
  return a;
}

}  // namespace

TEST(PreviewVsPathTracer, StressBarkShowsTheSameCracksAtTheSamePixels) {
  PHELLEM_REQUIRE_GL();
  const Agreement a = compare_renderers(R"({
    "camera": {"position": [0.0, 0.3, 0.3], "look_at": [0, 0.3, 0], "fov_deg": 30},
    "render": {"resolution": [160, 160], "tessellation": {"mode": "object", "edge_length": 0.0008}},
    "objects": [{"type": "mesh",
      "procedural": {"shape": "trunk", "triangles": 6000, "radius": 0.1, "height": 0.6},
      "bark": {"model": "stress", "preset": "woodification", "iterations": 60, "alpha": 0.8, "seed": 5,
               "crack": {"width_per_edge": 0.002, "max_width": 0.008, "max_depth": 0.01, "depth_per_width": 1.5}}}]
  })", 160, 160);
  EXPECT_GT(a.both_hit, 160 * 160 / 3);
  EXPECT_GT(a.crack_pixels, 200);
  EXPECT_GE(a.iou, 0.9) << a.crack_pixels << " crack pixels";
  EXPECT_LT(a.median_depth_error, 0.01);
}

TEST(PreviewVsPathTracer, StripBarkShowsTheSameFracturesAtTheSamePixels) {
  PHELLEM_REQUIRE_GL();
  const Agreement a = compare_renderers(R"({
    "camera": {"position": [0.0, 0.5, 0.45], "look_at": [0, 0.5, 0], "fov_deg": 30},
    "render": {"resolution": [160, 160], "tessellation": {"mode": "object", "edge_length": 0.001}},
    "objects": [{"type": "tree", "axis": [[0, 0, 0], [0, 1.0, 0]], "radius": [0.1, 0.08],
      "bark": {"model": "strips", "preset": "furrowed", "steps": 250, "growth_rate": 1.0025, "strip_width": 0.006, "seed": 4,
               "depth": {"max_depth": 0.012, "depth_per_width": 1.2}}}]
  })", 160, 160);
  EXPECT_GT(a.both_hit, 160 * 160 / 3);
  EXPECT_GT(a.crack_pixels, 200);
  EXPECT_GE(a.iou, 0.9) << a.crack_pixels << " crack pixels";
  EXPECT_LT(a.median_depth_error, 0.01);
}
