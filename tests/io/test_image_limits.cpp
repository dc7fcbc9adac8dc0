// Images are refused from their header alone when they are larger than io/image_limits.h
// allows (2^28 pixels, and never more than a quarter of physical memory as floats): a tiny
// Radiance .hdr whose header claims 100000 x 100000 pixels used to crash OpenImageIO's
// texture set-up, and a 60000 x 60000 one ended in bad_alloc as a dressing sample, weakness
// map or stress image. Each is now an exit-2 error at the JSON path that named the image.
#include <gtest/gtest.h>

#include <fstream>
#include <string>

#include "io/image_limits.h"
#include "renderer/textures.h"
#include "tests/support/test_util.h"
#include "util/errors.h"

namespace phellem {
namespace {

using test::lying_hdr;

TEST(ImageLimits, PixelAndMemoryLimits) {
  const double gib = 1024.0 * 1024.0 * 1024.0;
  EXPECT_FALSE(image_size_problem(16384, 16384, 1, 4, 64 * gib));  // 2^28 pixels, 4 GiB of 64
  const auto over = image_size_problem(16385, 16384, 1, 4, 64 * gib);
  ASSERT_TRUE(over);
  EXPECT_NE(over->find("at most 268435456"), std::string::npos) << *over;
  EXPECT_TRUE(image_size_problem(100000, 100000, 1, 3, 1e15));  // no amount of memory lifts the pixel limit
  EXPECT_TRUE(image_size_problem(2048, 2048, 2048, 1, 1e15));   // volume images count every slice
  // 8192 x 8192 RGBA floats are 1 GiB: refused with 2 GiB of memory, read with 4 GiB.
  const auto memory = image_size_problem(8192, 8192, 1, 4, 2 * gib);
  ASSERT_TRUE(memory);
  EXPECT_NE(memory->find("more than a quarter of this machine's 2.0 GiB"), std::string::npos) << *memory;
  EXPECT_FALSE(image_size_problem(8192, 8192, 1, 4, 4 * gib));
  EXPECT_TRUE(image_size_problem(0, 16, 1, 3, 64 * gib));
  EXPECT_TRUE(image_size_problem(16, 16, 1, 0, 64 * gib));
}

TEST(ImageLimits, HeaderIsReadWithoutDecoding) {
  const std::string dir = test::temp_dir("image_limits_header");
  std::string why;
  EXPECT_FALSE(read_image_header(lying_hdr(dir + "/big.hdr", 100000, 100000), &why));
  EXPECT_NE(why.find("cannot read image " + dir + "/big.hdr: the image is 100000x100000"), std::string::npos) << why;
  const auto small = read_image_header(lying_hdr(dir + "/small.hdr", 4, 2), &why);
  ASSERT_TRUE(small) << why;
  EXPECT_EQ(small->width, 4);
  EXPECT_EQ(small->height, 2);
}

TEST(ImageLimits, TextureWhoseHeaderClaimsTenGigapixelsIsAUserError) {
  const std::string dir = test::temp_dir("image_limits_texture");
  TextureStore store;
  TextureDesc d;
  d.file = lying_hdr(dir + "/big.hdr", 100000, 100000);
  d.srgb = false;
  try {
    store.add(d, {"scene.json", "/materials/m/base_color_texture"});
    FAIL() << "accepted";
  } catch (const UserError& e) {
    EXPECT_EQ(e.where(), "/materials/m/base_color_texture");
    EXPECT_NE(e.detail().find("100000x100000"), std::string::npos) << e.what();
  }
}

// Runs phellem in a 4 GiB address space (a build without the check fails the test with a
// crash or exit 1 instead of taking the machine's memory).
void expect_refused(const std::string& args, const std::string& prefix, const std::string& says) {
  const auto r = test::run_phellem_limited(args, 4096, 120);
  EXPECT_EQ(r.exit_code, 2) << args << ": " << r.output;
  EXPECT_EQ(r.output.rfind(prefix, 0), 0u) << args << ": " << r.output;
  EXPECT_NE(r.output.find(says), std::string::npos) << args << ": " << r.output;
}

TEST(ImageLimits, RenderRefusesAHugeTexture) {
  const std::string dir = test::temp_dir("image_limits_render");
  lying_hdr(dir + "/big.hdr", 100000, 100000);
  const std::string scene = dir + "/scene.json";
  test::write_text(scene, R"({"render": {"resolution": [8, 8], "spp": 1},
    "materials": {"m": {"type": "diffuse", "base_color_texture": {"file": "big.hdr", "srgb": false}}},
    "objects": [{"type": "plane", "material": "m", "point": [0, 0, 0], "normal": [0, 1, 0], "size": 4}]})");
  expect_refused("render " + scene + " -o " + dir + "/o.exr", "phellem: error: " + scene + ": /materials/m/base_color_texture: ",
                 "100000x100000 = 10000000000 pixels; at most 268435456");
  // The same image as an OBJ material's map_Kd.
  test::write_text(dir + "/m.mtl", "newmtl bigtex\nKd 1 1 1\nmap_Kd big.hdr\n");
  test::write_text(dir + "/m.obj", "mtllib m.mtl\nv 0 0 0\nv 1 0 0\nv 1 1 0\nusemtl bigtex\nf 1 2 3\n");
  test::write_text(scene, R"({"render": {"resolution": [8, 8], "spp": 1}, "objects": [{"type": "mesh", "file": "m.obj"}]})");
  expect_refused("render " + scene + " -o " + dir + "/o.exr", "phellem: error: ", "big.hdr: the image is 100000x100000");
}

std::string tree_with_bark(const std::string& bark) {
  return R"({"objects": [{"type": "tree", "name": "t", "axis": [[0, 0, 0], [0, 0.3, 0]], "radius": [0.05, 0.04], "bark": )" +
         bark + "}]}";
}

TEST(ImageLimits, SimulateRefusesHugeSceneImages) {
  const std::string dir = test::temp_dir("image_limits_simulate");
  lying_hdr(dir + "/big.hdr", 60000, 60000);
  const std::string scene = dir + "/scene.json";
  const std::string says = "cannot read image " + dir + "/big.hdr: the image is 60000x60000 = 3600000000 pixels";
  const struct {
    const char* bark;
    const char* path;
  } cases[] = {
      {R"({"model": "strips", "steps": 20, "growth_rate": 1.01, "dressing": {"epidermis": {"image": "big.hdr", "size": [0.1, 0.1]}}})",
       "/objects/0/bark/dressing/epidermis/image"},
      {R"({"model": "strips", "steps": 20, "growth_rate": 1.01, "weakness_map": "big.hdr"})", "/objects/0/bark/weakness_map"},
      {R"({"model": "stress", "pattern": "image", "stress_image": "big.hdr", "iterations": 5})", "/objects/0/bark/stress_image"},
  };
  for (const auto& c : cases) {
    test::write_text(scene, tree_with_bark(c.bark));
    expect_refused("simulate " + scene + " -o " + dir + "/out", "phellem: error: " + scene + ": " + c.path + ": ", says);
  }
}

}  // namespace
}  // namespace phellem
