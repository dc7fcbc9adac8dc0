// The largest axis-aligned rectangle of set pixels in a binary mask (the maximal-rectangle
// problem), exact, in O(#w·#h): each row is the base of a histogram of run heights upwards, and
// the largest rectangle under a histogram comes from a stack of rising bars (every maximal
// rectangle is some bar's height times the widest span around it that is at least as high).
#pragma once

#include <cstdint>
#include <vector>

namespace phellem {

struct PixelRect {
  int x = 0, y = 0, width = 0, height = 0;  // top-left corner, row 0 at the top
  long long area() const { return (long long)width * height; }
  bool operator==(const PixelRect&) const = default;
};

// `mask` is #height×#width, row-major, nonzero = set. The rectangle of largest area; among
// equal areas the top-most, then the left-most. Empty (all zero) when nothing is set.
PixelRect maximal_rectangle(const std::vector<uint8_t>& mask, int width, int height);

}  // namespace phellem
