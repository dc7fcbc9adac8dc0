// Cambial growth of a tree object from the command line: `simulate` grows its trunk and
// branch as one surface; a tree with strip bark cannot grow (exit 2 at its growth block).
#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "tests/support/test_util.h"

namespace phellem {
namespace {

// A small tree with one branch; `bark` spliced in.
std::string tree_scene(const std::string& bark = "") {
  return R"({"objects": [{"type": "tree", "name": "tree",
    "axis": [[0, 0, 0], [0.02, 0.6, 0.01], [0.0, 1.2, 0.02]], "radius": [0.12, 0.1, 0.08],
    "branches": [{"attach": 0.5, "azimuth_deg": 20, "angle_deg": 50, "length": 0.5, "radius": [0.05, 0.03]}],)" +
         bark + R"(
    "growth": {"steps": 3, "years": 6, "age_scale": 20, "weibull_c": 1, "thickness": 0.02, "edge_length": [0.012, 0.036]}}]})";
}

TEST(GrowthTreeCli, ATreeGrowsItsTrunkAndBranchAsOneSurface) {
  const std::string dir = test::temp_dir("tree_growth");
  const std::string scene = dir + "/scene.json";
  test::write_text(scene, tree_scene());
  const auto r =
      test::run_phellem_limited("simulate " + scene + " -o " + dir + "/out --stats " + dir + "/stats.json --quiet", 8192, 240);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  std::ifstream f(dir + "/stats.json");
  const nlohmann::json stats = nlohmann::json::parse(f);
  EXPECT_EQ(stats["growth"]["steps"], 3);
  EXPECT_GT(stats["growth"]["vertices_start"].get<long>(), 500);
  EXPECT_GT(test::read_text(dir + "/out/tree.glb").size(), 1000u);
}

TEST(GrowthTreeCli, ATreeWithStripBarkCannotGrow) {
  const std::string dir = test::temp_dir("tree_growth_strips");
  const std::string scene = dir + "/scene.json";
  test::write_text(scene, tree_scene(R"( "bark": {"model": "strips"},)"));
  const auto r = test::run_phellem_limited("simulate " + scene + " -o " + dir + "/out --quiet", 8192, 60);
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_EQ(r.output.rfind("phellem: error: " + scene + ": /objects/0/growth: ", 0), 0u) << r.output;
  EXPECT_NE(r.output.find("strip model"), std::string::npos) << r.output;
}

}  // namespace
}  // namespace phellem
