// A key given twice in one JSON object is refused, naming the JSON path of the second one
// (the JSON parser alone would silently keep the last).
#include <gtest/gtest.h>

#include <string>

#include "scene/scene_parser.h"
#include "tests/support/scene_errors.h"
#include "util/errors.h"

namespace phellem {
namespace {

using test::error_of;

TEST(DuplicateKeys, AreRefusedAtTheirPath) {
  const auto top = error_of(R"({"render": {"spp": 4}, "render": {"spp": 8}})");
  EXPECT_NE(top.find("scene.json: /render: duplicate key \"render\""), std::string::npos) << top;
  const auto nested = error_of(R"({"camera": {"fov_deg": 30, "position": [0, 1, 5], "fov_deg": 60}})");
  EXPECT_NE(nested.find("scene.json: /camera/fov_deg: duplicate key \"fov_deg\""), std::string::npos) << nested;
  const auto in_array = error_of(R"({"objects": [{"type": "sphere", "radius": 1},
                                                  {"type": "sphere", "radius": 1, "radius": 2}]})");
  EXPECT_NE(in_array.find("scene.json: /objects/1/radius: duplicate key \"radius\""), std::string::npos) << in_array;
  const auto deep = error_of(R"({"objects": [{"type": "mesh", "procedural": {"shape": "sheet"},
                                              "bark": {"model": "stress", "crack": {"noise": 0.1, "noise": 0.2}}}]})");
  EXPECT_NE(deep.find("scene.json: /objects/0/bark/crack/noise: duplicate key \"noise\""), std::string::npos) << deep;
}

TEST(DuplicateKeys, TheSameKeyInDifferentObjectsIsFine) {
  EXPECT_NO_THROW(parse_scene(R"({"objects": [{"type": "sphere", "radius": 1}, {"type": "sphere", "radius": 2}],
                                   "camera": {"position": [0, 1, 5]}, "render": {"seed": 1}})",
                              "scene.json", "."));
}

}  // namespace
}  // namespace phellem
