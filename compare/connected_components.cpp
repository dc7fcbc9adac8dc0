#include "compare/connected_components.h"

#include <numeric>
#include <stdexcept>

namespace phellem {
namespace {

int32_t find_root(std::vector<int32_t>& parent, int32_t a) {
  while (parent[size_t(a)] != a) a = parent[size_t(a)] = parent[size_t(parent[size_t(a)])];  // path halving
  return a;
}

void unite(std::vector<int32_t>& parent, int32_t a, int32_t b) {
  a = find_root(parent, a);
  b = find_root(parent, b);
  if (a < b)
    parent[size_t(b)] = a;
  else if (b < a)
    parent[size_t(a)] = b;
}

}  // namespace

// Two-pass labelling with union–find (Rosenfeld & Pfaltz 1966): the first pass gives each
// pixel a provisional label joined with its already-visited 8-neighbours (W, NW, N, NE), the
// second replaces provisional labels by their component's, numbered in raster order.
Components label_components(const std::vector<uint8_t>& mask, int width, int height) {
  if (mask.size() != size_t(width) * size_t(height)) throw std::invalid_argument("label_components: size mismatch");
  Components c;
  c.label.assign(mask.size(), 0);
  std::vector<int32_t> parent{0};
  auto at = [&](int x, int y) { return c.label[size_t(y) * size_t(width) + size_t(x)]; };
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      if (!mask[size_t(y) * size_t(width) + size_t(x)]) continue;
      int32_t l = 0;
      const int nx[4] = {x - 1, x - 1, x, x + 1}, ny[4] = {y, y - 1, y - 1, y - 1};
      for (int n = 0; n < 4; ++n) {
        if (nx[n] < 0 || nx[n] >= width || ny[n] < 0) continue;
        const int32_t ln = at(nx[n], ny[n]);
        if (!ln) continue;
        if (!l)
          l = ln;
        else
          unite(parent, l, ln);
      }
      if (!l) {
        l = int32_t(parent.size());
        parent.push_back(l);
      }
      c.label[size_t(y) * size_t(width) + size_t(x)] = l;
    }
  std::vector<int32_t> final_label(parent.size(), 0);
  for (int32_t& l : c.label) {
    if (!l) continue;
    const int32_t root = find_root(parent, l);
    if (!final_label[size_t(root)]) final_label[size_t(root)] = ++c.count;
    l = final_label[size_t(root)];
  }
  return c;
}

}  // namespace phellem
