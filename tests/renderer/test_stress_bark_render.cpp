// Stress-bark cracks in the path tracer (Spicker 2014 sec. 4.2 as real geometry): the surface
// is carved by the V-profiles (hits lie at the reported depth below the base surface), the
// crack AOV and the depth darkening agree with it, and crack-aware dicing refines only near
// the cracks.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "renderer/render_scene.h"
#include "scene/scene_parser.h"
#include "tests/support/render_helpers.h"

using namespace phellem;

namespace {

std::string trunk_scene(bool crack_aware) {
  return std::string(R"({
    "camera": {"position": [0, 0.3, 0.7], "look_at": [0, 0.3, 0], "fov_deg": 18},
    "render": {"resolution": [96, 96], "spp": 4, "max_depth": 2, "seed": 3,
               "tessellation": {"crack_aware": )") +
         (crack_aware ? "true" : "false") + R"(}},
    "lights": [{"type": "environment", "color": [1, 1, 1]}],
    "materials": {"bark": {"type": "diffuse", "base_color": [0.5, 0.5, 0.5]}},
    "objects": [{"type": "mesh", "material": "bark",
                 "procedural": {"shape": "trunk", "triangles": 20000, "radius": 0.1, "height": 0.6, "jitter": 0},
                 "bark": {"model": "stress", "preset": "woodification", "iterations": 60, "alpha": 0.8,
                          "crack": {"width_per_edge": 0.002, "max_width": 0.008, "max_depth": 0.01, "depth_per_width": 1.5,
                                    "noise": 0.2, "darkening": 0.6}}}]
  })";
}

}  // namespace

TEST(StressBarkRender, HitsLieAtTheCrackDepthAndTheAovAndDarkeningAgree) {
  const double R = 0.1, max_depth = 0.01;
  const RenderResult r = test::render_json(trunk_scene(true));
  const Film& f = r.film;
  std::vector<double> err;
  int cracked = 0, deep = 0, darker = 0;
  for (int y = 1; y < f.height - 1; ++y)
    for (int x = 1; x < f.width - 1; ++x) {
      if (!test::interior_pixel(f, x, y)) continue;  // keep silhouette pixels (partly sky) out
      const size_t p = size_t(y) * f.width + x;
      const double r_hit = std::hypot(f.position[3 * p], f.position[3 * p + 2]);
      const double mask = f.crack[2 * p], depth = f.crack[2 * p + 1];
      cracked += mask > 0.5;
      // The base is a prism of ~100 sides (its faces within 0.12 mm of R, 0.04 mm on average)
      // and the crack carves depth·max_depth into it.
      err.push_back(std::abs(r_hit - (R - depth * max_depth)));
      if (depth > 0.4) {
        ++deep;
        // Undisplaced, these would be off by at least 4 mm.
        EXPECT_LT(err.back(), 1.5e-3) << "pixel " << x << "," << y;
        // Albedo darkened by 0.6 × normalized depth (pixel averages of both are linear).
        EXPECT_NEAR(f.albedo[3 * p], 0.5 * (1 - 0.6 * depth), 0.03);
        darker += f.albedo[3 * p] < 0.45;
      } else if (mask == 0) {
        EXPECT_NEAR(f.albedo[3 * p], 0.5, 1e-3);
      }
    }
  ASSERT_GT(err.size(), 1000u);
  EXPECT_GT(cracked, 15);
  EXPECT_GT(deep, 3);
  EXPECT_EQ(darker, deep);
  std::sort(err.begin(), err.end());
  EXPECT_LT(err[err.size() / 2], 2e-4) << "median |r − (R − depth)| (m)";
  EXPECT_LT(err[err.size() * 95 / 100], 1e-3) << "95th percentile (m)";
}

TEST(StressBarkRender, CrackAwareDicingRefinesOnlyNearTheCracks) {
  auto diced = [](bool aware) {
    const SceneDesc d = parse_scene(trunk_scene(aware), "<test>", ".");
    return build_render_scene(d, d.camera, d.render.width, d.render.height)->stats().diced_triangles;
  };
  const long long aware = diced(true), uniform = diced(false);
  EXPECT_GT(aware, 20000);        // the cracks were refined
  EXPECT_LT(aware * 2, uniform);  // but not the rest of the trunk
}
