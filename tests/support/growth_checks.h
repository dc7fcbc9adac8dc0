// Checks shared by the growth tests.
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>
#include <vector>

namespace phellem::bark::test {

// Every directed interface edge is used once and its reverse once: a closed, consistently
// oriented 2-manifold.
inline bool closed_manifold(const std::vector<std::array<uint32_t, 3>>& faces) {
  std::vector<std::array<uint32_t, 2>> directed;
  for (const auto& f : faces)
    for (int e = 0; e < 3; ++e) directed.push_back({f[size_t(e)], f[size_t(e + 1) % 3]});
  std::sort(directed.begin(), directed.end());
  if (std::adjacent_find(directed.begin(), directed.end()) != directed.end()) return false;
  for (const auto& e : directed)
    if (!std::binary_search(directed.begin(), directed.end(), std::array<uint32_t, 2>{e[1], e[0]})) return false;
  return true;
}

}  // namespace phellem::bark::test
