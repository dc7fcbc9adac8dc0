#include "bark/stress/crack_width.h"

#include <algorithm>
#include <deque>

namespace phellem::bark {

CrackGraph CrackGraph::from_edges(size_t vertices, const std::vector<std::pair<uint32_t, uint32_t>>& edges) {
  CrackGraph g;
  g.adjacency.resize(vertices);
  for (const auto& [a, b] : edges) {
    g.adjacency[a].push_back(b);
    g.adjacency[b].push_back(a);
  }
  for (auto& n : g.adjacency) std::sort(n.begin(), n.end());
  return g;
}

std::vector<int32_t> crack_components(const CrackGraph& g) {
  const size_t n = g.adjacency.size();
  std::vector<int32_t> comp(n, -1);
  int32_t next = 0;
  std::vector<uint32_t> stack;
  for (size_t s = 0; s < n; ++s) {
    if (comp[s] >= 0 || g.adjacency[s].empty()) continue;
    comp[s] = next;
    stack.assign(1, uint32_t(s));
    while (!stack.empty()) {
      const uint32_t x = stack.back();
      stack.pop_back();
      for (uint32_t y : g.adjacency[x])
        if (comp[y] < 0) {
          comp[y] = next;
          stack.push_back(y);
        }
    }
    ++next;
  }
  return comp;
}

std::vector<int32_t> crack_widths(const CrackGraph& g) {
  const size_t n = g.adjacency.size();
  const std::vector<int32_t> comp = crack_components(g);
  std::vector<int32_t> width(n, 0), dist(n, -1);
  // Components with ends: one search from all ends at once gives each vertex its distance to
  // the nearest end, the level at which Algorithm 1's search from it first meets an end.
  std::deque<uint32_t> queue;
  int32_t components = 0;
  for (int32_t c : comp) components = std::max(components, c + 1);
  std::vector<char> has_end(size_t(components), 0);
  for (size_t v = 0; v < n; ++v)
    if (g.adjacency[v].size() == 1) {
      dist[v] = 0;
      queue.push_back(uint32_t(v));
      has_end[size_t(comp[v])] = 1;
    }
  while (!queue.empty()) {
    const uint32_t x = queue.front();
    queue.pop_front();
    for (uint32_t y : g.adjacency[x])
      if (dist[y] < 0) {
        dist[y] = dist[x] + 1;
        queue.push_back(y);
      }
  }
  std::vector<int32_t> seen(n, -1);
  for (size_t v = 0; v < n; ++v) {
    if (comp[v] < 0) continue;
    if (has_end[size_t(comp[v])]) {
      width[v] = dist[v];
      continue;
    }
    // A closed crack: search until no new vertices; the last level that found one.
    int32_t level = 0;
    std::vector<uint32_t> current{uint32_t(v)}, next;
    seen[v] = int32_t(v);
    while (true) {
      next.clear();
      for (uint32_t x : current)
        for (uint32_t y : g.adjacency[x])
          if (seen[y] != int32_t(v)) {
            seen[y] = int32_t(v);
            next.push_back(y);
          }
      if (next.empty()) break;
      ++level;
      current.swap(next);
    }
    width[v] = level;
  }
  return width;
}

}  // namespace phellem::bark
