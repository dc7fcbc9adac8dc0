// Strip bark starts growth_rate^steps times smaller than the scene's tree (the shrinking
// strategy, Lefebvre & Neyret 2002 sec. 5.2). A growth that overflows (1.5^2000) used to
// crash StripModel::init_strip; it is now refused at the JSON path of `steps` with the
// number of steps the given growth_rate allows, and that many steps run. Dilatation bulges,
// which raise the growth where they sit, are bounded the same way.
#include <gtest/gtest.h>

#include <string>

#include "bark/strips/strip_params.h"
#include "tests/support/test_util.h"

namespace phellem {
namespace {

std::string scene_with_bark(const std::string& bark) {
  return R"({"objects": [{"type": "tree", "name": "t", "axis": [[0, 0, 0], [0, 0.3, 0]], "radius": [0.05, 0.04], "bark": )" +
         bark + "}]}";
}

TEST(StripGrowthCli, OverflowingGrowthIsRefusedAtSteps) {
  const std::string dir = test::temp_dir("strip_growth");
  const std::string scene = dir + "/scene.json";
  test::write_text(scene, scene_with_bark(R"({"model": "strips", "growth_rate": 1.5, "steps": 2000})"));
  const auto r = test::run_phellem_limited("simulate " + scene + " -o " + dir + "/out", 8192, 120);
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_EQ(r.output.rfind("phellem: error: " + scene + ": /objects/0/bark/steps: ", 0), 0u) << r.output;
  EXPECT_NE(r.output.find("growth_rate 1.5 allows at most 34 steps"), std::string::npos) << r.output;
  // One step past the limit is refused, the limit itself runs.
  test::write_text(scene, scene_with_bark(R"({"model": "strips", "growth_rate": 1.5, "steps": 35})"));
  const auto past = test::run_phellem_limited("simulate " + scene + " -o " + dir + "/out", 8192, 120);
  EXPECT_EQ(past.exit_code, 2) << past.output;
  EXPECT_NE(past.output.find("allows at most 34 steps"), std::string::npos) << past.output;
  test::write_text(scene, scene_with_bark(R"({"model": "strips", "growth_rate": 1.5, "steps": 34})"));
  const auto at = test::run_phellem_limited("simulate " + scene + " -o " + dir + "/out", 8192, 300);
  EXPECT_EQ(at.exit_code, 0) << at.output;
}

TEST(StripGrowthCli, DilatationThatOverflowsTheGrowthIsRefused) {
  // A bulge multiplies the growth exponent by 1 + amount at its centre: 1.01^(60 x 100001).
  const std::string dir = test::temp_dir("strip_growth_bulge");
  const std::string scene = dir + "/scene.json";
  test::write_text(scene, scene_with_bark(R"({"model": "strips", "growth_rate": 1.01, "steps": 60,
      "dilatation": [{"s": 0.1, "theta_deg": 0, "amount": 100000}]})"));
  const auto r = test::run_phellem_limited("simulate " + scene + " -o " + dir + "/out", 8192, 120);
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_EQ(r.output.rfind("phellem: error: " + scene + ": /objects/0/bark/dilatation: ", 0), 0u) << r.output;
  EXPECT_NE(r.output.find("the amounts may sum to at most 22.1"), std::string::npos) << r.output;
}

TEST(StripGrowthCli, StepsAllowedByAGrowthRate) {
  EXPECT_EQ(bark::max_steps_for_growth(1.5), 34);        // 1.5^34 = 9.7e5, 1.5^35 = 1.46e6
  EXPECT_EQ(bark::max_steps_for_growth(10.0 / 9), 131);  // log(1e6) / log(10/9) = 131.1
  EXPECT_EQ(bark::max_steps_for_growth(1.0012), 11519);
  EXPECT_EQ(bark::max_steps_for_growth(1.000001), 1000000);  // the steps limit itself
  bark::StripParams p;
  p.growth_rate = 1.5;
  p.threshold = 1.5;
  p.steps = 2000;
  const auto e = bark::validate(p);
  ASSERT_TRUE(e);
  EXPECT_EQ(e->key, "steps");
  EXPECT_NE(e->message.find("allows at most 34 steps"), std::string::npos) << e->message;
}

}  // namespace
}  // namespace phellem
