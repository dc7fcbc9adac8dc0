// render.spp and render.max_depth: every refusal states the documented range, whether the
// value is too small, too large, too large for an int, or not an integer at all.
#include <gtest/gtest.h>

#include <string>

#include "scene/scene_parser.h"
#include "tests/support/scene_errors.h"
#include "util/errors.h"

namespace phellem {
namespace {

using test::error_of;

TEST(RenderRanges, SppMessagesStateTheRange) {
  for (const std::string v : {"0", "1048577", "-3", "99999999999", "2.5", "\"many\""}) {
    const auto msg = error_of(R"({"render": {"spp": )" + v + "}}");
    EXPECT_NE(msg.find("scene.json: /render/spp: "), std::string::npos) << v << ": " << msg;
    EXPECT_NE(msg.find("[1, 1048576]"), std::string::npos) << v << ": " << msg;
  }
  EXPECT_EQ(error_of(R"({"render": {"spp": 1048576}})"), "<no error>");
}

TEST(RenderRanges, MaxDepthMessagesStateTheRange) {
  for (const std::string v : {"0", "1025", "-1", "99999999999", "1.5"}) {
    const auto msg = error_of(R"({"render": {"max_depth": )" + v + "}}");
    EXPECT_NE(msg.find("scene.json: /render/max_depth: "), std::string::npos) << v << ": " << msg;
    EXPECT_NE(msg.find("[1, 1024]"), std::string::npos) << v << ": " << msg;
  }
  EXPECT_EQ(error_of(R"({"render": {"max_depth": 1024}})"), "<no error>");
}

}  // namespace
}  // namespace phellem
