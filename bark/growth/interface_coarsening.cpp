#include "bark/growth/interface_coarsening.h"

#include <algorithm>
#include <tuple>
#include <unordered_map>

namespace phellem::bark {

namespace {

template <class T>
void sort_unique(std::vector<T>& v) {
  std::sort(v.begin(), v.end());
  v.erase(std::unique(v.begin(), v.end()), v.end());
}

template <class T>
bool intersects(const std::vector<T>& a, const std::vector<T>& b) {
  auto i = a.begin(), j = b.begin();
  while (i != a.end() && j != b.end()) {
    if (*i < *j)
      ++i;
    else if (*j < *i)
      ++j;
    else
      return true;
  }
  return false;
}

// The interface faces' corners next to v (the interface's 1-ring), sorted.
void interface_neighbours(const TetComplex& c, const TetAdjacency& adj, uint32_t v, std::vector<uint32_t>& out) {
  out.clear();
  for (uint32_t t : adj.around(v)) {
    const auto& T = c.tets[t];
    for (int j = 0; j < 4; ++j) {
      if (T[size_t(j)] == v) continue;
      const uint32_t p = T[size_t(kTetFace[j][0])], q = T[size_t(kTetFace[j][1])], r = T[size_t(kTetFace[j][2])];
      if (!c.on_interface[p] || !c.on_interface[q] || !c.on_interface[r]) continue;
      const long u = adj.across(c, t, j);
      if (u < 0 || c.label[size_t(u)] == c.label[t]) continue;
      for (uint32_t w : {p, q, r})
        if (w != v) out.push_back(w);
    }
  }
  sort_unique(out);
}

bool is_interface_face(const TetComplex& c, const TetAdjacency& adj, uint32_t a, uint32_t p, uint32_t q) {
  for (uint32_t t : adj.around(a)) {
    const auto& T = c.tets[t];
    if (std::find(T.begin(), T.end(), p) == T.end() || std::find(T.begin(), T.end(), q) == T.end()) continue;
    for (int j = 0; j < 4; ++j)
      if (T[size_t(j)] != a && T[size_t(j)] != p && T[size_t(j)] != q) {
        const long u = adj.across(c, t, j);
        return u >= 0 && c.label[size_t(u)] != c.label[t];
      }
  }
  return false;
}

// The link condition of the tetrahedral complex, Lk(a) ∩ Lk(b) = Lk(ab), on vertices, edges
// and triangles.
bool link_condition(const TetComplex& c, const TetAdjacency& adj, uint32_t a, uint32_t b, const std::vector<uint32_t>& ab) {
  std::vector<uint32_t> ring, va, vb;
  std::vector<std::array<uint32_t, 2>> ring_edges, ea, eb;
  std::vector<std::array<uint32_t, 3>> fa, fb;
  for (uint32_t t : ab) {
    std::array<uint32_t, 2> e{};
    int n = 0;
    for (uint32_t w : c.tets[t])
      if (w != a && w != b) e[size_t(n++)] = w;
    if (e[0] > e[1]) std::swap(e[0], e[1]);
    ring.push_back(e[0]);
    ring.push_back(e[1]);
    ring_edges.push_back(e);
  }
  sort_unique(ring);
  sort_unique(ring_edges);
  auto collect = [&](uint32_t v, uint32_t other, std::vector<uint32_t>& verts, std::vector<std::array<uint32_t, 2>>& edges,
                     std::vector<std::array<uint32_t, 3>>& faces) {
    for (uint32_t t : adj.around(v)) {
      std::array<uint32_t, 3> f{};
      int n = 0;
      for (uint32_t w : c.tets[t])
        if (w != v) f[size_t(n++)] = w;
      std::sort(f.begin(), f.end());
      const bool has_other = std::binary_search(f.begin(), f.end(), other);
      for (uint32_t w : f)
        if (w != other) verts.push_back(w);
      if (has_other) continue;  // edges and triangles through the other end are not in both links
      faces.push_back(f);
      edges.push_back({f[0], f[1]});
      edges.push_back({f[0], f[2]});
      edges.push_back({f[1], f[2]});
    }
    sort_unique(verts);
    sort_unique(edges);
    sort_unique(faces);
  };
  collect(a, b, va, ea, fa);
  collect(b, a, vb, eb, fb);
  std::vector<uint32_t> common;
  std::set_intersection(va.begin(), va.end(), vb.begin(), vb.end(), std::back_inserter(common));
  if (common != ring) return false;
  std::vector<std::array<uint32_t, 2>> common_edges;
  std::set_intersection(ea.begin(), ea.end(), eb.begin(), eb.end(), std::back_inserter(common_edges));
  for (const auto& e : common_edges)
    if (!std::binary_search(ring_edges.begin(), ring_edges.end(), e)) return false;
  return !intersects(fa, fb);
}

// Whether `gone` may be removed into `keep` placed at x: no interface edge too long, every
// tetrahedron left positive, the quality kept. Changes nothing.
bool collapse_keeps_shape(TetComplex& c, TetAdjacency& adj, uint32_t keep, uint32_t gone, const Eigen::Vector3d& x,
                          const std::vector<uint32_t>& ab, double max_length) {
  const Eigen::Vector3d keep_at = c.points[keep];
  // No interface edge may come out longer than the band's upper bound (the splits would undo
  // the collapse).
  for (uint32_t v : {keep, gone})
    for (uint32_t t : adj.around(v))
      for (uint32_t w : c.tets[t])
        if (w != keep && w != gone && c.on_interface[w] && (c.points[w] - x).norm() > max_length) return false;
  double before = 1e300;
  for (uint32_t v : {keep, gone})
    for (uint32_t t : adj.around(v)) before = std::min(before, tet_quality(c, c.tets[t]));
  c.points[keep] = x;
  bool ok = true;
  double after = 1e300;
  for (uint32_t v : {keep, gone}) {
    for (uint32_t t : adj.around(v)) {
      if (std::binary_search(ab.begin(), ab.end(), t)) continue;
      std::array<uint32_t, 4> T = c.tets[t];
      std::replace(T.begin(), T.end(), gone, keep);
      if (!positive_tet(c, T)) {
        ok = false;
        break;
      }
      after = std::min(after, tet_quality(c, T));
    }
    if (!ok) break;
  }
  // Not much worse than before: at least a fair quality or as good as the worst it replaces.
  ok = ok && (after >= 0.1 || after >= before);
  c.points[keep] = keep_at;
  return ok;
}

// Removes `gone` into `keep` placed at x (collapse_keeps_shape holds).
void collapse(TetComplex& c, TetAdjacency& adj, uint32_t keep, uint32_t gone, const Eigen::Vector3d& x,
              const std::vector<uint32_t>& ab) {
  const Eigen::Vector3d keep_at = c.points[keep];
  c.points[keep] = x;
  const std::vector<uint32_t> moved(adj.around(gone).begin(), adj.around(gone).end());
  for (uint32_t t : moved) {
    if (std::binary_search(ab.begin(), ab.end(), t)) continue;
    std::array<uint32_t, 4> T = c.tets[t];
    std::replace(T.begin(), T.end(), gone, keep);
    adj.set_tet(c, t, T);
  }
  for (auto it = ab.rbegin(); it != ab.rend(); ++it) adj.erase_tet(c, *it);  // last first: indices stay valid
  if (x != keep_at && !c.uv.empty()) {
    const double s = (x - keep_at).norm() / std::max(1e-300, (c.points[gone] - keep_at).norm());
    c.uv[keep] = TetComplex::uv_between(c.uv[keep], c.uv[gone], s);
  }
  c.on_interface[gone] = 0;
}

}  // namespace

bool collapse_interface_edge(TetComplex& c, TetAdjacency& adj, uint32_t a, uint32_t b, double max_length) {
  if (a == b || !c.on_interface[a] || !c.on_interface[b] || c.on_box[a] || c.on_box[b]) return false;
  // A point on a crack (crack coupling, thesis sec. 5) neither goes nor moves, like a frozen
  // one: the crack network persists; a point off the crack may still merge into it.
  auto fixed = [&](uint32_t p) { return c.frozen[p] || (!c.on_crack.empty() && c.on_crack[p]); };
  if (fixed(a) && fixed(b)) return false;
  std::vector<uint32_t> ab;
  adj.edge_tets(c, a, b, ab);
  if (ab.empty()) return false;
  std::sort(ab.begin(), ab.end());
  // The two interface faces on the edge and their apexes p, q.
  std::vector<uint32_t> apex;
  for (uint32_t t : ab) {
    const auto& T = c.tets[t];
    for (int j = 0; j < 4; ++j) {
      if (T[size_t(j)] == a || T[size_t(j)] == b) continue;
      const long u = adj.across(c, t, j);
      if (u >= 0 && c.label[size_t(u)] != c.label[t])
        for (uint32_t w : T)
          if (w != a && w != b && w != T[size_t(j)]) apex.push_back(w);
    }
  }
  sort_unique(apex);
  if (apex.size() != 2) return false;
  // Which end goes: never a fixed one; else the one the refinement added (no input vertex),
  // else the later one. Up to three ways, the first whose shape holds is made: at the edge's
  // midpoint, at the kept end, the other end kept. Those are decided first (most short edges
  // fail there), then the topology.
  uint32_t keep = a, gone = b;
  if (fixed(b) || (c.source_vertex[b] >= 0 && c.source_vertex[a] < 0)) std::swap(keep, gone);
  const Eigen::Vector3d mid = 0.5 * (c.points[a] + c.points[b]);
  Eigen::Vector3d x;
  if (!fixed(keep) && collapse_keeps_shape(c, adj, keep, gone, mid, ab, max_length))
    x = mid;
  else if (collapse_keeps_shape(c, adj, keep, gone, c.points[keep], ab, max_length))
    x = c.points[keep];
  else if (!fixed(gone) && !fixed(keep) && collapse_keeps_shape(c, adj, gone, keep, c.points[gone], ab, max_length)) {
    std::swap(keep, gone);
    x = c.points[keep];
  } else {
    return false;
  }
  // The interface's link condition: a and b share exactly p and q, and neither a–p–q nor
  // b–p–q is a face (the interface is not a tetrahedron's four faces).
  std::vector<uint32_t> na, nb, common;
  interface_neighbours(c, adj, a, na);
  interface_neighbours(c, adj, b, nb);
  std::set_intersection(na.begin(), na.end(), nb.begin(), nb.end(), std::back_inserter(common));
  if (common != apex) return false;
  if (is_interface_face(c, adj, a, apex[0], apex[1]) || is_interface_face(c, adj, b, apex[0], apex[1])) return false;
  if (!link_condition(c, adj, a, b, ab)) return false;
  collapse(c, adj, keep, gone, x, ab);
  return true;
}

long collapse_short_interface_edges(TetComplex& c, double min_length, double max_length) {
  TetAdjacency adj(c);
  return collapse_short_interface_edges(c, adj, min_length, max_length);
}

long collapse_short_interface_edges(TetComplex& c, TetAdjacency& adj, double min_length, double max_length) {
  std::vector<std::array<uint32_t, 2>> edges;
  for (const auto& f : interface_faces(c, adj))
    for (int e = 0; e < 3; ++e) {
      const uint32_t a = f[size_t(e)], b = f[size_t(e + 1) % 3];
      if (a < b) edges.push_back({a, b});  // each edge once: a closed oriented interface uses it once each way
    }
  return collapse_short_interface_edges(c, adj, edges, min_length, max_length);
}

long collapse_short_interface_edges(TetComplex& c, TetAdjacency& adj, const std::vector<std::array<uint32_t, 2>>& edges,
                                    double min_length, double max_length, long* stretched,
                                    std::vector<uint32_t>* touched) {
  long collapses = 0;
  // A collapse of a–b reads only the tetrahedra around a and b (corners, positions, flags) and
  // those sharing a face with them (labels). Collapse number n stamps n on every corner of
  // the tetrahedra around its two ends, before and after: an edge whose attempt failed after
  // f collapses, none of whose tetrahedra has a corner stamped f or later since, would fail
  // again, and is not retried (most short edges fail every pass: the passes cost half as much).
  std::vector<long> stamp(c.points.size(), -1);
  std::unordered_map<uint64_t, long> failed_at;  // edge a < b → collapses made when it failed
  std::vector<uint32_t> corners;
  auto gather = [&](uint32_t a, uint32_t b) {
    for (uint32_t v : {a, b})
      for (uint32_t t : adj.around(v)) corners.insert(corners.end(), c.tets[t].begin(), c.tets[t].end());
  };
  auto touched_since = [&](uint32_t a, uint32_t b, long f) {
    for (uint32_t v : {a, b})
      for (uint32_t t : adj.around(v))
        for (uint32_t w : c.tets[t])
          if (stamp[w] >= f) return true;
    return false;
  };
  using Edge = std::tuple<double, uint32_t, uint32_t>;  // length, a < b
  auto edge = [&](uint32_t a, uint32_t b) -> Edge {
    if (a > b) std::swap(a, b);
    return {(c.points[a] - c.points[b]).norm(), a, b};
  };
  std::vector<Edge> todo;         // the short interface edges, shortest first
  std::vector<uint32_t> stamped;  // the points the last pass stamped (with repeats)
  std::vector<uint32_t> ring;
  long made_total = 0, last_first = 0;  // collapses made; the number of the last pass's first
  for (int pass = 0; pass < 8; ++pass) {
    if (pass == 0) {
      for (const auto& [a, b] : edges) {
        const Edge x = edge(a, b);
        if (std::get<0>(x) < min_length) todo.push_back(x);
      }
    } else {
      // The last pass changed only tetrahedra all of whose corners it stamped, and moved only
      // stamped points: an edge with neither end stamped is as it was (still short, still on
      // the interface), and every other short interface edge has a stamped end, at which it is
      // found again. The same edges as a new scan of the interface, without the scan.
      std::vector<Edge> next;
      for (const Edge& x : todo)
        if (stamp[std::get<1>(x)] < last_first && stamp[std::get<2>(x)] < last_first) next.push_back(x);
      sort_unique(stamped);
      for (uint32_t v : stamped) {
        if (!c.on_interface[v]) continue;
        interface_neighbours(c, adj, v, ring);
        for (uint32_t w : ring) {
          if (w < v && stamp[w] >= last_first) continue;  // found from w, the smaller stamped end
          const Edge x = edge(v, w);
          if (std::get<0>(x) < min_length) next.push_back(x);
        }
      }
      stamped.clear();
      todo = std::move(next);
    }
    last_first = made_total;
    if (todo.empty()) break;
    std::sort(todo.begin(), todo.end());
    long made = 0;
    for (const auto& [len0, a, b] : todo) {
      if (!c.on_interface[a] || !c.on_interface[b]) continue;  // an end went in this pass
      if ((c.points[a] - c.points[b]).norm() >= min_length) continue;
      const uint64_t key = (uint64_t(a) << 32) | b;
      if (const auto it = failed_at.find(key); it != failed_at.end() && !touched_since(a, b, it->second)) continue;
      corners.clear();
      gather(a, b);
      bool done = collapse_interface_edge(c, adj, a, b, max_length);
      if (!done && stretched && collapse_interface_edge(c, adj, a, b, kStretchedCollapse * max_length)) {
        done = true;
        ++*stretched;
      }
      if (done) {
        ++made;
        gather(a, b);
        for (uint32_t w : corners) stamp[w] = made_total;
        stamped.insert(stamped.end(), corners.begin(), corners.end());
        if (touched) touched->insert(touched->end(), corners.begin(), corners.end());
        ++made_total;
      } else {
        failed_at[key] = made_total;
      }
    }
    collapses += made;
    if (made == 0) break;
  }
  return collapses;
}

}  // namespace phellem::bark
