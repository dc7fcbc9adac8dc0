// Output files: the EXR layers and channel names, the display-referred PNG, turntables.
#include <gtest/gtest.h>

#include <OpenImageIO/imageio.h>

#include <filesystem>

#include "io/image_output.h"
#include "tests/support/test_util.h"

namespace phellem {
namespace {

TEST(Output, ExrHasTheDocumentedLayersAndPngIsDisplayReferred) {
  const std::string dir = test::temp_dir("output");
  const auto r = test::run_phellem(std::string("render ") + PHELLEM_SOURCE_DIR + "/tests/scenes/spheres_env.json --spp 2 -o " +
                                   dir + "/o.exr --png " + dir + "/o.png");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  auto in = OIIO::ImageInput::open(dir + "/o.exr");
  ASSERT_TRUE(in);
  const OIIO::ImageSpec& spec = in->spec();
  // OpenEXR stores channels sorted by name; compare as sets and look channels up by name.
  auto sorted = [](std::vector<std::string> v) {
    std::sort(v.begin(), v.end());
    return v;
  };
  EXPECT_EQ(sorted(spec.channelnames), sorted(exr_channel_names()));
  auto ch = [&](const char* name) { return spec.channelindex(name); };
  EXPECT_EQ(spec.width, 64);
  EXPECT_EQ(spec.height, 40);
  EXPECT_EQ(spec.channelformat(ch("beauty.R")), OIIO::TypeDesc::HALF);
  EXPECT_EQ(spec.channelformat(ch("object_id.id")), OIIO::TypeDesc::FLOAT);  // object ids stay exact
  std::vector<float> px(size_t(spec.width) * spec.height * spec.nchannels);
  ASSERT_TRUE(in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, px.data()));
  // Centre pixel: the gold sphere (object 2), normal facing the camera, depth ≈ 4.1.
  const size_t c = (size_t(20) * 64 + 32) * spec.nchannels;
  EXPECT_EQ(px[c + ch("object_id.id")], 2.0f);
  EXPECT_GT(px[c + ch("normal.Z")], 0.8f);
  EXPECT_NEAR(px[c + ch("depth.Z")], 4.1f, 0.3f);
  EXPECT_EQ(px[c + ch("beauty.A")], 1.0f);
  EXPECT_EQ(px[c + ch("crack.mask")], 0.0f);  // reserved: zero until bark models land
  EXPECT_GT(px[c + ch("albedo.R")], 0.9f);    // gold F0
  in->close();

  auto png = OIIO::ImageInput::open(dir + "/o.png");
  ASSERT_TRUE(png);
  EXPECT_EQ(png->spec().format, OIIO::TypeDesc::UINT8);
  EXPECT_EQ(png->spec().nchannels, 3);
}

TEST(Output, DisplayViewsMapMidGreyAndClipHighlights) {
  const auto views = ocio_views();
  ASSERT_GE(views.size(), 3u);
  EXPECT_EQ(default_view(), "ACES 1.0 SDR-video");
  // Standard: plain sRGB encoding of scene-linear 0.18 is 0.461.
  std::vector<float> grey = {0.18f, 0.18f, 0.18f, 100.0f, 100.0f, 100.0f};
  apply_display_view(grey, "Standard");
  EXPECT_NEAR(grey[0], 0.461f, 0.01f);
  EXPECT_GE(grey[3], 0.999f);
  // ACES: filmic, mid grey lands lower and highlights roll off below white... but reach it.
  std::vector<float> aces = {0.18f, 0.18f, 0.18f, 1.0f, 1.0f, 1.0f};
  apply_display_view(aces, "ACES 1.0 SDR-video");
  std::printf("ACES view: 0.18 -> %.3f, 1.0 -> %.3f\n", aces[0], aces[3]);
  EXPECT_GT(aces[0], 0.3f);
  EXPECT_LT(aces[0], 0.46f);
  EXPECT_GT(aces[3], aces[0]);
  EXPECT_LT(aces[3], 1.0f);
  // sRGB texture decode: 0.5 encoded ≈ 0.214 linear.
  float tex[3] = {0.5f, 0.5f, 0.5f};
  srgb_texture_to_linear(tex, 1, 3);
  EXPECT_NEAR(tex[0], 0.214f, 0.003f);
}

TEST(Output, TurntableWritesEveryFrameAndOrbits) {
  const std::string dir = test::temp_dir("turntable");
  const auto r =
      test::run_phellem(std::string("turntable ") + PHELLEM_SOURCE_DIR +
                        "/tests/scenes/displaced_trunk.json --frames 3 --spp 1 --res 24x32 -o " + dir + "/f_%04d.exr --png");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  for (int f = 0; f < 3; ++f) {
    char name[64];
    std::snprintf(name, sizeof name, "/f_%04d", f);
    EXPECT_TRUE(std::filesystem::exists(dir + name + ".exr")) << name;
    EXPECT_TRUE(std::filesystem::exists(dir + name + ".png")) << name;
  }
  // Frames differ (the camera moved) while the geometry is the same (dicing camera fixed).
  auto read_pos = [&](const std::string& f) {
    auto in = OIIO::ImageInput::open(f);
    std::vector<float> px(size_t(in->spec().image_pixels()) * in->spec().nchannels);
    in->read_image(0, 0, 0, in->spec().nchannels, OIIO::TypeDesc::FLOAT, px.data());
    return px;
  };
  EXPECT_NE(read_pos(dir + "/f_0000.exr"), read_pos(dir + "/f_0001.exr"));
}

}  // namespace
}  // namespace phellem

