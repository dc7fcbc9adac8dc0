// tinyobjloader triangulates faces of more than four corners in time growing with the square
// of their corners (issue 43: one face "f 1 1 1 ..." of 200000 corners ran for over two
// minutes). The squared corner counts of large faces are bounded per file: beyond, an exit-2
// error naming the line, at once; ordinary polygons (caps of hundreds of corners) still load.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "io/mesh_io.h"
#include "tests/support/test_util.h"
#include "util/errors.h"

namespace phellem {
namespace {

// Three vertices and one face repeating vertex 1 `corners` times.
std::string repeated_face(int corners) {
  std::string text = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf";
  for (int i = 0; i < corners; ++i) text += " 1";
  return text + "\n";
}

// A convex polygon of `corners` corners, `faces` times over.
std::string convex_faces(int corners, int faces) {
  std::string text;
  for (int i = 0; i < corners; ++i) {
    const double a = 2 * 3.141592653589793 * i / corners;
    text += "v " + std::to_string(std::cos(a)) + " " + std::to_string(std::sin(a)) + " 0\n";
  }
  std::string face = "f";
  for (int i = 1; i <= corners; ++i) {
    face += ' ';
    face += std::to_string(i);
  }
  for (int k = 0; k < faces; ++k) text += face + "\n";
  return text;
}

TEST(ObjLargeFaces, AHugeFaceExitsTwoAtOnceNamingItsLine) {
  const std::string dir = test::temp_dir("obj_large_face");
  const std::string file = dir + "/m.obj";
  test::write_text(file, repeated_face(200000));
  test::write_text(dir + "/scene.json",
                   R"({"objects": [{"type": "mesh", "file": "m.obj"}], "render": {"resolution": [8, 8], "spp": 1}})");
  const auto r = test::run_phellem_limited("render " + dir + "/scene.json -o " + dir + "/o.exr", 4096, 60);
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_EQ(r.output.rfind("phellem: error: " + file + ": line 4: this face has 200000 corners", 0), 0u) << r.output;
  if (r.exit_code == 2)
    test::expect_user_error([&] { load_obj(file); }, "200000 corners", file, "line 4",
                            "the file's sum of those squares reaches 40000000000, more than the 100000000 allowed");
}

TEST(ObjLargeFaces, ManyLargeFacesAddUp) {
  // 1600 faces of 256 corners: 65536 each, the 1526th passes 1e8.
  const std::string dir = test::temp_dir("obj_large_faces_sum");
  const std::string file = dir + "/m.obj";
  test::write_text(file, convex_faces(256, 1600));
  test::expect_user_error([&] { load_obj(file); }, "1600 faces of 256", file, "line " + std::to_string(256 + 1526),
                          "this face has 256 corners");
}

TEST(ObjLargeFaces, OrdinaryPolygonsLoad) {
  const std::string dir = test::temp_dir("obj_large_faces_ok");
  test::write_text(dir + "/caps.obj", convex_faces(256, 100));  // a hundred caps of 256 corners
  const LoadedModel caps = load_obj(dir + "/caps.obj");
  ASSERT_EQ(caps.meshes.size(), 1u);
  EXPECT_EQ(caps.meshes[0].triangle_count(), 100u * 254u);
  test::write_text(dir + "/big.obj", convex_faces(8000, 1));  // 6.4e7: one large face alone is fine
  EXPECT_EQ(load_obj(dir + "/big.obj").meshes[0].triangle_count(), 7998u);
}

}  // namespace
}  // namespace phellem
