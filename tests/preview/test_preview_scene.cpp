// What the preview uploads, checked without OpenGL: the crack grid lists every segment a
// point's V-profile could reach in that point's cell (the GPU visits only that cell), and the
// ambient term of an environment is its irradiance on an upward and a downward surface.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>

#include "bark/dressing/crack_bark_surface.h"
#include "preview/orbit_camera.h"
#include "preview/preview_scene.h"
#include "preview/view_file.h"
#include "scene/displacement_map.h"
#include "scene/scene_parser.h"
#include "tests/bark/dressing/cracked_square.h"
#include "tests/support/test_util.h"

using namespace phellem;
using namespace phellem::preview;

TEST(PreviewScene, TheCrackGridListsEverySegmentWithinReachInThePointsCell) {
  bark::CrackedMesh c = test::cracked_square();
  // More crack edges: a zigzag across the square.
  for (int i = 0; i < 8; ++i) {
    c.mesh.positions.emplace_back(-0.04 + 0.01 * i, 0.02 * (i % 2), 0.0);
    c.crack_width.push_back(2);
    c.component.push_back(1);
    c.displacement.emplace_back(Eigen::Vector3f::Zero());
    if (i > 0) c.crack_edges.push_back({uint32_t(c.mesh.positions.size() - 2), uint32_t(c.mesh.positions.size() - 1)});
  }
  CrackLook look;
  look.shoulder_width = 0.004f;
  const CrackProfile profile(c, look, 3);
  for (size_t max_cells : {size_t(1) << 21, size_t(64)}) {  // fine cells, and cells grown to fit a small budget
    const GpuCracks g = gpu_cracks(profile, max_cells);
    EXPECT_LE(size_t(g.dims.x()) * g.dims.y() * g.dims.z(), max_cells);
    EXPECT_EQ(g.segments.size(), 12 * profile.segments());
    std::mt19937 rng(5);
    std::uniform_real_distribution<float> u(-0.06f, 0.06f);
    for (int k = 0; k < 4000; ++k) {
      const Vec3f p(u(rng), u(rng), 0.5f * u(rng));
      const Eigen::Vector3i i = ((p - g.origin) / g.cell).array().floor().cast<int>();
      if ((i.array() < 0).any() || (i.array() >= g.dims.array()).any()) continue;
      const size_t cell = (size_t(i.z()) * g.dims.y() + i.y()) * g.dims.x() + i.x();
      std::vector<uint32_t> listed(g.items.begin() + g.cell_start[cell], g.items.begin() + g.cell_start[cell + 1]);
      for (uint32_t s = 0; s < profile.segments(); ++s) {
        const auto& seg = profile.segment_list()[s];
        const Vec3f ab = seg.b - seg.a;
        const float t = std::clamp((p - seg.a).dot(ab) / ab.squaredNorm(), 0.0f, 1.0f);
        if ((p - (seg.a + t * ab)).norm() <= profile.reach()) {
          EXPECT_NE(std::find(listed.begin(), listed.end(), s), listed.end()) << "segment " << s << " missing at point " << k;
        }
      }
    }
  }
}

TEST(PreviewScene, AmbientIsTheEnvironmentsIrradianceUpAndDown) {
  PreviewEnvironment e;
  e.width = 64;
  e.height = 32;
  e.intensity = 2;
  e.rgb.assign(size_t(e.width) * e.height * 3, 0.5f);
  auto [up, down] = hemisphere_irradiance(e);
  // Uniform radiance L: E = π L on either side (midpoint rule over 32 rows: within 0.2 %).
  EXPECT_NEAR(up.x(), kPi * 1.0f, 0.002f * kPi);
  EXPECT_NEAR(down.z(), kPi * 1.0f, 0.002f * kPi);
  // Only the upper half lit: nothing reaches a surface facing down.
  for (int y = e.height / 2; y < e.height; ++y)
    for (int x = 0; x < e.width; ++x)
      for (int k = 0; k < 3; ++k) e.rgb[(size_t(y) * e.width + x) * 3 + k] = 0;
  std::tie(up, down) = hemisphere_irradiance(e);
  EXPECT_NEAR(up.y(), kPi * 1.0f, 0.002f * kPi);
  EXPECT_EQ(down.y(), 0.0f);
}

