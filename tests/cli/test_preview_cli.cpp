// `phellem preview` as a user runs it (issue 23): a headless snapshot and its AOVs, the
// window under a virtual X server, and every documented mistake as exit 2.
#include <gtest/gtest.h>

#include <OpenImageIO/imageio.h>

#include <chrono>
#include <cmath>
#include <cstdlib>

#include "tests/support/test_util.h"

using namespace phellem;

namespace {

const std::string kScene = R"({
  "camera": {"position": [0.0, 0.3, 0.3], "look_at": [0, 0.3, 0], "fov_deg": 30},
  "render": {"resolution": [96, 64]},
  "objects": [{"type": "mesh",
    "procedural": {"shape": "trunk", "triangles": 3000, "radius": 0.1, "height": 0.6},
    "bark": {"model": "stress", "preset": "woodification", "iterations": 40, "alpha": 0.8, "seed": 5,
             "crack": {"width_per_edge": 0.002, "max_width": 0.008, "max_depth": 0.01}}}]
})";

std::string scene_file(const std::string& dir) {
  const std::string path = dir + "/trunk.json";
  test::write_text(path, kScene);
  return path;
}

void expect_exit2(const std::string& args, const std::string& detail) {
  const auto r = test::run_phellem(args);
  EXPECT_EQ(r.exit_code, 2) << args << "\n" << r.output;
  EXPECT_NE(r.output.find("phellem: error: "), std::string::npos) << r.output;
  EXPECT_NE(r.output.find(detail), std::string::npos) << args << "\n" << r.output;
}

}  // namespace

TEST(PreviewCli, SnapshotWritesThePngAndTheAovsAtTheRequestedSize) {
  const std::string dir = test::temp_dir("preview_snapshot");
  const auto r = test::run_phellem("preview " + scene_file(dir) + " --snapshot " + dir + "/s.png -o " + dir + "/s.exr --res 120x80");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  auto png = OIIO::ImageInput::open(dir + "/s.png");
  ASSERT_TRUE(png);
  EXPECT_EQ(png->spec().width, 120);
  EXPECT_EQ(png->spec().height, 80);
  auto exr = OIIO::ImageInput::open(dir + "/s.exr");
  ASSERT_TRUE(exr);
  const auto& spec = exr->spec();
  ASSERT_EQ(spec.nchannels, 3);
  const int mask = spec.channelindex("crack.mask"), depth = spec.channelindex("depth.Z");
  ASSERT_GE(mask, 0);
  ASSERT_GE(depth, 0);
  EXPECT_GE(spec.channelindex("crack.depth"), 0);
  std::vector<float> px(size_t(spec.width) * spec.height * 3);
  ASSERT_TRUE(exr->read_image(0, 0, 0, 3, OIIO::TypeDesc::FLOAT, px.data()));
  int cracks = 0, hits = 0;
  for (size_t p = 0; p < px.size() / 3; ++p) {
    cracks += px[3 * p + size_t(mask)] > 0.5f;
    const float d = px[3 * p + size_t(depth)];
    if (std::isfinite(d)) {
      ++hits;
      EXPECT_GT(d, 0.15f);  // the trunk's front is 0.2 m away
      EXPECT_LT(d, 0.45f);
    }
  }
  EXPECT_GT(hits, 120 * 80 / 3);
  EXPECT_GT(cracks, 10);
  EXPECT_TRUE(test::leftover_temporaries(dir).empty());
}

