// A scene file nested deeper than kMaxJsonNesting levels is refused at the bracket that goes
// too deep, before nlohmann's parser sees it (issue 43: a recursive parser overflows its
// stack on 200000 levels): exit 2 naming the line and column, never a crash.
#include <gtest/gtest.h>

#include <string>

#include "scene/scene_parser.h"
#include "tests/support/scene_errors.h"
#include "tests/support/test_util.h"
#include "util/json_nesting.h"

namespace phellem {
namespace {

// {"camera": {"extra": [[[ ... ]]]}} with `levels` brackets.
std::string deep_scene(size_t levels) {
  return R"({"camera": {"extra": )" + std::string(levels, '[') + std::string(levels, ']') + "}}";
}

TEST(SceneNesting, TooDeepIsRefusedAtItsBracket) {
  const std::string json = deep_scene(200000);
  const std::string where = test::where_refused(json, "deep.json", ".");
  // The two objects are levels 1 and 2, the first [ is at column 22: the 511th, level 513, at 532.
  EXPECT_EQ(where, "line 1, column " + std::to_string(21 + kMaxJsonNesting - 1)) << test::error_of(json);
  EXPECT_NE(test::error_of(json).find("nest deeper than 512 levels"), std::string::npos) << test::error_of(json);
  // At the limit the parser reads it and only then names the unknown key.
  EXPECT_EQ(test::where_refused(deep_scene(kMaxJsonNesting - 2), "deep.json", "."), "/camera/extra");
}

TEST(SceneNesting, TheCliExitsTwoInsteadOfCrashing) {
  const std::string dir = test::temp_dir("scene_nesting");
  test::write_text(dir + "/deep.json", deep_scene(200000));
  const auto r = test::run_phellem_limited("render " + dir + "/deep.json -o " + dir + "/o.exr", 2048, 60);
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_EQ(r.output.rfind("phellem: error: " + dir + "/deep.json: line 1, column ", 0), 0u) << r.output;
}

}  // namespace
}  // namespace phellem
