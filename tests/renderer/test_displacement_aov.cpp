// The `displacement` AOV: the first hit's offset along the undisplaced surface's normal. A flat
// sheet displaced by noise, seen from straight above, must show the displacement function at
// each pixel's hit points; undisplaced geometry and the background show 0.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "renderer/camera.h"
#include "scene/displacement.h"
#include "scene/scene_parser.h"
#include "tests/support/render_helpers.h"

namespace phellem {
namespace {

using test::render_json;

// A 1 m sheet (x, y ∈ [0, 1], z = 0) displaced by fBm noise of amplitude A = 2 cm, a sphere
// without displacement beside it, background around both; box filter so that every sample
// of a pixel stays inside the pixel.
const char* kSheetScene = R"({
  "camera": {"position": [0.6, 0.5, 2], "look_at": [0.6, 0.5, 0], "fov_deg": 45},
  "render": {"resolution": [96, 84], "spp": 4, "max_depth": 1, "seed": 5, "filter": "box"},
  "lights": [{"type": "sun", "direction": [0.3, 0.2, 1], "irradiance": 2}],
  "objects": [
    {"type": "mesh", "procedural": {"shape": "sheet", "height": 1, "triangles": 200},
     "displacement": {"type": "noise", "amplitude": 0.02, "frequency": 2, "seed": 9}},
    {"type": "sphere", "center": [1.3, 0.5, 0], "radius": 0.12}
  ]
})";

TEST(DisplacementAov, DisplacedSheetShowsTheDisplacementFunction) {
  const SceneDesc desc = parse_scene(kSheetScene, "<test>", ".");
  const DisplacementFn disp = make_displacement(desc.objects[0].displacement);
  const float A = desc.objects[0].displacement.amplitude;
  const auto r = render_json(kSheetScene);
  const Film& f = r.film;
  const Camera cam(desc.camera, f.width, f.height);
  auto d = [&](float u, float v) { return disp(Vec2f(u, v), Vec3f(u, v, 0)); };
  // The range of d over the sheet (a 1 mm grid, widened by 1 mm): every hit lies between
  // z = zlo and z = zhi.
  float zlo = 0, zhi = 0;
  for (int j = 0; j <= 1000; ++j)
    for (int i = 0; i <= 1000; ++i) zlo = std::min(zlo, d(i * 1e-3f, j * 1e-3f)), zhi = std::max(zhi, d(i * 1e-3f, j * 1e-3f));
  ASSERT_LT(zhi - zlo, 2 * A);
  zlo -= 1e-3f, zhi += 1e-3f;
  // The sheet's normal is ±z (its winding decides which): displaced points sit at z = s·D.
  int sheet = 0, sphere = 0, background = 0, sign_pos = 0, sign_neg = 0;
  float max_abs = 0, max_slack = 0, max_range = 0;
  for (int y = 0; y < f.height; ++y)
    for (int x = 0; x < f.width; ++x) {
      const size_t p = size_t(y) * f.width + x;
      const float D = f.displacement[p], id = f.object_id[p], pz = f.position[p * 3 + 2];
      if (id == 0 && f.beauty[p * 4 + 3] == 0) {
        EXPECT_EQ(D, 0.0f) << "background (" << x << ", " << y << ")";
        ++background;
        continue;
      }
      if (id == 2) {
        EXPECT_EQ(D, 0.0f) << "undisplaced sphere (" << x << ", " << y << ")";
        ++sphere;
        continue;
      }
      if (id != 1 || !test::interior_pixel(f, x, y)) continue;
      ++sheet;
      max_abs = std::max(max_abs, std::abs(D));
      // 1. Geometry and AOV agree: both are the same barycentric interpolation of the diced
      // vertices, so only the ray-hit rounding (float at t ≈ 2 m: ~1e-7 relative) separates them.
      if (std::abs(D) > 1e-3f) (pz * D > 0 ? sign_pos : sign_neg)++;
      EXPECT_NEAR(std::abs(pz), std::abs(D), 1e-5f) << "(" << x << ", " << y << ")";
      // 2. The AOV is the displacement function: every sample of the pixel hits a base point
      // inside the pixel's footprint on the sheet, the box through the pixel's corners between
      // the planes z = zlo and z = zhi (the hit lies between them; the sheet and ±z normals
      // either way). The AOV, a mean of samples of the diced surface, lies within the
      // function's range over that box, widened by the linear interpolation error of the
      // dicing: at most h²/8·|d''| for micro-edges h. Dicing at ≤ 1 px per edge keeps h below
      // the footprint's size n·hx, and the second difference over hx is hx²·d'', so the bound
      // is n²/8 times the largest second difference.
      float lo = 1e9f, hi = -1e9f, x0 = 1e9f, x1 = -1e9f, y0 = 1e9f, y1 = -1e9f;
      for (int c = 0; c < 4; ++c) {
        const Ray ray = cam.generate(Vec2f(float(x + (c & 1)), float(y + (c >> 1))), Vec2f(0.5f, 0.5f));
        for (float z : {zlo, zhi, -zlo, -zhi}) {
          const Vec3f q = ray.o + ray.d * ((z - ray.o.z()) / ray.d.z());
          x0 = std::min(x0, q.x()), x1 = std::max(x1, q.x()), y0 = std::min(y0, q.y()), y1 = std::max(y1, q.y());
        }
      }
      const int n = 8;
      const float hx = (x1 - x0) / n, hy = (y1 - y0) / n;
      float second = 0;
      for (int j = 0; j <= n; ++j)
        for (int i = 0; i <= n; ++i) {
          const float u = x0 + i * hx, v = y0 + j * hy, dv = d(u, v);
          lo = std::min(lo, dv), hi = std::max(hi, dv);
          second = std::max({second, std::abs(d(u - hx, v) - 2 * dv + d(u + hx, v)) * float(n * n) / 8,
                             std::abs(d(u, v - hy) - 2 * dv + d(u, v + hy)) * float(n * n) / 8});
        }
      const float slack = second + 1e-6f;
      max_slack = std::max(max_slack, slack), max_range = std::max(max_range, hi - lo);
      EXPECT_GE(D, lo - slack) << "(" << x << ", " << y << ") range [" << lo << ", " << hi << "]";
      EXPECT_LE(D, hi + slack) << "(" << x << ", " << y << ") range [" << lo << ", " << hi << "]";
    }
  std::printf("sheet %d px (max |D| %.4f m, footprint range <= %.2e m, slack <= %.2e m), sphere %d, background %d\n", sheet,
              max_abs, max_range, max_slack, sphere, background);
  EXPECT_GT(sheet, 1500);
  EXPECT_GT(sphere, 20);
  EXPECT_GT(background, 200);
  EXPECT_GT(max_abs, 0.3f * A);                                                   // the noise really moves the surface
  EXPECT_TRUE(sign_pos == 0 || sign_neg == 0) << sign_pos << " vs " << sign_neg;  // one normal side throughout
}