// A patch with an image displacement (a 64 × 64 PNG of bumps, written here): the snapshot shows
// its relief, lit by a low sun, where the same patch without the displacement is one flat
// shade. Each snapshot's pixels on the patch (the depth AOV) give the luminance spread.
TEST(PreviewCli, APatchWithAnImageDisplacementShowsItsRelief) {
  const std::string dir = test::temp_dir("preview_patch");
  {
    const int n = 64;
    std::vector<uint8_t> px(size_t(n) * n);
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i)
        px[size_t(j) * n + size_t(i)] =
            uint8_t(std::lround(127.5 + 127.0 * std::sin(2 * M_PI * 4 * i / n) * std::sin(2 * M_PI * 3 * j / n)));
    auto out = OIIO::ImageOutput::create(dir + "/bumps.png");
    ASSERT_TRUE(out);
    ASSERT_TRUE(out->open(dir + "/bumps.png", OIIO::ImageSpec(n, n, 1, OIIO::TypeDesc::UINT8)));
    ASSERT_TRUE(out->write_image(OIIO::TypeDesc::UINT8, px.data()));
    out->close();
  }
  auto scene = [&](const std::string& name, const std::string& displacement) {
    const std::string path = dir + "/" + name + ".json";
    test::write_text(path, R"({
      "camera": {"position": [0.05, 0.04, 0.35], "look_at": [0, 0, 0], "fov_deg": 40},
      "lights": [{"type": "sun", "direction": [1, 0.3, 0.35], "irradiance": 3}],
      "objects": [{"type": "patch", "center": [0, 0, 0], "normal": [0, 0, 1], "up": [0, 1, 0], "size": [0.2, 0.2])" +
                             displacement + "}]}");
    return path;
  };
  struct Shot {
    int on_patch = 0;
    double mean = 0, spread = 0;  // luminance (0..255) on the patch
  };
  auto snapshot = [&](const std::string& path, const std::string& name) {
    const auto r = test::run_phellem("preview " + path + " --snapshot " + dir + "/" + name + ".png -o " + dir + "/" + name +
                                     ".exr --res 160x160 --quiet");
    EXPECT_EQ(r.exit_code, 0) << r.output;
    Shot s;
    auto png = OIIO::ImageInput::open(dir + "/" + name + ".png");
    auto exr = OIIO::ImageInput::open(dir + "/" + name + ".exr");
    if (!png || !exr) {
      ADD_FAILURE() << "no snapshot " << name;
      return s;
    }
    std::vector<uint8_t> rgb(160 * 160 * 3);
    std::vector<float> aov(160 * 160 * 3);
    EXPECT_TRUE(png->read_image(0, 0, 0, 3, OIIO::TypeDesc::UINT8, rgb.data()));
    EXPECT_TRUE(exr->read_image(0, 0, 0, 3, OIIO::TypeDesc::FLOAT, aov.data()));
    const int depth = exr->spec().channelindex("depth.Z");
    double sum = 0, sum2 = 0;
    for (size_t p = 0; p < rgb.size() / 3; ++p) {
      if (!std::isfinite(aov[3 * p + size_t(depth)])) continue;
      const double y = 0.2126 * rgb[3 * p] + 0.7152 * rgb[3 * p + 1] + 0.0722 * rgb[3 * p + 2];
      ++s.on_patch;
      sum += y;
      sum2 += y * y;
    }
    if (s.on_patch > 0) {
      s.mean = sum / s.on_patch;
      s.spread = std::sqrt(std::max(0.0, sum2 / s.on_patch - s.mean * s.mean));
    }
    return s;
  };
  const Shot flat = snapshot(scene("flat", ""), "flat");
  const Shot bumpy = snapshot(
      scene("bumpy", R"(, "displacement": {"type": "image", "file": "bumps.png", "scale": 0.012, "midlevel": 0.5, "wrap": "repeat"})"),
      "bumpy");
  RecordProperty("flat_spread", std::to_string(flat.spread));
  RecordProperty("bumpy_spread", std::to_string(bumpy.spread));
  std::printf("  luminance on the patch: flat %.1f ± %.2f (%d px), displaced %.1f ± %.2f (%d px)\n", flat.mean, flat.spread,
              flat.on_patch, bumpy.mean, bumpy.spread, bumpy.on_patch);
  EXPECT_GT(flat.on_patch, 160 * 160 / 3);
  EXPECT_GT(bumpy.on_patch, 160 * 160 / 3);
  EXPECT_LT(flat.spread, 3.0);           // one flat shade (and the rounding of 8 bits)
  EXPECT_GT(bumpy.spread, 10.0);         // bumps facing towards and away from the sun
  EXPECT_GT(bumpy.spread, 5 * flat.spread + 5);
}

// A metre-wide patch with an image displacement, seen whole at 512²: drawn as 16 × 16 cells,
// each tessellated to level ~24 at 2 px a micro-edge, llvmpipe dropped whole bands of cells
// (the background showed through) and took 1.3 s a frame; in cells of 2 cm it is drawn whole.
// Every pixel inside the patch's outline must be the patch's (the depth AOV is finite and
// positive only where a surface is).
TEST(PreviewCli, AMetreWidePatchIsDrawnWhole) {
  const std::string dir = test::temp_dir("preview_big_patch");
  {
    const std::vector<float> flat(64, 0.5f);
    auto out = OIIO::ImageOutput::create(dir + "/flat.exr");
    ASSERT_TRUE(out && out->open(dir + "/flat.exr", OIIO::ImageSpec(8, 8, 1, OIIO::TypeDesc::FLOAT)));
    ASSERT_TRUE(out->write_image(OIIO::TypeDesc::FLOAT, flat.data()));
    out->close();
  }
  const std::string scene = dir + "/scene.json";
  test::write_text(scene, R"({"camera": {"position": [0, 0, 2.2], "look_at": [0, 0, 0], "fov_deg": 30},
    "lights": [{"type": "environment", "file": "builtin:rooitou_park_1k.hdr"}, {"type": "sun", "direction": [0.87, 0, 0.5], "irradiance": 3}],
    "objects": [{"type": "patch", "size": 1.024, "displacement": {"type": "image", "file": "flat.exr", "scale": 0.03}}]})");
  const auto r = test::run_phellem("preview " + scene + " --snapshot " + dir + "/s.png -o " + dir + "/s.exr --res 512x512 --quiet");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  auto exr = OIIO::ImageInput::open(dir + "/s.exr");
  ASSERT_TRUE(exr);
  const OIIO::ImageSpec& spec = exr->spec();
  const int depth_channel = spec.channelindex("depth.Z");
  ASSERT_GE(depth_channel, 0);
  std::vector<float> depth(size_t(spec.width) * size_t(spec.height));
  ASSERT_TRUE(exr->read_image(0, 0, depth_channel, depth_channel + 1, OIIO::TypeDesc::FLOAT, depth.data()));
  // The patch spans ±0.512 m at 2.2 m under a 30° field of view: ±0.8686 of the half-frame,
  // pixels 34 to 478; inside it by 4 px, no pixel may show the background.
  int background = 0;
  for (int y = 38; y < 474; ++y)
    for (int x = 38; x < 474; ++x) {
      const float d = depth[size_t(y) * size_t(spec.width) + size_t(x)];
      background += !(std::isfinite(d) && d > 0.0f);
    }
  EXPECT_EQ(background, 0);
}

