// The numbers of an OBJ file's v, vt and vn lines are checked where they are read (issue 43):
// tinyobjloader turned "nan" and "inf" into 0 without a word and 1e39 into a float infinity.
// Each is an exit-2 error naming the line; texture coordinates are also bounded by kMaxUv.
// Ordinary spellings (a sign, no leading digit, an exponent, a tiny value that underflows
// to 0, trailing vertex colours and comments) still load.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "io/mesh_io.h"
#include "tests/support/test_util.h"
#include "util/errors.h"

namespace phellem {
namespace {

const char* kFace = "f 1/1/1 2/2/1 3/3/1\n";

struct BadObj {
  std::string name, text, where, expect;
};

TEST(ObjNumbers, NonFiniteOrOverflowingNumbersAreErrorsNamingTheLine) {
  const std::string ok_v = "v 0 0 0\nv 1 0 0\nv 0 1 0\n", ok_vt = "vt 0 0\nvt 1 0\nvt 0 1\n", ok_vn = "vn 0 0 1\n";
  const std::vector<BadObj> cases = {
      {"v nan", "v nan 0 0\nv 1 0 0\nv 0 1 0\n" + ok_vt + ok_vn + kFace, "line 1", "'v' field 1 \"nan\" is not a finite number"},
      {"v inf", ok_v + "v 0 -inf 0\n" + ok_vt + ok_vn + kFace, "line 4", "'v' field 2 \"-inf\" is not a finite number"},
      {"v 1e39 overflows a float", "v 0 0 0\nv 1e39 0 0\nv 0 1 0\n" + ok_vt + ok_vn + kFace, "line 2",
       "'v' field 1 \"1e39\" is out of range; coordinates must be finite and fit a float"},
      {"v 1e400 overflows a double", "v 0 0 1e400\nv 1 0 0\nv 0 1 0\n" + ok_vt + ok_vn + kFace, "line 1",
       "'v' field 3 \"1e400\" is out of range"},
      {"vt inf", ok_v + "vt inf 0\nvt 1 0\nvt 0 1\n" + ok_vn + kFace, "line 4", "'vt' field 1 \"inf\" is not a finite number"},
      {"vt 2e6", ok_v + "vt 0 0\nvt 1 2e6\nvt 0 1\n" + ok_vn + kFace, "line 5",
       "'vt' field 2 \"2e6\" is out of range; texture coordinates must lie in [-1e6, 1e6]"},
      {"vn nan", ok_v + ok_vt + "vn 0 NaN 1\n" + kFace, "line 7", "'vn' field 2 \"NaN\" is not a finite number"},
      {"v not a number", "v 0 0 0\nv 1 zero 0\nv 0 1 0\n" + ok_vt + ok_vn + kFace, "line 2", "'v' field 2 \"zero\" is not a finite number"},
  };
  for (const auto& c : cases) {
    const std::string dir = test::temp_dir("obj_numbers_" + std::to_string(&c - cases.data()));
    const std::string file = dir + "/m.obj";
    test::write_text(file, c.text);
    test::expect_user_error([&] { load_obj(file); }, c.name, file, c.where, c.expect);
  }
}

TEST(ObjNumbers, OrdinarySpellingsLoad) {
  const std::string dir = test::temp_dir("obj_numbers_ok");
  test::write_text(dir + "/m.obj",
                   "v +0 -0 .0\nv 1. 0 1e-400\nv 0 1E0 0 0.5 0.25 0.125\nvt 1e6 -1e6\nvt 0.5\nvt 0 1 0\n"
                   "vn 0 0 1 # a comment\n" +
                       std::string(kFace));
  const LoadedModel m = load_obj(dir + "/m.obj");
  ASSERT_EQ(m.meshes.size(), 1u);
  EXPECT_FLOAT_EQ(m.meshes[0].uvs[0].x(), 1e6f);
}

TEST(ObjNumbers, TheCliExitsTwoNamingFileAndLine) {
  const std::string dir = test::temp_dir("obj_numbers_cli");
  test::write_text(dir + "/m.obj", "v 0 0 0\nv 1 0 0\nv 0 1e39 0\nf 1 2 3\n");
  test::write_text(dir + "/scene.json",
                   R"({"objects": [{"type": "mesh", "file": "m.obj"}], "render": {"resolution": [8, 8], "spp": 1}})");
  const auto r = test::run_phellem("render " + dir + "/scene.json -o " + dir + "/o.exr");
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_EQ(r.output.rfind("phellem: error: " + dir + "/m.obj: line 3: ", 0), 0u) << r.output;
}

}  // namespace
}  // namespace phellem
