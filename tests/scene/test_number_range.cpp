// A number too large for its field is "out of range" and the message gives the valid range
// (1e300 is finite: calling it "not finite" was wrong), at its JSON path.
#include <gtest/gtest.h>

#include <string>

#include "scene/scene_parser.h"
#include "tests/support/scene_errors.h"
#include "util/errors.h"

namespace phellem {
namespace {

using test::error_of;

TEST(NumberRange, LargeFiniteNumbersAreOutOfRangeWithTheRange) {
  const auto msg = error_of(R"({"camera": {"position": [0, 1e300, 5]}})");
  EXPECT_NE(msg.find("scene.json: /camera/position/1: number out of range: 1e300; valid range [-3.4e38, 3.4e38]"),
            std::string::npos)
      << msg;
  const auto neg = error_of(R"({"objects": [{"type": "sphere", "radius": 1, "center": [-4e38, 0, 0]}]})");
  EXPECT_NE(neg.find("scene.json: /objects/0/center/0: number out of range: -4e38; valid range [-3.4e38, 3.4e38]"),
            std::string::npos)
      << neg;
  EXPECT_EQ(error_of(R"({"camera": {"position": [0, 1, 5], "fov_deg": 1e300}})").find("not finite"), std::string::npos);
}

TEST(NumberRange, OverflowingLiteralsAreOutOfRangeAtTheirPath) {
  // 1e999 overflows a double while the JSON is read: still named by its path.
  const auto msg = error_of(R"({"camera": {"fov_deg": 1e999}})");
  EXPECT_NE(msg.find("scene.json: /camera/fov_deg: number out of range: 1e999; valid range [-3.4e38, 3.4e38]"), std::string::npos)
      << msg;
  const auto in_array =
      error_of(R"({"objects": [{"type": "sphere", "radius": 1}, {"type": "sphere", "center": [0, -1e999, 0]}]})");
  EXPECT_NE(in_array.find("scene.json: /objects/1/center/1: number out of range"), std::string::npos) << in_array;
}

TEST(NumberRange, IntegersOutOfRangeGiveTheRange) {
  const auto msg = error_of(R"({"render": {"tessellation": {"max_triangles": 99999999999}}})");
  EXPECT_NE(msg.find("scene.json: /render/tessellation/max_triangles: "), std::string::npos) << msg;
  EXPECT_NE(msg.find("[-2147483648, 2147483647]"), std::string::npos) << msg;
}

}  // namespace
}  // namespace phellem
