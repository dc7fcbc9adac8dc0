// Image displacement (`"displacement": {"type": "image", ...}`) is true geometry: a known height
// map (a sine, a ramp) diced by the adaptive dicer and hit by rays lands on the analytic surface
// scale × (f(uv × uv_repeat) − midlevel) within 1e-4 m, on a patch (repeat and clamp) and on a
// tree's trunk (at its texture coordinates). The lookup itself is checked against hand
// interpolation, and a map that is misplaced by half a texel or flipped in v fails the bound.
#include <gtest/gtest.h>

#include <OpenImageIO/imageio.h>

#include <cmath>
#include <filesystem>

#include "renderer/render_scene.h"
#include "scene/displacement_map.h"
#include "scene/scene_parser.h"
#include "tests/support/test_util.h"

namespace phellem {
namespace {

constexpr int kMapSize = 256;

// f(u, v) with an integer number of periods along both axes, so that it tiles.
double sine_field(double u, double v) { return 0.5 + 0.3 * std::sin(2 * M_PI * 3 * u) + 0.15 * std::sin(2 * M_PI * 2 * v); }

// A map of f at the texel centres: row j holds v = 1 − (j + ½) / n (row 0 is the top).
template <class F>
std::vector<float> texels(F f, int n) {
  std::vector<float> z(size_t(n) * size_t(n));
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) z[size_t(j) * size_t(n) + size_t(i)] = float(f((i + 0.5) / n, 1.0 - (j + 0.5) / n));
  return z;
}

std::string write_map(const std::string& path, const std::vector<float>& z, int n, OIIO::TypeDesc type) {
  auto out = OIIO::ImageOutput::create(path);
  OIIO::ImageSpec spec(n, n, 1, type);
  EXPECT_TRUE(out && out->open(path, spec)) << path;
  std::vector<float> q = z;
  if (type == OIIO::TypeDesc::UINT16)
    for (float& x : q) x = std::round(x * 65535.0f) / 65535.0f;  // what the file will hold
  EXPECT_TRUE(out->write_image(OIIO::TypeDesc::FLOAT, q.data()));
  out->close();
  return path;
}

// The largest |z − expected(x, y)| of rays shot straight down at a grid over the patch's
// middle 90 %, and how many hit.
struct Hits {
  double max_error = 0;
  int hits = 0;
};
template <class F>
Hits shoot_down(const RenderScene& scene, double size, F expected) {
  Hits h;
  for (int j = 0; j < 41; ++j)
    for (int i = 0; i < 41; ++i) {
      const float x = float(size * (-0.45 + 0.9 * (i + 0.37) / 41)), y = float(size * (-0.45 + 0.9 * (j + 0.61) / 41));
      SurfaceHit hit;
      if (!scene.intersect(Ray{Vec3f(x, y, 1.0f), Vec3f(0, 0, -1)}, 10.0f, &hit)) continue;
      ++h.hits;
      h.max_error = std::max(h.max_error, std::abs(double(hit.p.z()) - expected(hit.p.x() / size + 0.5, hit.p.y() / size + 0.5)));
    }
  return h;
}

std::string patch_scene(const std::string& map, const std::string& extra) {
  return R"({"camera": {"position": [0, 0, 1], "look_at": [0, 0, 0], "fov_deg": 20},
    "render": {"resolution": [64, 64], "tessellation": {"mode": "object", "edge_length": 0.0005}},
    "objects": [{"type": "patch", "size": 0.2,
      "displacement": {"type": "image", "file": ")" +
         map + R"(", "scale": 0.01, "midlevel": 0.4)" + extra + "}}]}";
}

std::unique_ptr<RenderScene> build(const std::string& json) {
  const SceneDesc d = parse_scene(json, "<test>", ".");
  return build_render_scene(d, d.camera, d.render.width, d.render.height);
}

TEST(ImageDisplacement, LookupInterpolatesBetweenTexelCentres) {
  DisplacementMap m;
  m.width = 4;
  m.height = 2;
  m.value = {0, 1, 2, 3,   // top row (v = 0.75)
             10, 11, 12, 13};  // bottom row (v = 0.25)
  // Texel centres.
  EXPECT_FLOAT_EQ(sample_displacement_map(m, Vec2f(0.125f, 0.75f), false), 0.0f);
  EXPECT_FLOAT_EQ(sample_displacement_map(m, Vec2f(0.625f, 0.25f), false), 12.0f);
  // Half way between four centres.
  EXPECT_FLOAT_EQ(sample_displacement_map(m, Vec2f(0.25f, 0.5f), false), 5.5f);
  // Repeat: u = 0 is half way between the last and the first column; v = 0 between the rows.
  EXPECT_FLOAT_EQ(sample_displacement_map(m, Vec2f(0.0f, 0.75f), false), 1.5f);
  EXPECT_FLOAT_EQ(sample_displacement_map(m, Vec2f(0.0f, 0.0f), false), 6.5f);
  EXPECT_FLOAT_EQ(sample_displacement_map(m, Vec2f(1.125f, -0.75f), false), 10.0f);  // ≡ (0.125, 0.25)
  // Clamp: edges extend, never blend with the opposite side.
  EXPECT_FLOAT_EQ(sample_displacement_map(m, Vec2f(0.0f, 0.75f), true), 0.0f);
  EXPECT_FLOAT_EQ(sample_displacement_map(m, Vec2f(1.0f, 0.0f), true), 13.0f);
  EXPECT_FLOAT_EQ(sample_displacement_map(m, Vec2f(-3.0f, 9.0f), true), 0.0f);
}

