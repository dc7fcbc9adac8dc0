#include "bark/growth/interface_refinement.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include "bark/growth/interface_motion.h"

#include <algorithm>
#include <set>

namespace phellem::bark {

namespace {

bool positive(const TetComplex& c, const std::array<uint32_t, 4>& t) {
  using K = CGAL::Exact_predicates_inexact_constructions_kernel;
  auto p = [&](uint32_t i) { return K::Point_3(c.points[i].x(), c.points[i].y(), c.points[i].z()); };
  return CGAL::orientation(p(t[0]), p(t[1]), p(t[2]), p(t[3])) == CGAL::POSITIVE;
}

}  // namespace

namespace {

std::vector<std::array<uint32_t, 2>> edges_of(const std::vector<std::array<uint32_t, 3>>& faces) {
  std::set<std::array<uint32_t, 2>> edges;
  for (const auto& f : faces)
    for (int e = 0; e < 3; ++e) edges.insert({std::min(f[size_t(e)], f[size_t(e + 1) % 3]), std::max(f[size_t(e)], f[size_t(e + 1) % 3])});
  return {edges.begin(), edges.end()};
}

}  // namespace

std::vector<std::array<uint32_t, 2>> interface_edges(const TetComplex& c) { return edges_of(c.interface_faces()); }

long split_long_interface_edges(TetComplex& c, double max_length, long max_splits) {
  long splits = 0;
  for (;;) {
    // Long edges of this pass, longest first (ties by index: deterministic).
    const std::vector<std::array<uint32_t, 3>> faces = c.interface_faces();  // once a pass: edges and normals
    std::vector<std::pair<double, std::array<uint32_t, 2>>> todo;
    for (const auto& e : edges_of(faces)) {
      const double len = (c.points[e[0]] - c.points[e[1]]).norm();
      if (len > max_length) todo.push_back({-len, e});
    }
    if (todo.empty() || splits >= max_splits) return splits;
    std::sort(todo.begin(), todo.end());
    const std::vector<Eigen::Vector3d> normals = interface_normals(c, faces);
    std::vector<std::vector<uint32_t>> around(c.points.size());
    for (uint32_t t = 0; t < c.tets.size(); ++t)
      for (uint32_t v : c.tets[t]) around[v].push_back(t);
    std::vector<uint8_t> touched(c.points.size(), 0);
    for (const auto& [neg_len, e] : todo) {
      if (splits >= max_splits) break;
      const uint32_t a = e[0], b = e[1];
      if (touched[a] || touched[b]) continue;  // its tetrahedra changed in this pass: next pass
      const uint32_t m = c.add_point_between(a, b, 0.5);
      around.emplace_back();
      touched.push_back(1);
      std::vector<uint32_t> shared;
      for (uint32_t t : around[a])
        if (std::find(c.tets[t].begin(), c.tets[t].end(), b) != c.tets[t].end()) shared.push_back(t);
      // The new vertex on the smooth surface the edge's ends and normals describe, rather than
      // on the chord: half of Phong tessellation's pull towards the two tangent planes, which
      // puts it on a circle's arc to second order. Kept on the chord if that would invert a
      // tetrahedron.
      const Eigen::Vector3d mid = c.points[m];
      const Eigen::Vector3d curved = mid + 0.25 * (normals[a].dot(c.points[a] - mid) * normals[a] +
                                                   normals[b].dot(c.points[b] - mid) * normals[b]);
      for (uint32_t t : shared) {
        std::array<uint32_t, 4> half = c.tets[t];
        std::replace(half.begin(), half.end(), a, m);  // the half at b's end
        std::replace(c.tets[t].begin(), c.tets[t].end(), b, m);  // the half at a's end
        const uint32_t u = uint32_t(c.tets.size());
        c.tets.push_back(half);
        c.label.push_back(c.label[t]);
        for (uint32_t v : half) around[v].push_back(u);
        around[m].push_back(t);
        auto& ab = around[b];
        ab.erase(std::remove(ab.begin(), ab.end(), t), ab.end());
        for (uint32_t v : c.tets[t]) touched[v] = 1;
        for (uint32_t v : half) touched[v] = 1;
      }
      c.points[m] = curved;
      bool ok = true;
      for (uint32_t t : around[m]) ok = ok && positive(c, c.tets[t]);
      if (!ok) c.points[m] = mid;
      ++splits;
    }
  }
}

}  // namespace phellem::bark
