#include "compare/maximal_rectangle.h"

#include <cstddef>

namespace phellem {

using std::size_t;

PixelRect maximal_rectangle(const std::vector<uint8_t>& mask, int width, int height) {
  PixelRect best;
  auto consider = [&](int x, int y, int w, int h) {
    const long long a = (long long)w * h;
    if (a > best.area() || (a == best.area() && a > 0 && (y < best.y || (y == best.y && x < best.x)))) best = {x, y, w, h};
  };
  std::vector<int> run(size_t(width), 0);  // set pixels upwards from the current row, inclusive
  std::vector<int> stack;                  // columns whose runs rise strictly
  stack.reserve(size_t(width) + 1);
  for (int y = 0; y < height; ++y) {
    const uint8_t* row = &mask[size_t(y) * size_t(width)];
    for (int x = 0; x < width; ++x) run[size_t(x)] = row[x] ? run[size_t(x)] + 1 : 0;
    stack.clear();
    for (int x = 0; x <= width; ++x) {
      const int h = x < width ? run[size_t(x)] : 0;
      while (!stack.empty() && run[size_t(stack.back())] >= h) {
        const int top = run[size_t(stack.back())];
        stack.pop_back();
        const int left = stack.empty() ? 0 : stack.back() + 1;
        // Popped on an equal run, the span is cut short at x; the bar still on the stack
        // spans it whole later, so the largest area is never missed.
        if (top > 0) consider(left, y - top + 1, x - left, top);
      }
      stack.push_back(x);
    }
  }
  return best;
}

}  // namespace phellem
