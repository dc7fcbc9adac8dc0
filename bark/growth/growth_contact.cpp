#include "bark/growth/growth_contact.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <iterator>
#include <queue>

#include "bark/growth/interface_motion.h"
#include "bark/growth/triangle_tree.h"

namespace phellem::bark {

namespace {

using namespace triangle_tree;

enum : uint8_t { kNone = 0, kByObstacle = 1, kByFront = 2 };

// The points near v along the interface: within two edges, or within `reach` (m) along
// interface edges (a Dijkstra search bounded by reach); sorted.
std::vector<uint32_t> near_along_interface(const TetComplex& c, const std::vector<std::vector<uint32_t>>& adjacent, uint32_t v,
                                           double reach) {
  std::vector<std::pair<uint32_t, double>> best{{v, 0.0}};  // point, shortest path found
  auto found = [&](uint32_t w) {
    for (auto& b : best)
      if (b.first == w) return &b.second;
    return static_cast<double*>(nullptr);
  };
  using Item = std::pair<double, uint32_t>;
  std::priority_queue<Item, std::vector<Item>, std::greater<>> queue;
  queue.push({0.0, v});
  while (!queue.empty()) {
    const auto [d, u] = queue.top();
    queue.pop();
    if (d > *found(u)) continue;
    for (uint32_t w : adjacent[u]) {
      const double dw = d + (c.points[u] - c.points[w]).norm();
      if (dw > reach) continue;
      double* b = found(w);
      if (!b) {
        best.push_back({w, dw});
        queue.push({dw, w});
      } else if (dw < *b) {
        *b = dw;
        queue.push({dw, w});
      }
    }
  }
  std::vector<uint32_t> out;
  for (const auto& b : best) out.push_back(b.first);
  for (uint32_t u : adjacent[v]) {  // the 2-ring, whatever its length
    out.push_back(u);
    out.insert(out.end(), adjacent[u].begin(), adjacent[u].end());
  }
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

}  // namespace

ContactStats freeze_contacts(TetComplex& c, double gap) {
  return freeze_contacts(c, c.interface_faces(), c.boundary_faces(TetComplex::kObstacle), gap);
}

ContactStats freeze_contacts(TetComplex& c, const std::vector<std::array<uint32_t, 3>>& faces,
                             const std::vector<std::array<uint32_t, 3>>& obstacle_faces, double gap) {
  ContactStats st;
  if (!(gap > 0)) return st;
  const std::vector<Eigen::Vector3d> normals = interface_normals(c, faces);

  // The interface's edges, as neighbour lists (sorted: deterministic searches).
  std::vector<std::vector<uint32_t>> adjacent(c.points.size());
  for (const auto& f : faces)
    for (int e = 0; e < 3; ++e) {
      adjacent[f[size_t(e)]].push_back(f[size_t(e + 1) % 3]);
      adjacent[f[size_t(e + 1) % 3]].push_back(f[size_t(e)]);
    }
  for (auto& a : adjacent) {
    std::sort(a.begin(), a.end());
    a.erase(std::unique(a.begin(), a.end()), a.end());
  }

  // Every candidate face: the interface's first, then the obstacles'. Degenerate faces (none in
  // a positive complex, but cheap to guard) are left out.
  Triangles triangles;
  std::vector<std::array<uint32_t, 3>> corners;
  std::vector<Eigen::Vector3d> face_normal;
  std::vector<uint8_t> is_obstacle;
  auto add = [&](const std::array<uint32_t, 3>& f, bool obstacle) {
    const Eigen::Vector3d n = (c.points[f[1]] - c.points[f[0]]).cross(c.points[f[2]] - c.points[f[0]]);
    if (!(n.squaredNorm() > 0)) return;
    triangles.emplace_back(cgal(c.points[f[0]]), cgal(c.points[f[1]]), cgal(c.points[f[2]]));
    corners.push_back(f);
    face_normal.push_back(n.normalized());
    is_obstacle.push_back(obstacle);
  };
  for (const auto& f : faces) add(f, false);
  for (const auto& f : obstacle_faces) add(f, true);
  if (triangles.empty()) return st;
  Tree tree(triangles.cbegin(), triangles.cend());
  tree.build();  // before the concurrent queries

  std::vector<uint8_t> decision(c.points.size(), kNone);
  const double gap2 = gap * gap;
  tbb::parallel_for(tbb::blocked_range<uint32_t>(0, uint32_t(c.points.size())), [&](const tbb::blocked_range<uint32_t>& r) {
    std::vector<Primitive::Id> hits;
    for (uint32_t v = r.begin(); v != r.end(); ++v) {
      if (!c.on_interface[v] || c.frozen[v]) continue;
      const Eigen::Vector3d& p = c.points[v];
      hits.clear();
      tree.all_intersected_primitives(CGAL::Bbox_3(p.x() - gap, p.y() - gap, p.z() - gap, p.x() + gap, p.y() + gap, p.z() + gap),
                                      std::back_inserter(hits));
      std::vector<size_t> ids;
      for (const auto& h : hits) ids.push_back(size_t(std::distance(triangles.cbegin(), h)));
      std::sort(ids.begin(), ids.end());  // obstacles last; the order does not change the decision
      std::vector<uint32_t> near;
      bool near_known = false;
      uint8_t d = kNone;
      for (size_t i : ids) {
        if (CGAL::squared_distance(cgal(p), triangles[i]) >= gap2) continue;
        if (is_obstacle[i]) {
          d = kByObstacle;
          break;
        }
        if (!(face_normal[i].dot(normals[v]) < 0)) continue;  // not facing the vertex
        if (!near_known) {
          near = near_along_interface(c, adjacent, v, kNearGaps * gap);
          near_known = true;
        }
        const auto& f = corners[i];
        if (std::none_of(f.begin(), f.end(), [&](uint32_t w) { return std::binary_search(near.begin(), near.end(), w); }))
          d = kByFront;  // an obstacle face, if any, may still come: it takes precedence
      }
      decision[v] = d;
    }
  });
  for (uint32_t v = 0; v < c.points.size(); ++v) {
    if (decision[v] == kNone) continue;
    c.frozen[v] = 1;
    ++(decision[v] == kByObstacle ? st.obstacle : st.front);
  }
  return st;
}

}  // namespace phellem::bark
