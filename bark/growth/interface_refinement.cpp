#include "bark/growth/interface_refinement.h"

#include "bark/growth/interface_motion.h"

#include <algorithm>
#include <queue>
#include <tuple>

namespace phellem::bark {

namespace {

// Each edge once, from the face that walks it from its smaller end (a closed, oriented
// interface walks every edge once each way); in face order.
std::vector<std::array<uint32_t, 2>> edges_of(const std::vector<std::array<uint32_t, 3>>& faces) {
  std::vector<std::array<uint32_t, 2>> edges;
  edges.reserve(faces.size() * 3 / 2);
  for (const auto& f : faces)
    for (int e = 0; e < 3; ++e)
      if (f[size_t(e)] < f[size_t(e + 1) % 3]) edges.push_back({f[size_t(e)], f[size_t(e + 1) % 3]});
  return edges;
}

}  // namespace

std::vector<std::array<uint32_t, 2>> interface_edges(const TetComplex& c) {
  const TetAdjacency adj(c);
  std::vector<std::array<uint32_t, 2>> edges;
  for (const auto& f : interface_faces(c, adj))
    for (int e = 0; e < 3; ++e)
      edges.push_back({std::min(f[size_t(e)], f[size_t(e + 1) % 3]), std::max(f[size_t(e)], f[size_t(e + 1) % 3])});
  std::sort(edges.begin(), edges.end());
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
  return edges;
}

long split_long_interface_edges(TetComplex& c, double max_length, long max_splits) {
  TetAdjacency adj(c);
  return split_long_interface_edges(c, adj, max_length, max_splits);
}

long split_long_interface_edges(TetComplex& c, TetAdjacency& adj, double max_length, long max_splits) {
  return split_long_interface_edges(c, adj, interface_faces(c, adj), max_length, max_splits);
}

long split_long_interface_edges(TetComplex& c, TetAdjacency& adj, const std::vector<std::array<uint32_t, 3>>& faces,
                                double max_length, long max_splits) {
  std::vector<std::array<uint32_t, 2>> edges;
  return split_long_interface_edges(c, adj, faces, max_length, edges, max_splits);
}

long split_long_interface_edges(TetComplex& c, TetAdjacency& adj, const std::vector<std::array<uint32_t, 3>>& faces,
                                double max_length, std::vector<std::array<uint32_t, 2>>& edges, long max_splits) {
  // The interface is scanned once; afterwards only the edges a split makes are new (the two
  // halves, shorter, and the two from the new vertex to the apexes across the edge), so they
  // join a queue of long edges, longest first (ties by index: deterministic).
  std::vector<Eigen::Vector3d> normals = interface_normals(c, faces);
  using Item = std::tuple<double, uint32_t, uint32_t>;
  std::priority_queue<Item> queue;
  edges = edges_of(faces);
  std::vector<std::array<uint32_t, 2>> split;  // the edges split
  for (const auto& e : edges) {
    const double len = (c.points[e[0]] - c.points[e[1]]).norm();
    if (len > max_length) queue.push({len, e[0], e[1]});
  }
  long splits = 0;
  std::vector<uint32_t> shared;
  while (!queue.empty() && splits < max_splits) {
    const auto [len0, a, b] = queue.top();
    queue.pop();
    if ((c.points[a] - c.points[b]).norm() <= max_length) continue;
    adj.edge_tets(c, a, b, shared);
    // The apexes of the interface faces on the edge: the ring vertices whose two tetrahedra
    // around the edge carry different labels (none once the edge was split).
    std::array<uint32_t, 2> apex{};
    int apexes = 0;
    for (size_t i = 0; i < shared.size(); ++i)
      for (uint32_t x : c.tets[shared[i]]) {
        if (x == a || x == b) continue;
        for (size_t j = i + 1; j < shared.size(); ++j)
          if (std::find(c.tets[shared[j]].begin(), c.tets[shared[j]].end(), x) != c.tets[shared[j]].end() &&
              c.label[shared[i]] != c.label[shared[j]] && apexes < 2)
            apex[size_t(apexes++)] = x;
      }
    if (apexes != 2) continue;  // no longer an interface edge
    const uint32_t m = c.add_point_between(a, b, 0.5);
    // The new vertex on the smooth surface the edge's ends and normals describe, rather than
    // on the chord: half of Phong tessellation's pull towards the two tangent planes, which
    // puts it on a circle's arc to second order. Kept on the chord if that would invert a
    // tetrahedron.
    const Eigen::Vector3d mid = c.points[m];
    const Eigen::Vector3d curved = mid + 0.25 * (normals[a].dot(c.points[a] - mid) * normals[a] +
                                                 normals[b].dot(c.points[b] - mid) * normals[b]);
    normals.push_back((normals[a] + normals[b]).normalized());
    adj.split_edge_tets(c, a, b, m, shared);  // every tetrahedron around the edge, in two
    c.points[m] = curved;
    bool ok = true;
    for (uint32_t t : adj.around(m)) ok = ok && positive_tet(c, c.tets[t]);
    if (!ok) c.points[m] = mid;
    ++splits;
    split.push_back({a, b});
    for (uint32_t w : {a, b, apex[0], apex[1]}) {
      edges.push_back({std::min(m, w), std::max(m, w)});
      const double len = (c.points[m] - c.points[w]).norm();
      if (len > max_length) queue.push({len, std::min(m, w), std::max(m, w)});
    }
  }
  if (!split.empty()) {  // the split edges are gone (a split edge's halves are new edges)
    std::sort(split.begin(), split.end());
    std::erase_if(edges, [&](const std::array<uint32_t, 2>& e) { return std::binary_search(split.begin(), split.end(), e); });
  }
  return splits;
}

}  // namespace phellem::bark