TEST(PreviewView, TheOrbitCameraStartsAtTheScenesCameraAndKeepsItsDistance) {
  CameraDesc d;
  d.position = Vec3f(0.4f, 1.3f, 1.1f);
  d.look_at = Vec3f(0.1f, 1.0f, -0.2f);
  d.fov_deg = 33;
  OrbitCamera orbit(d);
  EXPECT_TRUE(orbit.desc().position.isApprox(d.position, 1e-5f));
  EXPECT_TRUE(orbit.desc().look_at.isApprox(d.look_at));
  EXPECT_EQ(orbit.desc().fov_deg, 33);
  const float r = (d.position - d.look_at).norm();
  orbit.orbit(120, -40);
  EXPECT_NEAR((orbit.desc().position - orbit.desc().look_at).norm(), r, 1e-5f);
  orbit.zoom(2);
  EXPECT_NEAR((orbit.desc().position - orbit.desc().look_at).norm(), r * 0.81f, 1e-5f);
  orbit.pan(10, 0, 100);
  EXPECT_FALSE(orbit.desc().look_at.isApprox(d.look_at));
}

TEST(PreviewView, TheCameraKeyWritesASceneThatRendersThatView) {
  const std::string dir = test::temp_dir("preview_view");
  const std::string scene = dir + "/trunk.json";
  test::write_text(scene, R"({"camera": {"position": [0, 1, 3], "look_at": [0, 1, 0], "aperture_radius": 0.01},
    "materials": {"m": {"type": "diffuse"}},
    "objects": [{"type": "sphere", "center": [0, 1, 0], "radius": 0.3, "material": "m"}]})");
  CameraDesc c;
  c.position = Vec3f(1, 2, 2);
  c.look_at = Vec3f(0, 1.1f, 0);
  c.fov_deg = 25;
  const std::string out = write_view_scene(scene, c);
  EXPECT_EQ(out, dir + "/trunk_view.json");
  const SceneDesc back = load_scene_file(out);
  EXPECT_TRUE(back.camera.position.isApprox(c.position));
  EXPECT_TRUE(back.camera.look_at.isApprox(c.look_at));
  EXPECT_EQ(back.camera.fov_deg, 25);
  EXPECT_EQ(back.camera.aperture_radius, 0.01f);  // the rest of the scene is kept
  EXPECT_EQ(back.objects.size(), 1u);
  // An unwritable folder: an exception, not a crash (the window shows "nothing").
  EXPECT_ANY_THROW(write_view_scene(dir + "/missing/trunk.json", c));
}

// Image displacements reach the GPU where the path tracer dices them: a mesh's at its UVs
// (every edge tessellated finely), and a mesh without UVs is refused as the path tracer refuses
// it; a mesh file's transform is applied on the CPU, so the offset stays in metres.
TEST(PreviewScene, AnImageDisplacementTakesTheMeshsUvsAndNeedsThem) {
  const std::string dir = test::temp_dir("preview_image_uvs");
  test::write_text(dir + "/uv.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 0.5 0\nvt 0 0.25\nvn 0 0 1\nf 1/1/1 2/2/1 3/3/1\n");
  test::write_text(dir + "/bare.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  const std::string scene = dir + "/scene.json";
  test::write_text(scene, R"({"objects": [{"type": "mesh", "file": "uv.obj", "transform": {"scale": 2}},
                                          {"type": "mesh", "file": "bare.obj"}]})");
  SceneDesc desc = load_scene_file(scene);
  auto map = std::make_shared<DisplacementMap>();
  map->width = map->height = 2;
  map->value = {0, 1, 1, 0};
  DisplacementDesc d;
  d.type = DisplacementDesc::Type::Image;
  d.map = map;
  desc.objects[0].displacement = d;
  SceneDesc one = desc;
  one.objects.pop_back();
  const PreviewScene s = build_preview_scene(one, BarkResults{});
  ASSERT_EQ(s.objects.size(), 1u);
  const PreviewObject& o = s.objects[0];
  ASSERT_TRUE(o.image);
  EXPECT_EQ(o.image->map, map);
  EXPECT_FLOAT_EQ(o.image->reach(), 0.5f * d.scale);
  ASSERT_EQ(o.texcoords.size(), 3u);
  EXPECT_TRUE(o.texcoords[1].isApprox(Vec2f(0.5f, 0)));
  EXPECT_TRUE(o.texcoords[2].isApprox(Vec2f(0, 0.25f)));
  EXPECT_EQ(std::count(o.crack_near.begin(), o.crack_near.end(), 1.0f), 3);
  EXPECT_TRUE(o.model.isIdentity());
  EXPECT_TRUE(o.positions[1].isApprox(Vec3f(2, 0, 0)));  // in world space
  desc.objects[1].displacement = d;
  test::expect_user_error([&] { build_preview_scene(desc, BarkResults{}); }, "mesh without UVs", scene,
                          desc.objects[1].where.path + "/displacement", "has none (export it with UVs)");
}
