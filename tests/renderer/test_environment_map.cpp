// Environment maps of any size, down to one pixel wide, light the scene with their colour.
#include <gtest/gtest.h>

#include <OpenImageIO/imageio.h>

#include <vector>

#include "tests/support/render_helpers.h"
#include "tests/support/test_util.h"

using namespace phellem;

TEST(EnvironmentMap, OnePixelWideMapIsAcceptedAndSeenAsItsColour) {
  const std::string dir = test::temp_dir("env_1px");
  const std::string path = dir + "/sky.exr";
  const int w = 1, h = 4;
  std::vector<float> px(size_t(w) * h * 3);
  for (size_t i = 0; i < px.size(); i += 3) {
    px[i] = 0.25f;
    px[i + 1] = 0.5f;
    px[i + 2] = 1.0f;
  }
  auto out = OIIO::ImageOutput::create(path);
  ASSERT_TRUE(out);
  ASSERT_TRUE(out->open(path, OIIO::ImageSpec(w, h, 3, OIIO::TypeDesc::FLOAT)));
  ASSERT_TRUE(out->write_image(OIIO::TypeDesc::FLOAT, px.data()));
  out->close();
  const RenderResult r = test::render_json(R"({
    "camera": {"position": [0, 0, 0], "look_at": [0, 0, -1], "fov_deg": 30},
    "render": {"resolution": [8, 8], "spp": 2, "seed": 1},
    "lights": [{"type": "environment", "file": "sky.exr"}], "objects": []})",
                                           1, dir);
  const Film& f = r.film;
  for (size_t p = 0; p < size_t(f.width) * f.height; ++p) {
    EXPECT_NEAR(f.beauty[4 * p + 0], 0.25f, 1e-4f);
    EXPECT_NEAR(f.beauty[4 * p + 1], 0.5f, 1e-4f);
    EXPECT_NEAR(f.beauty[4 * p + 2], 1.0f, 1e-4f);
  }
}

TEST(EnvironmentMap, AHeaderClaimingAHugeImageIsRefusedBeforeDecoding) {
  const std::string dir = test::temp_dir("env_huge");
  test::write_text(dir + "/sky.hdr", "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 100000 +X 100000\n\x02\x02\x01\x00");
  test::write_text(dir + "/scene.json", R"({"render": {"resolution": [8, 8], "spp": 1},
    "lights": [{"type": "environment", "file": "sky.hdr"}], "objects": []})");
  const auto r = test::run_phellem("render " + dir + "/scene.json -o " + dir + "/out.exr");
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("phellem: error: " + dir + "/scene.json: /lights/0/file: cannot read environment map"),
            std::string::npos)
      << r.output;
  EXPECT_NE(r.output.find("pixels; at most"), std::string::npos) << r.output;
}
