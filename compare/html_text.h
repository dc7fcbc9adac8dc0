// Small pieces of the HTML reports (compare, compare --lit): escaped text, fixed-point numbers,
// and PNG bytes as an inline <img>.
#pragma once

#include <string>
#include <vector>

namespace phellem {

std::string html_escape(const std::string& text);
// `v` with `digits` decimals; "—" when it is not finite.
std::string html_fixed(double v, int digits);
// An <img> whose source is `png` as a data: URI; `extra` is added inside the tag (e.g. a style).
std::string html_img(const std::vector<unsigned char>& png, const std::string& alt, const std::string& extra = "");

}  // namespace phellem
