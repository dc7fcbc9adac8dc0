// "builtin:<name>" files (io/builtin_files.h): the default scene's HDRI and bark photo are in
// the binary, so scenes that name them load and render from a folder holding no data.
#include <gtest/gtest.h>

#include <filesystem>

#include "io/builtin_files.h"
#include "scene/scene_parser.h"
#include "tests/support/scene_errors.h"
#include "tests/support/test_util.h"
#include "util/errors.h"

namespace phellem {
namespace {

constexpr const char* kPhotoTree = R"({
  "lights": [{"type": "environment", "file": "builtin:rooitou_park_1k.hdr", "rotation_deg": 30, "clamp": 50}],
  "objects": [{"type": "tree", "axis": [[0, 0, 0], [0, 1, 0]], "radius": [0.1, 0.08],
    "bark": {"model": "strips", "dressing": {"photo": {"albedo": "builtin:bark_brown_01.jpg",
      "height": "builtin:bark_brown_01_disp.jpg", "px_per_cm": 10}}}}]})";

TEST(BuiltinFiles, EveryFileIsThereWithItsBytes) {
  ASSERT_EQ(builtin_files().size(), 3u);
  for (const BuiltinFile& f : builtin_files()) {
    EXPECT_GT(f.end - f.begin, 1000) << f.name;
    ASSERT_TRUE(builtin_bytes(std::string("builtin:") + f.name)) << f.name;
  }
  const auto hdr = builtin_bytes("builtin:rooitou_park_1k.hdr");
  ASSERT_TRUE(hdr);
  EXPECT_EQ(std::string(reinterpret_cast<const char*>(hdr->data()), 10), "#?RADIANCE");
  EXPECT_FALSE(builtin_bytes("builtin:nope.hdr"));
}

TEST(BuiltinFiles, ImagesOpenFromMemory) {
  ImageSource s = open_image_source("builtin:rooitou_park_1k.hdr");
  ASSERT_TRUE(s.in) << s.why;
  EXPECT_EQ(s.in->spec().width, 1024);
  EXPECT_EQ(s.in->spec().height, 512);
  std::vector<float> px(size_t(1024) * 512 * 3);
  ASSERT_TRUE(s.in->read_image(0, 0, 0, 3, OIIO::TypeDesc::FLOAT, px.data()));
  float peak = 0;
  for (float v : px) peak = std::max(peak, v);
  EXPECT_GT(peak, 1000.0f);  // the sun disk
  ImageSource bad = open_image_source("builtin:nope.jpg");
  EXPECT_FALSE(bad.in);
  EXPECT_NE(bad.why.find("builtin:bark_brown_01.jpg"), std::string::npos) << bad.why;
}

TEST(BuiltinFiles, SceneLoadsInAFolderWithoutData) {
  const std::string dir = test::temp_dir("builtin_files_empty");
  const auto cwd = std::filesystem::current_path();
  std::filesystem::current_path(dir);
  EXPECT_NO_THROW(parse_scene(kPhotoTree, dir + "/scene.json", dir));
  const SceneDesc d = default_scene();  // its photo and HDRI come from the binary too
  std::filesystem::current_path(cwd);
  ASSERT_EQ(d.lights.size(), 2u);
  EXPECT_EQ(d.lights[0].file, "builtin:rooitou_park_1k.hdr");
  EXPECT_TRUE(std::filesystem::is_empty(dir));
}

TEST(BuiltinFiles, UnknownNameListsTheNames) {
  const std::string msg = test::error_of(R"({"lights": [{"type": "environment", "file": "builtin:sky.hdr"}]})");
  EXPECT_NE(msg.find("/lights/0/file: unknown builtin file \"builtin:sky.hdr\"; builtin files: builtin:rooitou_park_1k.hdr, "
                     "builtin:bark_brown_01.jpg, builtin:bark_brown_01_disp.jpg"),
            std::string::npos)
      << msg;
  std::string photo = kPhotoTree;
  photo.replace(photo.find("bark_brown_01.jpg"), 17, "bark.jpg");
  EXPECT_NE(test::error_of(photo).find("/photo/albedo: unknown builtin file \"builtin:bark.jpg\""), std::string::npos)
      << test::error_of(photo);
  // Textures go through OpenImageIO's texture system, which reads files only.
  EXPECT_NE(test::error_of(R"({"materials": {"m": {"type": "diffuse", "base_color_texture": "builtin:bark_brown_01.jpg"}}})")
                .find("are for environment maps and bark images only"),
            std::string::npos);
}

TEST(BuiltinFiles, EnvironmentClampIsPositive) {
  EXPECT_NE(test::error_of(R"({"lights": [{"type": "environment", "file": "builtin:rooitou_park_1k.hdr", "clamp": 0}]})")
                .find("/lights/0/clamp: clamp must be > 0"),
            std::string::npos);
  const SceneDesc d = parse_scene(R"({"lights": [{"type": "environment", "file": "builtin:rooitou_park_1k.hdr", "clamp": 50}]})",
                                  "scene.json", ".");
  EXPECT_EQ(d.lights[0].clamp, 50.0f);
}

TEST(BuiltinFilesCli, RendersFromAnEmptyFolderAndRefusesUnknownNames) {
  const std::string dir = test::temp_dir("builtin_files_cli"), data = test::temp_dir("builtin_files_cli_out");
  const std::string ok = R"({"render": {"resolution": [16, 8], "spp": 2},
    "lights": [{"type": "environment", "file": "builtin:rooitou_park_1k.hdr", "clamp": 50},
               {"type": "sun", "direction": [0.6, 0.2, -0.8], "irradiance": 6}],
    "objects": [{"type": "sphere", "radius": 1}]})";
  test::write_text(data + "/ok.json", ok);
  auto r =
      test::run_command("cd " + dir + " && " PHELLEM_BINARY " render " + data + "/ok.json -o " + data + "/ok.exr --quiet 2>&1");
  EXPECT_EQ(r.exit_code, 0) << r.output;
  EXPECT_TRUE(std::filesystem::is_regular_file(data + "/ok.exr"));
  std::string bad = ok;
  bad.replace(bad.find("rooitou_park_1k"), 15, "rooitou");
  test::write_text(data + "/bad.json", bad);
  r = test::run_phellem("render " + data + "/bad.json -o " + data + "/bad.exr");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.output.find("phellem: error: " + data +
                          "/bad.json: /lights/0/file: unknown builtin file \"builtin:rooitou.hdr\"; "
                          "builtin files: builtin:rooitou_park_1k.hdr"),
            std::string::npos)
      << r.output;
}

}  // namespace
}  // namespace phellem
