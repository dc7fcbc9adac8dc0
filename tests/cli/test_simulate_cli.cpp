// `phellem simulate` with the strip model: documented outputs and errors.
#include <gtest/gtest.h>

#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "io/mesh_io.h"
#include "tests/support/test_util.h"

namespace phellem {
namespace {

// All pixels of an image as floats (spec->nchannels per pixel); empty if it cannot be read.
std::vector<float> read_pixels(const std::string& path, OIIO::ImageSpec* spec) {
  auto in = OIIO::ImageInput::open(path);
  if (!in) return {};
  *spec = in->spec();
  std::vector<float> px(size_t(spec->width) * spec->height * spec->nchannels);
  if (!in->read_image(0, 0, 0, spec->nchannels, OIIO::TypeDesc::FLOAT, px.data())) return {};
  return px;
}

std::string scene_with_bark(const std::string& bark) {
  return R"({"render": {"seed": 3}, "objects": [{"type": "tree", "name": "t", "axis": [[0, 0, 0], [0, 0.3, 0]],
              "radius": [0.05, 0.04], "branches": [{"attach": 0.6, "length": 0.15, "radius": [0.02, 0.015]}],
              "bark": )" +
         bark + "}]}";
}

TEST(SimulateCli, WritesAFractureFieldPerCylinderWithTheDocumentedChannels) {
  const std::string dir = test::temp_dir("simulate_ok");
  const std::string scene = dir + "/scene.json";
  test::write_text(scene, scene_with_bark(R"({"model": "strips", "preset": "fissured", "steps": 60, "growth_rate": 1.01,
                                              "strip_width": 0.01})"));
  const auto r =
      test::run_phellem("simulate " + scene + " -o " + dir + "/out --res 64x96 --quiet --stats " + dir + "/stats.json");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  for (const char* part : {"t_trunk.exr", "t_branch1.exr"}) {
    OIIO::ImageSpec spec;
    const std::vector<float> px = read_pixels(dir + "/out/" + part, &spec);
    ASSERT_FALSE(px.empty()) << part;
    EXPECT_EQ(spec.width, 64);
    EXPECT_EQ(spec.height, 96);
    std::vector<std::string> want = {"color.R", "color.G",     "color.B", "opening", "depth",   "uv0.u",
                                     "uv0.v",   "fracture_id", "age",     "level",   "interior"};
    std::vector<std::string> got = spec.channelnames;  // OpenEXR stores channels sorted: compare as sets
    std::sort(want.begin(), want.end());
    std::sort(got.begin(), got.end());
    EXPECT_EQ(got, want);
    const int c_open = spec.channelindex("opening"), c_depth = spec.channelindex("depth");
    ASSERT_GE(c_open, 0);
    ASSERT_GE(c_depth, 0);
    double open = 0, depth_in = 0, depth_out = 0;
    for (size_t p = 0; p < px.size(); p += size_t(spec.nchannels)) {
      open += px[p + size_t(c_open)];
      (px[p + size_t(c_open)] > 0 ? depth_in : depth_out) += px[p + size_t(c_depth)];
    }
    open /= double(spec.width) * spec.height;
    // Circumference grew ×1.01^60 = 1.82: fractures must cover a large share, but not all.
    EXPECT_GT(open, 0.15) << part;
    EXPECT_LT(open, 0.9) << part;
    EXPECT_GT(depth_in, 0) << part;
    EXPECT_EQ(depth_out, 0) << part;  // depth only inside fractures
  }
  std::ifstream sf(dir + "/stats.json");
  const auto j = nlohmann::json::parse(sf);
  EXPECT_EQ(j["model"], "strips");
  EXPECT_EQ(j["steps"], 60);
  EXPECT_GT(j["strips"].get<int>(), 30);
  EXPECT_GT(j["fractures"].get<int>(), 0);
  EXPECT_TRUE(j["time_s"].contains("simulate"));
  EXPECT_TRUE(j["time_s"].contains("dress"));
  // The bark meshes read back through Phellem's own glTF loader: epidermis and fracture
  // primitives, every vertex within [r − max_depth, r] of the axis (trunk radius 0.05 → 0.04).
  long long triangles = 0;
  for (const char* part : {"t_trunk.glb", "t_branch1.glb"}) {
    const LoadedModel model = load_gltf(dir + "/out/" + part);
    ASSERT_EQ(model.meshes.size(), 2u) << part;
    ASSERT_EQ(model.materials.size(), 2u);
    EXPECT_EQ(model.materials[0].name, "epidermis");
    EXPECT_EQ(model.materials[1].name, "fracture");
    for (const MeshData& m : model.meshes) {
      triangles += (long long)m.triangle_count();
      EXPECT_FALSE(m.normals.empty());
    }
    if (std::string(part) == "t_trunk.glb")
      for (const MeshData& m : model.meshes)
        for (const Vec3f& p : m.positions) {
          const double r = std::hypot(p.x(), p.z());
          ASSERT_LE(r, 0.05 + 1e-4);
          ASSERT_GE(r, 0.04 - 0.02 - 1e-4);
        }
  }
  EXPECT_EQ(triangles, j["mesh_triangles"].get<long long>());
}

TEST(SimulateCli, ThresholdOutsideItsRangeIsRefusedWithTheRange) {
  const std::string dir = test::temp_dir("simulate_threshold");
  const std::string scene = dir + "/scene.json";
  test::write_text(scene, scene_with_bark(R"({"model": "strips", "growth_rate": 1.01, "threshold": 1.5})"));
  const auto r = test::run_phellem("simulate " + scene + " -o " + dir + "/out --quiet");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(
      r.output.find("phellem: error: " + scene + ": /objects/0/bark/threshold: threshold: S = 1.5 is outside its valid range ("),
      std::string::npos)
      << r.output;
  EXPECT_NE(r.output.find(", 1.01]"), std::string::npos) << r.output;
  EXPECT_FALSE(std::filesystem::exists(dir + "/out/t_trunk.exr"));
}

TEST(SimulateCli, BadBarkSettingsNameTheirPath) {
  const std::string dir = test::temp_dir("simulate_bad");
  const std::string scene = dir + "/scene.json";
  struct Case {
    std::string bark, expect;
  };
  const std::vector<Case> cases = {
      {R"({"model": "strips", "preset": "birch"})",
       "/objects/0/bark/preset: unknown preset \"birch\"; allowed: furrowed, fissured, plated, brittle, banded"},
      {R"({"model": "strips", "orientation": "diagonal"})",
       "/objects/0/bark/orientation: unknown orientation \"diagonal\"; allowed: vertical, horizontal"},
      {R"({"model": "waves"})", "/objects/0/bark/model: unknown bark model"},
      {R"({"model": "strips", "attachmnt": 1})", "/objects/0/bark/attachmnt: unknown key"},
      {R"({"model": "strips", "threshold_noise": 1.5})", "/objects/0/bark/threshold_noise: threshold_noise: must be in [0, 1)"},
      {R"({"model": "strips", "weakness_map": "missing.png"})", "/objects/0/bark/weakness_map: file not found"},
      {R"({"model": "strips", "depth": {"profile": "w"}})", "/objects/0/bark/depth/profile: unknown depth profile"},
  };
  for (const Case& c : cases) {
    test::write_text(scene, scene_with_bark(c.bark));
    const auto r = test::run_phellem("simulate " + scene + " -o " + dir + "/out --quiet");
    EXPECT_EQ(r.exit_code, 2) << c.bark;
    EXPECT_NE(r.output.find(c.expect), std::string::npos) << r.output;
  }
  test::write_text(scene, R"({"objects": [{"type": "sphere", "radius": 1}]})");
  const auto r = test::run_phellem("simulate " + scene + " -o " + dir + "/out --quiet");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.output.find("no object has a \"bark\" to simulate"), std::string::npos) << r.output;
}

}  // namespace

