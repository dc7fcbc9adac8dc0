// An emissive material's colour and strength each lie in [0, 1e6] (issue 43): 3e38 × 10
// overflowed a float, and every sample that saw it was discarded with a warning. Refused at
// the JSON path; the brightest allowed values still parse.
#include <gtest/gtest.h>

#include <string>

#include "scene/scene_parser.h"
#include "tests/support/scene_errors.h"

namespace phellem {
namespace {

std::string emissive(const std::string& fields) {
  return R"({"materials": {"lamp": {"type": "emissive", )" + fields + R"(}}})";
}

TEST(EmissionRange, HugeColourOrStrengthIsRefusedAtItsPath) {
  const std::string huge_color = test::error_of(emissive(R"("color": [3e38, 1, 1])"));
  EXPECT_NE(huge_color.find("scene.json: /materials/lamp/color: colour components must lie in [0, 1e6]"), std::string::npos)
      << huge_color;
  const std::string huge_strength = test::error_of(emissive(R"("color": [1, 1, 1], "strength": 1e7)"));
  EXPECT_NE(huge_strength.find("scene.json: /materials/lamp/strength: must lie in [0, 1e6]"), std::string::npos)
      << huge_strength;
  // Negative ones were refused before; still so.
  EXPECT_NE(test::error_of(emissive(R"("color": [-1, 1, 1])")).find("/materials/lamp/color: colour components must be >= 0"),
            std::string::npos);
  EXPECT_NE(test::error_of(emissive(R"("strength": -1)")).find("/materials/lamp/strength: must be >= 0"), std::string::npos);
}

TEST(EmissionRange, TheBoundsThemselvesParse) {
  const SceneDesc s = parse_scene(emissive(R"("color": [1e6, 0, 2], "strength": 1e6)"), "scene.json", ".");
  ASSERT_EQ(s.materials.size(), 1u);
  EXPECT_FLOAT_EQ(s.materials[0].emission[0], 1e6f);
  EXPECT_FLOAT_EQ(s.materials[0].strength, 1e6f);
}

}  // namespace
}  // namespace phellem
