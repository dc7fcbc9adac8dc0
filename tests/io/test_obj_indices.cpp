// OBJ face indices are checked against the elements defined before their line, before
// tinyobjloader converts them (its atoi wraps 4294967299 to a valid 3, and it drops
// out-of-range vt/vn indices without a word): every bad index is an exit-2 error naming the
// line, valid absolute and relative ones still load.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "io/mesh_io.h"
#include "tests/support/test_util.h"
#include "util/errors.h"

namespace phellem {
namespace {

const char* kHeader = "v 0 0 0\nv 1 0 0\nv 1 1 0\nvt 0 0\nvt 1 0\nvn 0 0 1\n";  // 3 v, 2 vt, 1 vn; faces from line 7

struct BadObj {
  std::string name, text, where, expect;
};

TEST(ObjIndices, OutOfRangeIndicesAreErrorsNamingTheLine) {
  const std::vector<BadObj> cases = {
      {"wraps to 3 in 32 bits", std::string(kHeader) + "f 1 2 4294967299\n", "line 7",
       "vertex index 4294967299 is out of range: 3 v lines"},
      {"past the vertices", std::string(kHeader) + "f 1 2 4\n", "line 7", "vertex index 4 is out of range"},
      {"zero", std::string(kHeader) + "f 0 1 2\n", "line 7", "vertex index 0 is out of range"},
      {"relative too far back", std::string(kHeader) + "f -1 -2 -4\n", "line 7", "vertex index -4 is out of range"},
      {"texture coordinate", std::string(kHeader) + "f 1/1 2/3 3/1\n", "line 7",
       "texture coordinate index 3 is out of range: 2 vt lines"},
      {"texture coordinate, huge", std::string(kHeader) + "f 1/4294967297 2/1 3/1\n", "line 7",
       "texture coordinate index 4294967297 is out of range"},
      {"relative texture coordinate", std::string(kHeader) + "f 1/-3 2/1 3/1\n", "line 7",
       "texture coordinate index -3 is out of range"},
      {"normal", std::string(kHeader) + "f 1//1 2//2 3//1\n", "line 7", "normal index 2 is out of range: 1 vn line"},
      {"normal after a texture coordinate", std::string(kHeader) + "f 1/1/1 2/2/9 3/1/1\n", "line 7",
       "normal index 9 is out of range"},
      {"no normals at all", "v 0 0 0\nv 1 0 0\nv 1 1 0\nf 1//1 2//1 3//1\n", "line 4",
       "normal index 1 is out of range: 0 vn lines"},
      // Only elements defined before the face count, as OBJ defines relative indices.
      {"vertex defined after the face", "v 0 0 0\nv 1 0 0\nv 1 1 0\nf 1 2 4\nv 0 1 0\n", "line 4",
       "vertex index 4 is out of range: 3 v lines"},
      {"second face, Windows line ends", "v 0 0 0\r\nv 1 0 0\r\nv 1 1 0\r\nf 1 2 3\r\nf 3 2 7\r\n", "line 5", "vertex index 7"},
      {"not a number", std::string(kHeader) + "f 1 2 3x\n", "line 7", "vertex index \"3x\" is not an integer"},
      {"four indices", std::string(kHeader) + "f 1/1/1/1 2 3\n", "line 7", "more than three indices"},
  };
  for (const auto& c : cases) {
    const std::string dir = test::temp_dir("obj_indices_" + std::to_string(&c - cases.data()));
    const std::string file = dir + "/m.obj";
    test::write_text(file, c.text);
    test::expect_user_error([&] { load_obj(file); }, c.name, file, c.where, c.expect);
  }
}

TEST(ObjIndices, TheCliExitsTwoNamingFileAndLine) {
  const std::string dir = test::temp_dir("obj_indices_cli");
  test::write_text(dir + "/m.obj", std::string(kHeader) + "f 1 2 3\nf 1 2 4294967299\n");
  test::write_text(dir + "/scene.json",
                   R"({"objects": [{"type": "mesh", "file": "m.obj"}], "render": {"resolution": [8, 8], "spp": 1}})");
  const auto r = test::run_phellem("render " + dir + "/scene.json -o " + dir + "/o.exr");
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_EQ(r.output.rfind("phellem: error: " + dir + "/m.obj: line 8: ", 0), 0u) << r.output;
}

TEST(ObjIndices, ValidAbsoluteAndRelativeIndicesLoad) {
  const std::string dir = test::temp_dir("obj_indices_ok");
  // Two quads: one absolute with v/vt/vn, one relative (v//vn), the second quad's vertices
  // defined after the first face.
  test::write_text(dir + "/m.obj", std::string(kHeader) +
                                       "v 0 1 0\nf 1/1/1 2/2/1 3/2/1 4/1/1\n"
                                       "v 0 0 1\nv 1 0 1\nv 1 1 1\n  f\t-3//-1 -2//-1 -1//-1\n");
  const LoadedModel m = load_obj(dir + "/m.obj");
  size_t triangles = 0;
  for (const auto& mesh : m.meshes) triangles += mesh.triangle_count();
  EXPECT_EQ(triangles, 3u);
}

}  // namespace
}  // namespace phellem
