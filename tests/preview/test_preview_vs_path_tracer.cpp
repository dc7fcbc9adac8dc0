// The same cracks in both renderers (issue 23): the preview's crack mask and distance against
// the path tracer's crack coverage and hit distance from unjittered primary rays through the
// pixel centres of the shared camera model, for stress bark and for strip bark; the depth of a
// patch with an image displacement.
#include <gtest/gtest.h>

#include <OpenImageIO/imageio.h>

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
#include "tests/support/test_util.h"

using namespace phellem;
using namespace phellem::preview;

namespace {

struct Agreement {
  double iou = 0, median_depth_error = 1;
  int crack_pixels = 0, both_hit = 0;
};

// `preview_json`: the preview draws another scene (tests that the comparison can fail).
Agreement compare_renderers(const std::string& json, int width, int height, const std::string& preview_json = "") {
  const SceneDesc desc = parse_scene(json, "scene.json", ".");
  const BarkResults bark = simulate_bark(desc, false);
  const SceneDesc preview_desc = preview_json.empty() ? desc : parse_scene(preview_json, "preview.json", ".");
  // The path tracer: unjittered primary rays through the pixel centres.
  const auto rs = build_render_scene(desc, bark, desc.camera, width, height);
  const Camera camera(desc.camera, width, height);
  // The preview, on the same camera model.
  const PreviewScene scene = build_preview_scene(preview_desc, preview_json.empty() ? bark : simulate_bark(preview_desc, false));
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

// An image displacement (a PNG of bumps, 1.2 cm from trough to crest) on a patch: the preview's
// relief is at the path tracer's depth; drawn flat, the same patch is not.
TEST(PreviewVsPathTracer, AnImageDisplacedPatchIsAtTheSameDepth) {
  PHELLEM_REQUIRE_GL();
  const std::string dir = test::temp_dir("preview_vs_pt_patch");
  const int n = 64;
  std::vector<uint8_t> px(size_t(n) * n);
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i)
      px[size_t(j) * n + size_t(i)] = uint8_t(std::lround(127.5 + 127.0 * std::sin(2 * M_PI * 4 * i / n) * std::sin(2 * M_PI * 3 * j / n)));
  auto out = OIIO::ImageOutput::create(dir + "/bumps.png");
  ASSERT_TRUE(out);
  ASSERT_TRUE(out->open(dir + "/bumps.png", OIIO::ImageSpec(n, n, 1, OIIO::TypeDesc::UINT8)));
  ASSERT_TRUE(out->write_image(OIIO::TypeDesc::UINT8, px.data()));
  out->close();
  auto scene = [&](const std::string& displacement) {
    return R"({
      "camera": {"position": [0.08, 0.1, 0.3], "look_at": [0, 0, 0], "fov_deg": 40},
      "render": {"resolution": [120, 120], "tessellation": {"mode": "object", "edge_length": 0.0008}},
      "objects": [{"type": "patch", "center": [0, 0, 0], "normal": [0, 0, 1], "up": [0, 1, 0], "size": [0.25, 0.25])" +
           displacement + "}]}";
  };
  const std::string bumps =
      R"(, "displacement": {"type": "image", "file": ")" + dir + R"(/bumps.png", "scale": 0.012, "midlevel": 0.5, "uv_repeat": 1.5})";
  const Agreement a = compare_renderers(scene(bumps), 120, 120);
  const Agreement flat = compare_renderers(scene(bumps), 120, 120, scene(""));
  std::printf("  median relative depth difference %.3g (flat in the preview: %.3g) over %d pixels\n", a.median_depth_error,
              flat.median_depth_error, a.both_hit);
  EXPECT_GT(a.both_hit, 120 * 120 / 2);
  EXPECT_LT(a.median_depth_error, 1e-3);
  EXPECT_GT(flat.median_depth_error, 5 * a.median_depth_error);
}