// Coverage (alpha sum) of a rendered frame: how much of the image the tree fills.
double coverage(const std::string& exr) {
  OIIO::ImageSpec spec;
  const std::vector<float> px = read_pixels(exr, &spec);
  if (px.empty()) return -1;
  const int a = spec.channelindex("beauty.A");
  if (a < 0) return -1;
  double sum = 0;
  for (size_t p = 0; p < size_t(spec.width) * spec.height; ++p) sum += px[p * spec.nchannels + size_t(a)];
  return sum;
}

// Writes a small trunk scene with strip bark `preset` into `dir` and renders 3 growth frames
// f_00..f_02.exr; returns the scene path.
std::string grow_three_frames(const std::string& dir, const std::string& preset) {
  const std::string scene = dir + "/scene.json";
  test::write_text(scene, R"({"camera": {"position": [0, 0.15, 0.6], "look_at": [0, 0.15, 0], "fov_deg": 30},
    "lights": [{"type": "environment", "color": [1, 1, 1]}],
    "objects": [{"type": "tree", "axis": [[0, 0, 0], [0, 0.3, 0]], "radius": [0.05],
                 "bark": {"model": "strips", "preset": ")" +
                              preset + R"(", "steps": 60, "growth_rate": 1.01, "strip_width": 0.01}}]})");
  const auto r = test::run_phellem("growth " + scene + " --frames 3 -o " + dir + "/f_%02d.exr --res 48x48 --spp 1 --quiet");
  EXPECT_EQ(r.exit_code, 0) << r.output;
  return scene;
}

