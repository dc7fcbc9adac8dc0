// Files a scene names that are hostile (issue 43): a FIFO (which would block its reader for
// ever) is named as one before anything opens it, and a JPEG cut short is refused, not read
// with its missing part grey.
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <OpenImageIO/imageio.h>

#include <string>
#include <vector>

#include "scene/scene_parser.h"
#include "tests/support/test_util.h"
#include "util/errors.h"

namespace phellem {
namespace {

std::string fifo(const std::string& path) {
  EXPECT_EQ(mkfifo(path.c_str(), 0600), 0) << path;
  return path;
}

// A 32 × 32 grey JPEG of noise, whole and cut in half (cut.jpg).
std::string truncated_jpeg(const std::string& dir) {
  std::vector<unsigned char> px(32 * 32);
  uint32_t x = 7;
  for (auto& p : px) p = static_cast<unsigned char>((x = x * 1664525u + 1013904223u) >> 24);
  const std::string whole = dir + "/whole.jpg";
  auto out = OIIO::ImageOutput::create(whole);
  EXPECT_TRUE(out && out->open(whole, OIIO::ImageSpec(32, 32, 1, OIIO::TypeDesc::UINT8)) &&
              out->write_image(OIIO::TypeDesc::UINT8, px.data()) && out->close());
  const std::string bytes = test::read_text(whole);
  test::write_text(dir + "/cut.jpg", bytes.substr(0, bytes.size() / 2));
  return dir + "/cut.jpg";
}

std::string growing_log(const std::string& speed_map_file) {
  return R"({"objects": [{"type": "mesh", "name": "log",
      "procedural": {"shape": "log", "triangles": 3000, "radius": 0.1, "height": 0.3},
      "growth": {"steps": 6, "years": 10, "age_scale": 10, "thickness": 0.03,
                 "speed_map": {"file": ")" +
         speed_map_file + R"("}}}]})";
}

void expect_refused(const std::string& dir, const std::string& json, const std::string& where, const std::string& detail) {
  test::expect_user_error([&] { parse_scene(json, dir + "/s.json", dir); }, where, dir + "/s.json", where, detail);
}

TEST(HostileSceneFiles, AFifoIsNamedAsOneWhereverASceneNamesAFile) {
  const std::string dir = test::temp_dir("scene_fifos");
  const std::string f = fifo(dir + "/f.png");
  const std::string says = f + " is not a regular file (a FIFO); ";
  expect_refused(dir, R"({"materials": {"bark": {"type": "diffuse", "base_color_texture": "f.png"}}})",
                 "/materials/bark/base_color_texture", says + "a file a scene names is read from a regular file");
  expect_refused(dir, R"({"lights": [{"type": "environment", "file": "f.png"}]})", "/lights/0/file", says);
  expect_refused(dir, growing_log("f.png"), "/objects/0/growth/speed_map/file", says);
  expect_refused(dir, R"({"objects": [{"type": "mesh", "file": "f.png"}]})", "/objects/0/file", says);
}

TEST(HostileSceneFiles, ATruncatedJpegSpeedMapIsRefused) {
  const std::string dir = test::temp_dir("scene_cut_jpeg");
  const std::string cut = truncated_jpeg(dir);
  expect_refused(dir, growing_log("cut.jpg"), "/objects/0/growth/speed_map/file",
                 "cannot read image " + cut + ": the file is damaged or cut short (JPEG error: Premature end of JPEG file");
  EXPECT_NO_THROW(parse_scene(growing_log("whole.jpg"), dir + "/s.json", dir));
}

}  // namespace
}  // namespace phellem
