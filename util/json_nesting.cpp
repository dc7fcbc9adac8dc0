#include "util/json_nesting.h"

#include "util/errors.h"

namespace phellem {

void check_json_nesting(std::string_view text, const std::string& file, const std::string& prefix) {
  size_t depth = 0, line = 1, line_start = 0;
  bool in_string = false, escaped = false;
  for (size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (c == '\n') {
      ++line;
      line_start = i + 1;
    }
    if (in_string) {
      // Brackets inside strings are text; \" does not end the string.
      if (escaped)
        escaped = false;
      else if (c == '\\')
        escaped = true;
      else if (c == '"')
        in_string = false;
      continue;
    }
    if (c == '"') {
      in_string = true;
    } else if (c == '[' || c == '{') {
      if (++depth > kMaxJsonNesting)
        throw UserError(file, prefix + "line " + std::to_string(line) + ", column " + std::to_string(i - line_start + 1),
                        "arrays and objects nest deeper than " + std::to_string(kMaxJsonNesting) + " levels; at most " +
                            std::to_string(kMaxJsonNesting) + " are allowed (deeper JSON would overflow the parser's stack)");
    } else if ((c == ']' || c == '}') && depth > 0) {
      --depth;  // an unmatched one is the parser's to report
    }
  }
}

}  // namespace phellem