namespace phellem {
namespace {

TEST(Output, EnvironmentFileLightsAPlaneByItsIrradiance) {
  // A constant 2.0 .hdr map: a plane of albedo 0.25 facing up shows ρ·L = 0.5.
  const std::string dir = test::temp_dir("envfile");
  {
    auto out = OIIO::ImageOutput::create(dir + "/sky.hdr");
    OIIO::ImageSpec spec(32, 16, 3, OIIO::TypeDesc::FLOAT);
    std::vector<float> px(32 * 16 * 3, 2.0f);
    ASSERT_TRUE(out->open(dir + "/sky.hdr", spec));
    ASSERT_TRUE(out->write_image(OIIO::TypeDesc::FLOAT, px.data()));
    out->close();
  }
  test::write_text(dir + "/scene.json", R"({
    "camera": {"position": [0, 1, 0.001], "look_at": [0, 0, 0], "fov_deg": 10},
    "render": {"resolution": [8, 8], "spp": 256, "max_depth": 2},
    "lights": [{"type": "environment", "file": "sky.hdr", "intensity": 1, "rotation_deg": 40}],
    "materials": {"m": {"type": "diffuse", "base_color": [0.25, 0.25, 0.25]}},
    "objects": [{"type": "plane", "size": 1000, "material": "m"}]})");
  const auto r = test::run_phellem("render " + dir + "/scene.json -o " + dir + "/o.exr");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  auto in = OIIO::ImageInput::open(dir + "/o.exr");
  const auto& spec = in->spec();
  std::vector<float> px(size_t(spec.image_pixels()) * spec.nchannels);
  in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, px.data());
  double sum = 0;
  for (size_t p = 0; p < size_t(spec.image_pixels()); ++p) sum += px[p * spec.nchannels + spec.channelindex("beauty.G")];
  EXPECT_NEAR(sum / spec.image_pixels(), 0.5, 0.01);
  // A corrupt map is a user error naming the light.
  test::write_text(dir + "/bad.hdr", "#?RADIANCE\ngarbage");
  test::write_text(dir + "/bad.json",
                   R"({"lights": [{"type": "environment", "file": "bad.hdr"}], "render": {"resolution": [4, 4], "spp": 1}})");
  const auto b = test::run_phellem("render " + dir + "/bad.json -o " + dir + "/b.exr");
  EXPECT_EQ(b.exit_code, 2) << b.output;
  EXPECT_NE(b.output.find("/lights/0/file"), std::string::npos) << b.output;
}

TEST(Output, Mp4WithoutFfmpegIsAClearError) {
  if (std::system("command -v ffmpeg >/dev/null 2>&1") == 0) GTEST_SKIP() << "ffmpeg is installed here";
  const std::string dir = test::temp_dir("mp4");
  const auto r =
      test::run_phellem(std::string("turntable ") + PHELLEM_SOURCE_DIR + "/tests/scenes/displaced_trunk.json --frames 2 -o " +
                        dir + "/f_%04d.exr --mp4 " + dir + "/t.mp4");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.output.find("ffmpeg is not installed"), std::string::npos) << r.output;
  EXPECT_FALSE(std::filesystem::exists(dir + "/f_0000.exr"));  // refused before rendering
}

}  // namespace
}  // namespace phellem
