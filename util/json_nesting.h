// A bound on how deeply JSON text nests, checked on the raw text before any parser sees it.
// The parsers that read our JSON (nlohmann's, and tinygltf's conversion of it into a
// tinygltf::Value) recurse once per level of [ or {: a hostile file of 200000 nested
// brackets overflows the stack (SIGSEGV) long before they could report anything. Well-kept
// JSON readers bound the depth for the same reason (serde_json stops at 128 levels, Go's
// encoding/json at 10000).
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

namespace phellem {

// The deepest nesting of arrays and objects accepted: far beyond any real scene or glTF file
// (a glTF's deepest structure, extras aside, is about 6 levels), and shallow enough that a
// recursive parser's frames for it fit a thread's stack with room to spare.
inline constexpr size_t kMaxJsonNesting = 512;

// Throws UserError(file, "<prefix>line L, column C", ...) at the first [ or { that opens
// level kMaxJsonNesting + 1, counting brackets outside strings only (a backslash escapes the
// next character inside a string). Unbalanced or otherwise invalid text passes: the parser
// reports that with its own message. `prefix` places the text in its file (e.g. "JSON chunk,
// " for a GLB); the lines and columns count from the start of `text`.
void check_json_nesting(std::string_view text, const std::string& file, const std::string& prefix = "");

}  // namespace phellem
