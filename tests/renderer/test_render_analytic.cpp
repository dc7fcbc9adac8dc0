// Rendering against analytic answers: white furnace, known irradiance, determinism.
#include <gtest/gtest.h>

#include "tests/support/render_helpers.h"

namespace phellem {
namespace {

using test::mean_beauty;
using test::render_json;

std::string furnace_scene(const std::string& material, int spp = 64) {
  return R"({
    "camera": {"position": [0, 0, 3.2], "look_at": [0, 0, 0], "fov_deg": 45},
    "render": {"resolution": [40, 40], "spp": )" +
         std::to_string(spp) + R"(, "max_depth": 64, "seed": 1},
    "lights": [{"type": "environment", "color": [1, 1, 1]}],
    "materials": {"m": )" +
         material + R"(},
    "objects": [{"type": "sphere", "center": [0, 0, 0], "radius": 1, "material": "m"}]
  })";
}

TEST(WhiteFurnace, DiffuseSphereRendersItsAlbedo) {
  const auto r = render_json(furnace_scene(R"({"type": "diffuse", "base_color": [0.8, 0.8, 0.8]})"));
  const double sphere = mean_beauty(r.film, 1, 1.0f), background = mean_beauty(r.film, 1, 0.0f);
  std::printf("furnace diffuse: sphere %.4f (expect 0.8), background %.4f (expect 1)\n", sphere, background);
  EXPECT_NEAR(sphere, 0.8, 0.01);
  EXPECT_NEAR(background, 1.0, 1e-6);
}

TEST(WhiteFurnace, BarkConductorAndDielectricNeverGainEnergy) {
  struct Case {
    const char* material;
    double lo, hi;
  } cases[] = {
      {R"({"type": "bark", "base_color": [1, 1, 1], "roughness": 0.4, "specular": 0.5})", 0.9, 1.01},
      {R"({"type": "conductor", "base_color": [1, 1, 1], "roughness": 0.5})", 0.85, 1.01},
      {R"({"type": "conductor", "base_color": [1, 1, 1], "roughness": 0.0})", 0.99, 1.01},
      {R"({"type": "dielectric", "roughness": 0.3, "ior": 1.5})", 0.85, 1.01},
      {R"({"type": "dielectric", "roughness": 0.0, "ior": 1.5})", 0.97, 1.01},
  };
  for (const auto& c : cases) {
    const auto r = render_json(furnace_scene(c.material, 128));
    const double v = mean_beauty(r.film, 1, 1.0f);
    std::printf("furnace %s: %.4f\n", c.material, v);
    EXPECT_GT(v, c.lo) << c.material;
    EXPECT_LT(v, c.hi) << c.material;
  }
}

std::string sun_plane_scene(const Vec3f& sun_dir, float angle_deg) {
  char buf[1024];
  std::snprintf(buf, sizeof buf, R"({
    "camera": {"position": [0, 3, 0.001], "look_at": [0, 0, 0], "fov_deg": 30},
    "render": {"resolution": [24, 24], "spp": 16, "max_depth": 4, "seed": 2},
    "lights": [{"type": "sun", "direction": [%f, %f, %f], "irradiance": 2.0, "angle_deg": %f}],
    "materials": {"m": {"type": "diffuse", "base_color": [0.5, 0.5, 0.5]}},
    "objects": [{"type": "plane", "point": [0, 0, 0], "normal": [0, 1, 0], "size": 100, "material": "m"}]
  })",
                sun_dir.x(), sun_dir.y(), sun_dir.z(), angle_deg);
  return buf;
}

TEST(AnalyticLighting, DiffusePlaneUnderPerpendicularSun) {
  // L = ρ E / π.
  const double expected = 0.5 * 2.0 / M_PI;
  for (float angle : {0.53f, 0.0f}) {
    const auto r = render_json(sun_plane_scene(Vec3f(0, 1, 0), angle));
    const double v = mean_beauty(r.film, 0, 1.0f);
    std::printf("sun %.2f deg perpendicular: %.5f (expect %.5f)\n", angle, v, expected);
    EXPECT_NEAR(v, expected, 0.005 * expected);
  }
}

TEST(AnalyticLighting, SunAtSixtyDegreesGivesHalf) {
  const double expected = 0.5 * 2.0 / M_PI * 0.5;
  const Vec3f dir(std::sin(radians(60.0f)), std::cos(radians(60.0f)), 0);
  const auto r = render_json(sun_plane_scene(dir, 0.53f));
  const double v = mean_beauty(r.film, 0, 1.0f);
  std::printf("sun at 60 deg: %.5f (expect %.5f)\n", v, expected);
  EXPECT_NEAR(v, expected, 0.005 * expected);
}