TEST(PreviewCli, MistakesAreExit2WithTheirReason) {
  const std::string dir = test::temp_dir("preview_errors");
  const std::string scene = scene_file(dir);
  expect_exit2("preview " + scene + " --snapshot " + dir + "/s.jpg", "expected a .png file name");
  expect_exit2("preview " + scene + " -o " + dir + "/a.exr", "only with --snapshot");
  expect_exit2("preview " + scene + " --snapshot " + dir + "/missing/dir/s.png", "--snapshot");
  expect_exit2("preview " + dir + "/nope.json --snapshot " + dir + "/s.png", "nope.json");
  expect_exit2("preview " + scene + " --max-level 65 --snapshot " + dir + "/s.png", "must lie in [1, 64]");
  expect_exit2("preview " + scene + " --edge-px nan --snapshot " + dir + "/s.png", "--edge-px");
  expect_exit2("preview " + scene + " --spp 4 --snapshot " + dir + "/s.png", "not an option of preview");
  expect_exit2("preview " + scene + " --res 20000x100 --snapshot " + dir + "/s.png", "draws at most");
  // Without a display the window cannot open: said so, with the headless alternative.
  const auto r = test::run_command("env -u DISPLAY -u WAYLAND_DISPLAY " PHELLEM_BINARY " preview " + scene + " --frames 1 --quiet 2>&1");
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("phellem: error: <command line>: preview: no display"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("--snapshot OUT.png renders a frame without one"), std::string::npos) << r.output;
}

// --edge-px below half a pixel was accepted (the range was (0, 1000]) and cost 1/P² the
// triangles: at 0.01 a 32×24 snapshot ran for minutes. Shorter micro-edges show nothing more
// at one sample a pixel, so the range is [0.5, 1000] (the window's finer key stops there too),
// and a snapshot at 0.5 takes seconds (of the default scene: a 15 ms frame of 31,374
// triangles after a minute of simulating its bark). Under a time limit, so that the old code
// fails.
TEST(PreviewCli, MicroEdgesShorterThanHalfAPixelAreRefused) {
  const std::string dir = test::temp_dir("preview_edge");
  const std::string snapshot = " " + scene_file(dir) + " --snapshot " + dir + "/s.png --res 32x24";
  for (const char* tiny : {"0.01", "0.49", "1e-30"}) {
    const auto r = test::run_phellem_limited("preview" + snapshot + " --edge-px " + tiny, 8192, 60);
    EXPECT_EQ(r.exit_code, 2) << tiny << "\n" << r.output;
    EXPECT_NE(r.output.find("phellem: error: <command line>: --edge-px: must be at least 0.5 (pixels; at most 1000)"),
              std::string::npos)
        << r.output;
  }
  const auto t0 = std::chrono::steady_clock::now();
  const auto r = test::run_phellem_limited("preview" + snapshot + " --edge-px 0.5", 8192, 60);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  EXPECT_EQ(r.exit_code, 0) << r.output;
  EXPECT_LT(seconds, 30.0) << r.output;
}

TEST(PreviewCli, TheWindowRunsUnderAVirtualDisplay) {
  if (std::system("command -v xvfb-run > /dev/null") != 0) {
    if (std::getenv("CI")) FAIL() << "xvfb-run is missing in CI (Debian's xvfb)";
    GTEST_SKIP() << "xvfb-run is not installed";
  }
  const std::string dir = test::temp_dir("preview_window");
  const auto r = test::run_command("xvfb-run -a -s '-screen 0 640x480x24' " PHELLEM_BINARY " preview " + scene_file(dir) +
                                   " --frames 4 --res 320x240 2>&1");
  EXPECT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("4 frames"), std::string::npos) << r.output;
}
