// The procedural `branch_junction` shape from the command line: its parameters are validated at
// their JSON paths (exit 2, `phellem: error:`), and a small junction grows.
#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "tests/support/test_util.h"

namespace phellem {
namespace {

// One mesh object with `procedural` spliced in, growing two steps.
std::string junction_scene(const std::string& procedural) {
  return R"({"objects": [{"type": "mesh", "name": "junction", "procedural": )" + procedural +
         R"(, "growth": {"steps": 2, "years": 4, "age_scale": 10, "weibull_c": 1, "thickness": 0.01}}]})";
}

TEST(ProceduralBranchJunctionCli, BadParametersAreRefusedAtTheirJsonPath) {
  const std::string dir = test::temp_dir("branch_junction_bad");
  const std::string scene = dir + "/scene.json";
  struct Case {
    std::string procedural, where, says;
  };
  const std::string j = R"({"shape": "branch_junction", "radius": 0.1, "height": 0.6, )";
  const std::vector<Case> cases = {
      {j + R"("branch_radius": 0.1})", "/objects/0/procedural/branch_radius", "branch_radius must lie in (0, 0.9 × radius]"},
      {j + R"("branch_radius": -1})", "/objects/0/procedural/branch_radius", "> 0"},
      {j + R"("branch_angle_deg": 100})", "/objects/0/procedural/branch_angle_deg", "[20, 90]"},
      {j + R"("branch_length": 0.15})", "/objects/0/procedural/branch_length", "branch_length must be at least"},
      {j + R"("branch_height": 0.95})", "/objects/0/procedural/branch_height", "must leave through the trunk's side"},
      {j + R"("branch_height": 1.5})", "/objects/0/procedural/branch_height", "(0, 1)"},
      {j + R"("triangles": 100})", "/objects/0/procedural/triangles", "triangles must lie in ["},
      {j + R"("jitter": 0.6})", "/objects/0/procedural/jitter", "[0, 0.45]"},
      {j + R"("branch_side": 1})", "/objects/0/procedural/branch_side", ""},  // unknown key
      // The defaults break a bound the trunk's height sets: reported at the block.
      {R"({"shape": "branch_junction", "radius": 0.1, "height": 0.2})", "/objects/0/procedural",
       "must leave through the trunk's side"},
      // Branch keys on another shape.
      {R"({"shape": "log", "branch_radius": 0.05})", "/objects/0/procedural/branch_radius",
       "belongs to the shape branch_junction only"},
      {R"({"shape": "junction"})", "/objects/0/procedural/shape", "branch_junction"},
  };
  for (const auto& c : cases) {
    test::write_text(scene, junction_scene(c.procedural));
    const auto r = test::run_phellem_limited("simulate " + scene + " -o " + dir + "/out --quiet", 8192, 60);
    EXPECT_EQ(r.exit_code, 2) << c.procedural << "\n" << r.output;
    EXPECT_EQ(r.output.rfind("phellem: error: " + scene + ": " + c.where + ": ", 0), 0u) << c.procedural << "\n" << r.output;
    EXPECT_NE(r.output.find(c.says), std::string::npos) << c.procedural << "\n" << r.output;
  }
}

TEST(ProceduralBranchJunctionCli, ASmallJunctionGrows) {
  const std::string dir = test::temp_dir("branch_junction_grow");
  const std::string scene = dir + "/scene.json";
  test::write_text(scene, junction_scene(R"({"shape": "branch_junction", "triangles": 1200, "radius": 0.1, "height": 0.5,
      "branch_radius": 0.05, "branch_angle_deg": 60, "branch_length": 0.3, "branch_height": 0.4})"));
  const auto r =
      test::run_phellem_limited("simulate " + scene + " -o " + dir + "/out --stats " + dir + "/stats.json --quiet", 8192, 120);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  std::ifstream f(dir + "/stats.json");
  const nlohmann::json stats = nlohmann::json::parse(f);
  EXPECT_EQ(stats["growth"]["steps"], 2);
  EXPECT_GT(stats["growth"]["vertices_start"].get<long>(), 400);
  EXPECT_GT(test::read_text(dir + "/out/junction.glb").size(), 1000u);
}

}  // namespace
}  // namespace phellem