TEST(AnalyticLighting, UniformSkyOnPlaneGivesAlbedoTimesRadiance) {
  // A plane under a uniform environment L receives E = πL, so it shows ρL.
  const auto r = render_json(R"({
    "camera": {"position": [0, 1, 0.001], "look_at": [0, 0, 0], "fov_deg": 20},
    "render": {"resolution": [16, 16], "spp": 256, "max_depth": 2, "seed": 3},
    "lights": [{"type": "environment", "color": [2, 2, 2]}],
    "materials": {"m": {"type": "diffuse", "base_color": [0.25, 0.25, 0.25]}},
    "objects": [{"type": "plane", "point": [0, 0, 0], "normal": [0, 1, 0], "size": 1000, "material": "m"}]
  })");
  const double v = mean_beauty(r.film, 0, 1.0f);
  EXPECT_NEAR(v, 0.5, 0.01);
}

TEST(AnalyticLighting, AreaLightMatchesDiskFormula) {
  // A square emitter of radiance L, side 2a, at height h above the centre of a diffuse plane:
  // E = 4 L · (a / sqrt(a² + h²)) · atan(a / sqrt(a² + h²)) for a square patch (exact:
  // E = L ∑ edges, computed here by numerical integration instead).
  const float a = 0.5f, h = 1.0f, L = 3.0f;
  double E = 0;
  const int n = 400;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      const double x = -a + 2 * a * (i + 0.5) / n, y = -a + 2 * a * (j + 0.5) / n;
      const double r2 = x * x + y * y + h * h;
      E += L * (h * h) / (r2 * r2) * (2 * a / n) * (2 * a / n);
    }
  const double expected = 0.5 * E / M_PI;
  const auto r = render_json(R"({
    "camera": {"position": [0, 0.5, 0.0001], "look_at": [0, 0, 0], "fov_deg": 2},
    "render": {"resolution": [8, 8], "spp": 1024, "max_depth": 1, "seed": 4},
    "materials": {"m": {"type": "diffuse", "base_color": [0.5, 0.5, 0.5]},
                  "light": {"type": "emissive", "color": [1, 1, 1], "strength": 3}},
    "objects": [{"type": "plane", "point": [0, 0, 0], "normal": [0, 1, 0], "size": 100, "material": "m"},
                {"type": "plane", "point": [0, 1, 0], "normal": [0, -1, 0], "size": 1, "material": "light"}]
  })");
  const double v = mean_beauty(r.film, 0, 1.0f);
  std::printf("area light: %.5f (expect %.5f)\n", v, expected);
  EXPECT_NEAR(v, expected, 0.02 * expected);
}

TEST(Determinism, OneAndTwoThreadsGiveIdenticalImages) {
  const std::string scene = R"({
    "camera": {"position": [2, 1.2, 3], "look_at": [0, 0.6, 0], "fov_deg": 40, "aperture_radius": 0.02},
    "render": {"resolution": [48, 32], "spp": 8, "max_depth": 6, "seed": 9},
    "lights": [{"type": "sun", "direction": [0.5, 0.7, 0.3], "irradiance": 2}, {"type": "sky"}],
    "materials": {"bark": {"type": "bark", "base_color_texture": {"procedural": "bark"}, "roughness": 0.6},
                  "glass": {"type": "dielectric", "roughness": 0.1}},
    "objects": [{"type": "tree", "material": "bark", "axis": [[0,0,0],[0,2,0]], "radius": [0.3, 0.2],
                 "displacement": {"type": "grooves", "amplitude": 0.02}},
                {"type": "sphere", "center": [0.8, 0.3, 0.5], "radius": 0.3, "material": "glass"},
                {"type": "plane", "size": 20}]
  })";
  const auto a = render_json(scene, 1), b = render_json(scene, 2);
  ASSERT_EQ(a.film.beauty.size(), b.film.beauty.size());
  EXPECT_TRUE(a.film.beauty == b.film.beauty);
  EXPECT_TRUE(a.film.albedo == b.film.albedo);
  EXPECT_TRUE(a.film.object_id == b.film.object_id);
  // A different seed must change the noise.
  std::string other = scene;
  other.replace(other.find("\"seed\": 9"), 9, "\"seed\": 8");
  const auto c = render_json(other, 2);
  EXPECT_FALSE(a.film.beauty == c.film.beauty);
}

}  // namespace
}  // namespace phellem