// Trees (diced parametric surfaces): grooves cut inwards by at most `amplitude`; the ground
// plane under the trunk is not displaced.
TEST(DisplacementAov, GroovedTrunkIsBetweenMinusAmplitudeAndZero) {
  const auto r = render_json(R"({
    "camera": {"position": [1.2, 1.0, 1.6], "look_at": [0, 0.8, 0], "fov_deg": 40},
    "render": {"resolution": [48, 64], "spp": 2, "max_depth": 1, "seed": 3, "filter": "box"},
    "objects": [
      {"type": "tree", "axis": [[0, -0.1, 0], [0, 1, 0], [0.05, 2, 0]], "radius": [0.3, 0.25, 0.2],
       "displacement": {"type": "grooves", "amplitude": 0.03, "frequency": 12}},
      {"type": "plane", "size": 30}
    ]
  })");
  const Film& f = r.film;
  int trunk = 0, ground = 0;
  float deepest = 0;
  // object_id is the first sample's: a ground pixel counts when it and its 8 neighbours are ground.
  auto all_ground = [&](int x, int y) {
    for (int dy = -1; dy <= 1; ++dy)
      for (int dx = -1; dx <= 1; ++dx)
        if (f.object_id[size_t(y + dy) * f.width + x + dx] != 2) return false;
    return true;
  };
  for (size_t p = 0; p < f.displacement.size(); ++p) {
    const int x = int(p % size_t(f.width)), y = int(p / size_t(f.width));
    if (x == 0 || y == 0 || x + 1 == f.width || y + 1 == f.height) continue;
    if (all_ground(x, y)) {
      EXPECT_EQ(f.displacement[p], 0.0f);
      ++ground;
    } else if (f.object_id[p] == 1 && f.beauty[p * 4 + 3] == 1) {
      ++trunk;
      EXPECT_LE(f.displacement[p], 1e-6f);
      EXPECT_GE(f.displacement[p], -0.03f - 1e-6f);
      deepest = std::min(deepest, f.displacement[p]);
    }
  }
  EXPECT_GT(trunk, 300);
  EXPECT_GT(ground, 100);
  EXPECT_LT(deepest, -0.01f);  // the furrows show
}

}  // namespace
}  // namespace phellem
