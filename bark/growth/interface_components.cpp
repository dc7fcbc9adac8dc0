#include "bark/growth/interface_components.h"

#include <numeric>

namespace phellem::bark {

InterfaceComponents interface_components(const TetComplex& c) {
  // Union–find over the points, joining the corners of every interface face.
  std::vector<uint32_t> parent(c.points.size());
  std::iota(parent.begin(), parent.end(), 0u);
  auto find = [&](uint32_t v) {
    while (parent[v] != v) v = parent[v] = parent[parent[v]];
    return v;
  };
  std::vector<uint8_t> on(c.points.size(), 0);
  for (const auto& f : c.interface_faces())
    for (int k = 0; k < 3; ++k) {
      on[f[size_t(k)]] = 1;
      const uint32_t a = find(f[size_t(k)]), b = find(f[size_t(k + 1) % 3]);
      if (a != b) parent[std::max(a, b)] = std::min(a, b);  // the root is the smallest index
    }
  InterfaceComponents out;
  out.of_point.assign(c.points.size(), -1);
  std::vector<int> id(c.points.size(), -1);
  for (uint32_t v = 0; v < c.points.size(); ++v) {
    if (!on[v]) continue;
    const uint32_t r = find(v);
    if (id[r] < 0) id[r] = out.count++;
    out.of_point[v] = id[r];
  }
  return out;
}

}  // namespace phellem::bark
