#include "compare/html_text.h"

#include <cmath>
#include <cstdio>

#include "util/base64.h"

namespace phellem {

std::string html_escape(const std::string& text) {
  std::string out;
  for (char c : text) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      case '\'': out += "&#39;"; break;
      default: out += c;
    }
  }
  return out;
}

std::string html_fixed(double v, int digits) {
  if (!std::isfinite(v)) return "—";
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*f", digits, v);
  return buf;
}

std::string html_img(const std::vector<unsigned char>& png, const std::string& alt, const std::string& extra) {
  return "<img alt=\"" + html_escape(alt) + "\"" + (extra.empty() ? "" : " " + extra) + " src=\"data:image/png;base64," +
         base64(png.data(), png.size()) + "\">";
}

}  // namespace phellem