TEST(ImageDisplacement, SineMapOnAPatchLandsOnTheAnalyticSurface) {
  const std::string dir = test::temp_dir("image_displacement_sine");
  const std::string map = write_map(dir + "/sine.exr", texels(sine_field, kMapSize), kMapSize, OIIO::TypeDesc::FLOAT);
  for (const float repeat : {1.0f, 2.0f}) {
    SCOPED_TRACE("uv_repeat " + std::to_string(repeat));
    auto scene = build(patch_scene(map, R"(, "uv_repeat": )" + std::to_string(repeat)));
    const Hits h = shoot_down(*scene, 0.2, [&](double u, double v) { return 0.01 * (sine_field(repeat * u, repeat * v) - 0.4); });
    EXPECT_EQ(h.hits, 41 * 41);
    EXPECT_LT(h.max_error, 1e-4);
    // The bound is tight enough to see a map misplaced by half a texel or flipped in v.
    const Hits shifted = shoot_down(*scene, 0.2, [&](double u, double v) {
      return 0.01 * (sine_field(repeat * u + 0.5 / kMapSize, repeat * v) - 0.4);
    });
    EXPECT_GT(shifted.max_error, 1e-4);
    const Hits flipped = shoot_down(*scene, 0.2, [&](double u, double v) { return 0.01 * (sine_field(repeat * u, 1 - repeat * v) - 0.4); });
    EXPECT_GT(flipped.max_error, 1e-3);
  }
}

TEST(ImageDisplacement, RampMapClampedAtItsEdges) {
  const std::string dir = test::temp_dir("image_displacement_ramp");
  const std::string map =
      write_map(dir + "/ramp.png", texels([](double u, double) { return u; }, kMapSize), kMapSize, OIIO::TypeDesc::UINT16);
  auto scene = build(patch_scene(map, R"(, "wrap": "clamp")"));
  const double lo = 0.5 / kMapSize, hi = 1 - lo;
  const Hits h = shoot_down(*scene, 0.2, [&](double u, double) { return 0.01 * (std::clamp(u, lo, hi) - 0.4); });
  EXPECT_EQ(h.hits, 41 * 41);
  EXPECT_LT(h.max_error, 1e-4);
  // At the very edge the clamped ramp keeps its value; repeating it would blend in the other end.
  SurfaceHit hit;
  ASSERT_TRUE(scene->intersect(Ray{Vec3f(-0.09999f, 0.0f, 1.0f), Vec3f(0, 0, -1)}, 10.0f, &hit));
  EXPECT_NEAR(hit.p.z(), 0.01 * (lo - 0.4), 1e-4);
  auto repeated = build(patch_scene(map, ""));
  ASSERT_TRUE(repeated->intersect(Ray{Vec3f(-0.09999f, 0.0f, 1.0f), Vec3f(0, 0, -1)}, 10.0f, &hit));
  EXPECT_NEAR(hit.p.z(), 0.01 * (0.5 - 0.4), 2e-4);  // half way between the first and last texel
}

// A vertical trunk of radius r: the map is looked up at the tree's texcoords
// (θ / 2π, arc length / circumference), so a map varying along v makes rings whose radius
// at height y is r + scale × (f(y / 2πr) − midlevel).
TEST(ImageDisplacement, TreeTakesTheMapAtItsTextureCoordinates) {
  const std::string dir = test::temp_dir("image_displacement_tree");
  auto rings = [](double, double v) { return 0.5 + 0.4 * std::sin(2 * M_PI * v); };
  const std::string map = write_map(dir + "/rings.exr", texels(rings, kMapSize), kMapSize, OIIO::TypeDesc::FLOAT);
  const double r = 0.1, circumference = 2 * M_PI * r;
  const std::string json = R"({"camera": {"position": [0, 0.3, 2], "look_at": [0, 0.3, 0], "fov_deg": 30},
    "render": {"resolution": [64, 64], "tessellation": {"mode": "object", "edge_length": 0.001}},
    "objects": [{"type": "tree", "axis": [[0, 0, 0], [0, 0.6, 0]], "radius": 0.1,
      "displacement": {"type": "image", "file": ")" + map + R"(", "scale": 0.02}}]})";
  auto scene = build(json);
  double max_error = 0;
  int hits = 0;
  for (int k = 0; k < 60; ++k) {
    const double y = 0.05 + 0.5 * (k + 0.5) / 60, phi = 2 * M_PI * k / 7.3;
    const Vec3f dir(float(-std::cos(phi)), 0.0f, float(-std::sin(phi)));
    SurfaceHit hit;
    if (!scene->intersect(Ray{Vec3f(0, float(y), 0) - 1.0f * dir, dir}, 2.0f, &hit)) continue;
    ++hits;
    const double radius = std::hypot(hit.p.x(), hit.p.z());
    max_error = std::max(max_error, std::abs(radius - (r + 0.02 * (rings(0, hit.p.y() / circumference) - 0.5))));
  }
  EXPECT_EQ(hits, 60);
  EXPECT_LT(max_error, 1e-4);
}

}  // namespace
}  // namespace phellem
