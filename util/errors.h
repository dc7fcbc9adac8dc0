// The three kinds of failure (STYLE.md, practice 5): UserError for bad input (exit 2),
// anything else that escapes to main is an internal failure (exit 1).
#pragma once

#include <stdexcept>
#include <string>
#include <string_view>

namespace phellem {

// Where a value came from: the scene file (or "<default scene>") and its JSON path.
struct Location {
  std::string file;  // scene file (or "<default scene>")
  std::string path;  // JSON path, e.g. /objects/2/radius
};

// Bad user input: a scene, a mesh, an image, a parameter out of range. `file` names the file,
// `where` the JSON path or glTF element, `what` what is wrong and what is allowed.
class UserError : public std::runtime_error {
 public:
  UserError(std::string file, std::string where, std::string what)
      : std::runtime_error(compose(file, where, what)), file_(std::move(file)), where_(std::move(where)), what_(std::move(what)) {
  }
  const std::string& file() const { return file_; }
  const std::string& where() const { return where_; }
  const std::string& detail() const { return what_; }

 private:
  static std::string compose(const std::string& f, const std::string& w, const std::string& x) {
    std::string s = f.empty() ? std::string("<command line>") : f;
    if (!w.empty()) s += ": " + w;
    return s + ": " + x;
  }
  std::string file_, where_, what_;
};

// `text` as it may be shown on a terminal: valid UTF-8 and newlines and tabs pass; any other
// control character and every byte that is not part of a valid UTF-8 sequence becomes \xNN
// (error messages quote bytes from broken files).
inline std::string printable(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  auto escape = [&](unsigned char c) {
    static const char* hex = "0123456789ABCDEF";
    out += "\\x";
    out += hex[c >> 4];
    out += hex[c & 15];
  };
  for (size_t i = 0; i < text.size();) {
    const auto c = static_cast<unsigned char>(text[i]);
    if (c < 0x80) {
      if (c < 0x20 && c != '\n' && c != '\t')
        escape(c);
      else if (c == 0x7F)
        escape(c);
      else
        out += char(c);
      ++i;
      continue;
    }
    // Length of the sequence a lead byte announces, and the range of its second byte
    // (overlong forms, surrogates and code points above U+10FFFF are invalid).
    size_t len = 0;
    unsigned char lo = 0x80, hi = 0xBF;
    if (c >= 0xC2 && c <= 0xDF)
      len = 2;
    else if (c >= 0xE0 && c <= 0xEF)
      len = 3, lo = c == 0xE0 ? 0xA0 : 0x80, hi = c == 0xED ? 0x9F : 0xBF;
    else if (c >= 0xF0 && c <= 0xF4)
      len = 4, lo = c == 0xF0 ? 0x90 : 0x80, hi = c == 0xF4 ? 0x8F : 0xBF;
    bool valid = len > 0 && i + len <= text.size();
    for (size_t k = 1; valid && k < len; ++k) {
      const auto b = static_cast<unsigned char>(text[i + k]);
      valid = k == 1 ? b >= lo && b <= hi : b >= 0x80 && b <= 0xBF;
    }
    if (valid) {
      out.append(text.substr(i, len));
      i += len;
    } else {
      escape(c);
      ++i;
    }
  }
  return out;
}

}  // namespace phellem
