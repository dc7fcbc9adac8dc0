// JSON nested deeper than kMaxJsonNesting levels is refused from the raw text, before a
// recursive parser overflows its stack on it (issue 43: 200000 nested brackets in a glTF's
// extras crashed with SIGSEGV). Brackets inside strings do not count; the error names the
// line and column of the bracket that goes one level too deep.
#include <gtest/gtest.h>

#include <string>

#include "util/errors.h"
#include "util/json_nesting.h"

namespace phellem {
namespace {

std::string nested(size_t levels, const std::string& inner = "0") {
  return std::string(levels, '[') + inner + std::string(levels, ']');
}

TEST(JsonNesting, AcceptsTheLimitAndRefusesOneLevelMoreAtItsBracket) {
  EXPECT_NO_THROW(check_json_nesting(nested(kMaxJsonNesting), "a.json"));
  const std::string text = "{\"a\":\n  " + nested(kMaxJsonNesting) + "}";  // one level more: the object
  try {
    check_json_nesting(text, "a.json");
    FAIL() << "accepted";
  } catch (const UserError& e) {
    EXPECT_EQ(e.file(), "a.json");
    // The object is level 1; the 512th '[' on line 2 (after two spaces) is level 513.
    EXPECT_EQ(e.where(), "line 2, column " + std::to_string(2 + kMaxJsonNesting));
    EXPECT_NE(e.detail().find("at most 512"), std::string::npos) << e.what();
  }
}

TEST(JsonNesting, RefusesDeepObjectsAndNamesThePrefix) {
  std::string text;
  for (size_t i = 0; i < 200000; ++i) text += "{\"a\":";
  text += "0" + std::string(200000, '}');
  try {
    check_json_nesting(text, "m.glb", "JSON chunk, ");
    FAIL() << "accepted";
  } catch (const UserError& e) {
    EXPECT_EQ(e.where(), "JSON chunk, line 1, column " + std::to_string(5 * kMaxJsonNesting + 1));
  }
}

TEST(JsonNesting, BracketsInStringsDoNotCount) {
  // 600 brackets in a string, with escaped quotes and backslashes that must not end it early.
  const std::string s = "\"\\\\\\\"" + std::string(600, '[') + "\\\"\"";
  EXPECT_NO_THROW(check_json_nesting("{\"k\": " + s + ", \"l\": [1, 2]}", "a.json"));
  // Unbalanced closing brackets are the parser's to report, not a negative depth.
  EXPECT_NO_THROW(check_json_nesting("]]]]" + nested(kMaxJsonNesting), "a.json"));
}

}  // namespace
}  // namespace phellem
