// Bad displacement maps (`"displacement": {"type": "image", ...}`) give `phellem: error:` naming
// the file and what is wrong, and exit 2: a missing map, a header that lies about its size, NaN
// pixels, a 1×1 map, and values out of range. A good map renders.
#include <gtest/gtest.h>

#include <OpenImageIO/imageio.h>

#include <cmath>
#include <limits>

#include "tests/support/test_util.h"

namespace phellem {
namespace {

std::string write_float_map(const std::string& path, int w, int h, float fill, float odd_one_out) {
  std::vector<float> z(size_t(w) * size_t(h), fill);
  z[z.size() / 2] = odd_one_out;
  auto out = OIIO::ImageOutput::create(path);
  OIIO::ImageSpec spec(w, h, 1, OIIO::TypeDesc::FLOAT);
  EXPECT_TRUE(out && out->open(path, spec));
  EXPECT_TRUE(out->write_image(OIIO::TypeDesc::FLOAT, z.data()));
  out->close();
  return path;
}

std::string scene_with_map(const std::string& dir, const std::string& map, const std::string& extra = "") {
  const std::string scene = dir + "/scene.json";
  test::write_text(scene, R"({"render": {"resolution": [32, 32], "spp": 1},
    "objects": [{"type": "patch", "size": 0.3,
      "displacement": {"type": "image", "file": ")" + map + "\"" + extra + "}}]}");
  return scene;
}

void expect_refused(const std::string& dir, const std::string& scene, const std::string& file, const std::string& detail) {
  const auto r = test::run_phellem("render " + scene + " -o " + dir + "/out.exr");
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("phellem: error: " + file), std::string::npos) << r.output;
  EXPECT_NE(r.output.find(detail), std::string::npos) << r.output;
  EXPECT_EQ(r.output.find("terminate"), std::string::npos) << r.output;
}

TEST(ImageDisplacementCli, MissingMap) {
  const std::string dir = test::temp_dir("disp_missing");
  const std::string scene = scene_with_map(dir, "nowhere.png");
  expect_refused(dir, scene, scene + ": /objects/0/displacement/file", "nowhere.png");
}

TEST(ImageDisplacementCli, HeaderThatLiesAboutItsSize) {
  const std::string dir = test::temp_dir("disp_lying");
  const std::string map = test::lying_hdr(dir + "/huge.hdr", 200000, 200000);
  expect_refused(dir, scene_with_map(dir, map), map, "200000");
}

TEST(ImageDisplacementCli, NanPixel) {
  const std::string dir = test::temp_dir("disp_nan");
  const std::string map = write_float_map(dir + "/nan.exr", 16, 16, 0.5f, std::numeric_limits<float>::quiet_NaN());
  expect_refused(dir, scene_with_map(dir, map), map, "nan");
}

TEST(ImageDisplacementCli, OnePixelMap) {
  const std::string dir = test::temp_dir("disp_1x1");
  const std::string map = write_float_map(dir + "/one.exr", 1, 1, 0.5f, 0.5f);
  expect_refused(dir, scene_with_map(dir, map), map, "at least 2×2");
}

TEST(ImageDisplacementCli, ValuesOutOfRange) {
  const std::string dir = test::temp_dir("disp_range");
  const std::string map = write_float_map(dir + "/ok.exr", 8, 8, 0.5f, 0.7f);
  expect_refused(dir, scene_with_map(dir, map, R"(, "scale": 1e6)"), dir + "/scene.json: /objects/0/displacement/scale",
                 "scale must lie in");
  expect_refused(dir, scene_with_map(dir, map, R"(, "uv_repeat": 0)"), dir + "/scene.json: /objects/0/displacement/uv_repeat",
                 "must be > 0");
  expect_refused(dir, scene_with_map(dir, map, R"(, "wrap": "mirror")"), dir + "/scene.json: /objects/0/displacement/wrap",
                 "allowed: repeat, clamp");
  expect_refused(dir, scene_with_map(dir, map, R"(, "amplitude": 0.1)"), dir + "/scene.json: /objects/0/displacement/amplitude",
                 "");
}

TEST(ImageDisplacementCli, GoodMapRendersDisplaced) {
  const std::string dir = test::temp_dir("disp_good");
  const std::string map = write_float_map(dir + "/bump.exr", 8, 8, 0.0f, 1.0f);
  const auto r = test::run_phellem("render " + scene_with_map(dir, map, R"(, "scale": 0.05)") + " -o " + dir + "/out.exr --stats " +
                                   dir + "/stats.json --quiet");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  // A flat patch is 2 triangles per 2 cm cell; the bump is diced finer than that.
  const std::string stats = test::read_text(dir + "/stats.json");
  const auto at = stats.find("\"diced_triangles\"");
  ASSERT_NE(at, std::string::npos) << stats;
  EXPECT_GT(std::stol(stats.substr(stats.find(':', at) + 1)), 2 * 15 * 15);
}

}  // namespace
}  // namespace phellem