TEST(GrowthCli, FramesFollowTheSimulationAndTheTrunkThickens) {
  const std::string dir = test::temp_dir("growth_ok");
  const std::string scene = grow_three_frames(dir, "fissured");
  const double c0 = coverage(dir + "/f_00.exr"), c2 = coverage(dir + "/f_02.exr");
  ASSERT_GT(c0, 0);
  // Girth at frame k is G^-(T - t_k) of the final one: 1.01^-40 = 0.67 for the first frame.
  EXPECT_NEAR(c0 / c2, std::pow(1.01, -40), 0.08);
  EXPECT_FALSE(std::filesystem::exists(dir + "/f_03.exr"));
  // Continuity: the last frame is the whole simulation, the same image `render` makes.
  const auto still = test::run_phellem("render " + scene + " -o " + dir + "/still.exr --res 48x48 --spp 1 --quiet");
  ASSERT_EQ(still.exit_code, 0) << still.output;
  EXPECT_EQ(coverage(dir + "/still.exr"), c2);
  OIIO::ImageSpec sa, sb;
  const std::vector<float> pa = read_pixels(dir + "/still.exr", &sa), pb = read_pixels(dir + "/f_02.exr", &sb);
  ASSERT_FALSE(pa.empty());
  EXPECT_EQ(pa, pb);
}

TEST(GrowthCli, HorizontalFracturesKeepTheGirth) {
  // Strips along the axis grow in length: the frames keep the final girth.
  const std::string dir = test::temp_dir("growth_horizontal");
  grow_three_frames(dir, "banded");
  const double c0 = coverage(dir + "/f_00.exr"), c2 = coverage(dir + "/f_02.exr");
  ASSERT_GT(c2, 0);
  // Same silhouette up to the displaced cracks on it (vertical fractures: 1.01^-40 = 0.67).
  EXPECT_NEAR(c0 / c2, 1.0, 0.03);
}

TEST(GrowthCli, ASceneWithoutStripBarkIsRefused) {
  const std::string dir = test::temp_dir("growth_none");
  const std::string scene = dir + "/scene.json";
  test::write_text(scene, R"({"objects": [{"type": "sphere", "center": [0, 0, 0], "radius": 1}]})");
  const auto r = test::run_phellem("growth " + scene + " --frames 2 -o " + dir + "/f_%02d.exr --res 8x8 --spp 1 --quiet");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.output.find("no tree object has a \"bark\""), std::string::npos) << r.output;
}

TEST(SimulateCli, EpidermisImageSampleColoursTheBarkAndABadOneIsNamed) {
  const std::string dir = test::temp_dir("simulate_dressing");
  // A flat 8-bit sRGB sample of value 128: linear 0.2158 everywhere.
  {
    std::vector<unsigned char> px(4 * 4 * 3, 128);
    auto out = OIIO::ImageOutput::create(dir + "/skin.png");
    ASSERT_TRUE(out);
    ASSERT_TRUE(out->open(dir + "/skin.png", OIIO::ImageSpec(4, 4, 3, OIIO::TypeDesc::UINT8)));
    ASSERT_TRUE(out->write_image(OIIO::TypeDesc::UINT8, px.data()));
    out->close();
  }
  const std::string scene = dir + "/scene.json";
  test::write_text(scene, scene_with_bark(R"({"model": "strips", "preset": "fissured", "steps": 60, "growth_rate": 1.01,
      "strip_width": 0.01, "dressing": {"epidermis": {"image": "skin.png", "size": [0.05, 0.05]}, "depth_darkening": 0}})"));
  const auto r = test::run_phellem("simulate " + scene + " -o " + dir + "/out --res 64x96 --no-mesh --quiet");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_FALSE(std::filesystem::exists(dir + "/out/t_trunk.glb"));  // --no-mesh
  OIIO::ImageSpec spec;
  const std::vector<float> px = read_pixels(dir + "/out/t_trunk.exr", &spec);
  ASSERT_FALSE(px.empty());
  const int c_open = spec.channelindex("opening"), c_r = spec.channelindex("color.R");
  int epidermis = 0;
  for (size_t p = 0; p < px.size(); p += size_t(spec.nchannels))
    if (px[p + size_t(c_open)] == 0) {
      EXPECT_NEAR(px[p + size_t(c_r)], 0.2158, 2e-3);
      ++epidermis;
    }
  EXPECT_GT(epidermis, 100);

  test::write_text(
      scene, scene_with_bark(R"({"model": "strips", "dressing": {"fracture": {"image": "missing.png", "size": [0.1, 0.1]}}})"));
  const auto bad = test::run_phellem("simulate " + scene + " -o " + dir + "/out --quiet");
  EXPECT_EQ(bad.exit_code, 2);
  EXPECT_NE(bad.output.find("/objects/0/bark/dressing/fracture/image"), std::string::npos) << bad.output;
  EXPECT_NE(bad.output.find("missing.png"), std::string::npos) << bad.output;
}

}  // namespace phellem
