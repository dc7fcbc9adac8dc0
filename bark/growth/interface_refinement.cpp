#include "bark/growth/interface_refinement.h"

#include "bark/growth/interface_motion.h"

#include <algorithm>
#include <queue>
#include <tuple>
#include <unordered_map>

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

namespace {

using Item = std::tuple<double, uint32_t, uint32_t>;  // length, a < b

// Splits the queue's edges longest first (ties by index), each still longer than max_length
// and still an interface edge, and the long edges the splits make; normal(p) is the
// interface normal at p as the scan found it, and set_normal(m, n) records one for a new
// point. With `made` and `split` given, the edges made are added to the one and the edges
// split to the other.
template <class Normal, class SetNormal>
long split_queue(TetComplex& c, TetAdjacency& adj, std::priority_queue<Item>& queue, double max_length, long max_splits,
                 Normal normal, SetNormal set_normal, std::vector<std::array<uint32_t, 2>>* made = nullptr,
                 std::vector<std::array<uint32_t, 2>>* split = nullptr) {
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
    const Eigen::Vector3d na = normal(a), nb = normal(b);
    const Eigen::Vector3d curved = mid + 0.25 * (na.dot(c.points[a] - mid) * na + nb.dot(c.points[b] - mid) * nb);
    set_normal(m, Eigen::Vector3d((na + nb).normalized()));
    adj.split_edge_tets(c, a, b, m, shared);  // every tetrahedron around the edge, in two
    c.points[m] = curved;
    bool ok = true;
    for (uint32_t t : adj.around(m)) ok = ok && positive_tet(c, c.tets[t]);
    if (!ok) c.points[m] = mid;
    ++splits;
    if (split) split->push_back({a, b});
    for (uint32_t w : {a, b, apex[0], apex[1]}) {
      if (made) made->push_back({std::min(m, w), std::max(m, w)});
      const double len = (c.points[m] - c.points[w]).norm();
      if (len > max_length) queue.push({len, std::min(m, w), std::max(m, w)});
    }
  }
  return splits;
}

}  // namespace

long split_long_interface_edges(TetComplex& c, TetAdjacency& adj, const std::vector<std::array<uint32_t, 3>>& faces,
                                double max_length, std::vector<std::array<uint32_t, 2>>& edges, long max_splits) {
  // The interface is scanned once; afterwards only the edges a split makes are new (the two
  // halves, shorter, and the two from the new vertex to the apexes across the edge), so they
  // join a queue of long edges, longest first (ties by index: deterministic).
  std::vector<Eigen::Vector3d> normals = interface_normals(c, faces);
  std::priority_queue<Item> queue;
  edges = edges_of(faces);
  for (const auto& e : edges) {
    const double len = (c.points[e[0]] - c.points[e[1]]).norm();
    if (len > max_length) queue.push({len, e[0], e[1]});
  }
  std::vector<std::array<uint32_t, 2>> split;  // the edges split
  const long splits = split_queue(
      c, adj, queue, max_length, max_splits, [&](uint32_t p) { return normals[p]; },
      [&](uint32_t m, const Eigen::Vector3d& n) {
        normals.resize(size_t(m) + 1, Eigen::Vector3d::Zero());
        normals[m] = n;
      },
      &edges, &split);
  if (!split.empty()) {  // the split edges are gone (a split edge's halves are new edges)
    std::sort(split.begin(), split.end());
    std::erase_if(edges, [&](const std::array<uint32_t, 2>& e) { return std::binary_search(split.begin(), split.end(), e); });
  }
  return splits;
}

long split_long_interface_edges_at(TetComplex& c, TetAdjacency& adj, std::vector<uint32_t> points, double max_length) {
  std::sort(points.begin(), points.end());
  points.erase(std::unique(points.begin(), points.end()), points.end());
  std::vector<std::array<uint32_t, 3>> faces;
  // The interface normal at p from its faces, summed in the scan's order (the same bits as
  // interface_normals over interface_faces).
  auto normal_now = [&](uint32_t p) {
    interface_faces_at(c, adj, p, faces);
    Eigen::Vector3d n = Eigen::Vector3d::Zero();
    for (const auto& f : faces) n += (c.points[f[1]] - c.points[f[0]]).cross(c.points[f[2]] - c.points[f[0]]);
    if (n.squaredNorm() > 0) n.normalize();
    return n;
  };
  // The long edges at the points, and the points whose normals a split may ask for: their
  // ends and the ends' interface neighbours (the apexes), taken before any split.
  std::vector<Item> long_edges;
  for (uint32_t v : points) {
    if (v >= c.points.size() || !c.on_interface[v]) continue;
    interface_faces_at(c, adj, v, faces);
    for (const auto& f : faces)
      for (uint32_t w : f) {
        if (w == v) continue;
        const double len = (c.points[v] - c.points[w]).norm();
        if (len > max_length) long_edges.push_back({len, std::min(v, w), std::max(v, w)});
      }
  }
  if (long_edges.empty()) return 0;
  std::sort(long_edges.begin(), long_edges.end());  // each edge once, as the scan has it
  long_edges.erase(std::unique(long_edges.begin(), long_edges.end()), long_edges.end());
  std::priority_queue<Item> queue;
  std::vector<uint32_t> asked;
  for (const auto& [len, a, b] : long_edges) {
    queue.push({len, a, b});
    for (uint32_t e : {a, b}) {
      asked.push_back(e);
      interface_faces_at(c, adj, e, faces);
      for (const auto& f : faces) asked.insert(asked.end(), f.begin(), f.end());
    }
  }
  std::sort(asked.begin(), asked.end());
  asked.erase(std::unique(asked.begin(), asked.end()), asked.end());
  std::unordered_map<uint32_t, Eigen::Vector3d> normals;
  for (uint32_t p : asked) normals.emplace(p, normal_now(p));
  return split_queue(
      c, adj, queue, max_length, 1000000,
      [&](uint32_t p) {
        const auto it = normals.find(p);
        return it != normals.end() ? it->second : normals.emplace(p, normal_now(p)).first->second;
      },
      [&](uint32_t m, const Eigen::Vector3d& n) { normals[m] = n; });
}

}  // namespace phellem::bark
