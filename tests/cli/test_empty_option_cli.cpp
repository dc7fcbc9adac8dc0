// An option given an empty string (`--view ""`, `-o ''`) is a mistake, refused with the
// option named, not taken as "not given".
#include <gtest/gtest.h>

#include <filesystem>

#include "tests/support/test_util.h"

namespace phellem {

TEST(EmptyOptionCli, EveryOptionRefusesAnEmptyValue) {
  const std::string d = test::temp_dir("empty_option");
  test::write_text(d + "/scene.json", R"({"objects": [{"type": "sphere", "center": [0, 0, 0], "radius": 1}]})");
  const std::string scene = d + "/scene.json";
  const std::string render = "render " + scene + " --res 8x8 --spp 1 -o " + d + "/x.exr ";
  const std::string turntable = "turntable " + scene + " --frames 1 --res 8x8 --spp 1 -o " + d + "/f_%02d.exr ";
  struct Case {
    std::string args, option;
  };
  const std::vector<Case> cases = {
      {"render " + scene + " --res 8x8 --spp 1 -o ''", "-o"},
      {"render " + scene + " --res 8x8 --spp 1 --output ''", "--output"},
      {render + "--view ''", "--view"},
      {render + "--png ''", "--png"},
      {render + "--stats ''", "--stats"},
      {render + "--spp ''", "--spp"},
      {render + "--threads ''", "--threads"},
      {render + "--seed ''", "--seed"},
      {render + "--res ''", "--res"},
      {turntable + "--view ''", "--view"},
      {turntable + "--degrees ''", "--degrees"},
      {turntable + "--mp4 ''", "--mp4"},
      {"turntable " + scene + " --frames '' -o " + d + "/f_%02d.exr", "--frames"},
      {"simulate " + scene + " -o ''", "-o"},
      {"render '' --res 8x8 --spp 1 -o " + d + "/x.exr", "SCENE"},
  };
  for (const Case& c : cases) {
    const auto r = test::run_phellem(c.args);
    EXPECT_EQ(r.exit_code, 2) << c.args << "\n" << r.output;
    EXPECT_NE(r.output.find("phellem: error: <command line>: " + c.option + ": "), std::string::npos) << c.args << "\n"
                                                                                                      << r.output;
  }
  EXPECT_FALSE(std::filesystem::exists(d + "/x.exr"));
}

}  // namespace phellem
