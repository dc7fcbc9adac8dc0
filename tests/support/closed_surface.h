// Checks of a closed triangle surface for tests (header only, Eigen and the standard library):
// a TriMesh whose seam copies are welded by position, whether it is closed and a 2-manifold,
// and the volume it encloses.
#pragma once

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <map>
#include <string>
#include <vector>

#include "bark/geometry/tri_mesh.h"

namespace phellem::test {

// The mesh's triangles over its vertices welded by exact position; `vertices` gets their count.
inline std::vector<std::array<uint32_t, 3>> welded_triangles(const bark::TriMesh& m, size_t* vertices = nullptr) {
  std::map<std::array<double, 3>, uint32_t> at;
  std::vector<uint32_t> id(m.positions.size());
  for (size_t i = 0; i < m.positions.size(); ++i)
    id[i] = at.emplace(std::array<double, 3>{m.positions[i].x(), m.positions[i].y(), m.positions[i].z()}, uint32_t(at.size()))
                .first->second;
  std::vector<std::array<uint32_t, 3>> out;
  for (const auto& t : m.triangles) out.push_back({id[t[0]], id[t[1]], id[t[2]]});
  if (vertices) *vertices = at.size();
  return out;
}

// The signed volume enclosed (positive when the triangles face outwards).
inline double signed_volume(const bark::TriMesh& m) {
  double volume = 0;
  for (const auto& t : m.triangles) volume += m.positions[t[0]].dot(m.positions[t[1]].cross(m.positions[t[2]])) / 6;
  return volume;
}

// Closed and a 2-manifold once welded: every directed edge once and its reverse once (edges),
// and the triangles around each vertex one fan (no pinched vertices). What is wrong, or "".
inline std::string manifold_problem(const bark::TriMesh& m) {
  size_t n = 0;
  const auto tris = welded_triangles(m, &n);
  std::map<std::pair<uint32_t, uint32_t>, int> directed;
  for (const auto& t : tris) {
    if (t[0] == t[1] || t[1] == t[2] || t[0] == t[2]) return "a triangle repeats a vertex";
    for (size_t e = 0; e < 3; ++e) ++directed[{t[e], t[(e + 1) % 3]}];
  }
  for (const auto& [e, count] : directed)
    if (count != 1 || directed.count({e.second, e.first}) != 1)
      return "edge " + std::to_string(e.first) + "-" + std::to_string(e.second) + " is not shared by exactly two triangles";
  // Around each vertex: the next corner after it in each triangle, linked to the one before.
  std::vector<std::map<uint32_t, uint32_t>> link(n);
  for (const auto& t : tris)
    for (size_t k = 0; k < 3; ++k) link[t[k]][t[(k + 1) % 3]] = t[(k + 2) % 3];
  for (size_t v = 0; v < n; ++v) {
    if (link[v].empty()) continue;
    size_t steps = 0;
    uint32_t at = link[v].begin()->first;
    do {
      at = link[v].at(at);
      ++steps;
    } while (at != link[v].begin()->first && steps <= link[v].size());
    if (steps != link[v].size()) return "vertex " + std::to_string(v) + " is pinched (several fans)";
  }
  return "";
}

// Every directed edge of `faces` used once and its reverse once: a closed, consistently
// oriented 2-manifold (the growth volume's interface faces, say).
inline bool closed_manifold(const std::vector<std::array<uint32_t, 3>>& faces) {
  std::vector<std::array<uint32_t, 2>> directed;
  for (const auto& f : faces)
    for (size_t e = 0; e < 3; ++e) directed.push_back({f[e], f[(e + 1) % 3]});
  std::sort(directed.begin(), directed.end());
  if (std::adjacent_find(directed.begin(), directed.end()) != directed.end()) return false;
  for (const auto& e : directed)
    if (!std::binary_search(directed.begin(), directed.end(), std::array<uint32_t, 2>{e[1], e[0]})) return false;
  return true;
}

}  // namespace phellem::test
