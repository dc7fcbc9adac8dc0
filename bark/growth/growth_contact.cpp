#include "bark/growth/growth_contact.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <iterator>
#include <limits>
#include <cmath>
#include <cstdint>
#include <queue>
#include <span>

#include "bark/growth/interface_motion.h"
#include "bark/growth/triangle_tree.h"

namespace phellem::bark {

namespace {

using namespace triangle_tree;

enum : uint8_t { kNone = 0, kByObstacle = 1, kByFront = 2 };

// The interface's edges as compressed neighbour rows (each sorted, each neighbour once).
struct Neighbours {
  std::vector<uint32_t> offset, flat;
  std::span<const uint32_t> operator[](uint32_t v) const { return {flat.data() + offset[v], flat.data() + offset[v + 1]}; }
};

Neighbours interface_neighbours(size_t points, const std::vector<std::array<uint32_t, 3>>& faces) {
  // A closed oriented interface walks each edge once each way: every face gives each corner
  // its next corner and its previous one.
  Neighbours n;
  n.offset.assign(points + 1, 0);
  for (const auto& f : faces)
    for (uint32_t v : f) n.offset[v + 1] += 2;
  for (size_t i = 0; i < points; ++i) n.offset[i + 1] += n.offset[i];
  n.flat.resize(n.offset[points]);
  std::vector<uint32_t> fill(n.offset.begin(), n.offset.end() - 1);
  for (const auto& f : faces)
    for (int e = 0; e < 3; ++e) {
      const uint32_t a = f[size_t(e)], b = f[size_t(e + 1) % 3];
      n.flat[fill[a]++] = b;
      n.flat[fill[b]++] = a;
    }
  // Sorted and deduplicated in place, each row closing up towards its start.
  uint32_t write = 0;
  for (size_t v = 0; v < points; ++v) {
    const auto begin = n.flat.begin() + n.offset[v], end = n.flat.begin() + n.offset[v + 1];
    std::sort(begin, end);
    const auto last = std::unique(begin, end);
    n.offset[v] = write;
    write = uint32_t(std::copy(begin, last, n.flat.begin() + write) - n.flat.begin());
  }
  n.offset[points] = write;
  n.flat.resize(write);
  return n;
}

// The points near v along the interface: within two edges, or within `reach` (m) along
// interface edges (a Dijkstra search bounded by reach); sorted.
std::vector<uint32_t> near_along_interface(const TetComplex& c, const Neighbours& adjacent, uint32_t v,
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


// The broad phase of the contact test: a uniform grid over the candidate faces' bounding
// boxes, each cell hashed into a flat table of buckets (counted, then filled in face order:
// no tree to build, linear in the faces, the same whatever the thread count). A query lists
// every face whose box meets the query box (a superset: buckets shared by several cells add
// more, which the exact distance test then drops). Faces whose boxes span many cells (large
// obstacle faces) are kept aside and listed for every query.
class FaceGrid {
 public:
  using Box = std::array<Eigen::Vector3d, 2>;  // lo, hi

  FaceGrid(const std::vector<Box>& boxes, double cell) : cell_(cell) {
    origin_ = Eigen::Vector3d::Constant(std::numeric_limits<double>::max());
    for (const auto& b : boxes) origin_ = origin_.cwiseMin(b[0]);
    std::vector<std::array<int64_t, 6>> range(boxes.size());
    std::vector<uint8_t> big(boxes.size(), 0);
    size_t entries = 0;
    for (size_t i = 0; i < boxes.size(); ++i) {
      const auto lo = index(boxes[i][0]), hi = index(boxes[i][1]);
      range[i] = {lo[0], lo[1], lo[2], hi[0], hi[1], hi[2]};
      const int64_t n = (hi[0] - lo[0] + 1) * (hi[1] - lo[1] + 1) * (hi[2] - lo[2] + 1);
      if (n > kBigCells) {
        big[i] = 1;
        big_.push_back(uint32_t(i));
      } else {
        entries += size_t(n);
      }
    }
    size_t buckets = 64;
    while (buckets < 2 * entries) buckets *= 2;
    mask_ = buckets - 1;
    start_.assign(buckets + 1, 0);
    auto each_cell = [&](size_t i, auto&& f) {
      const auto& r = range[i];
      for (int64_t x = r[0]; x <= r[3]; ++x)
        for (int64_t y = r[1]; y <= r[4]; ++y)
          for (int64_t z = r[2]; z <= r[5]; ++z) f(bucket(x, y, z));
    };
    for (size_t i = 0; i < boxes.size(); ++i)
      if (!big[i]) each_cell(i, [&](size_t k) { ++start_[k + 1]; });
    for (size_t k = 0; k < buckets; ++k) start_[k + 1] += start_[k];
    ids_.resize(entries);
    std::vector<uint32_t> fill(start_.begin(), start_.end() - 1);
    for (size_t i = 0; i < boxes.size(); ++i)
      if (!big[i]) each_cell(i, [&](size_t k) { ids_[fill[k]++] = uint32_t(i); });
  }

  // The faces whose boxes may meet [lo, hi], sorted, each once.
  void query(const Eigen::Vector3d& lo, const Eigen::Vector3d& hi, std::vector<uint32_t>& out) const {
    out.clear();
    const auto a = index(lo), b = index(hi);
    for (int64_t x = a[0]; x <= b[0]; ++x)
      for (int64_t y = a[1]; y <= b[1]; ++y)
        for (int64_t z = a[2]; z <= b[2]; ++z) {
          const size_t k = bucket(x, y, z);
          out.insert(out.end(), ids_.begin() + start_[k], ids_.begin() + start_[k + 1]);
        }
    out.insert(out.end(), big_.begin(), big_.end());
    std::sort(out.begin(), out.end());
    out.erase(std::unique(out.begin(), out.end()), out.end());
  }

 private:
  static constexpr int64_t kBigCells = 64;

  std::array<int64_t, 3> index(const Eigen::Vector3d& p) const {
    const Eigen::Vector3d q = (p - origin_) / cell_;
    // Clamped: a point far below the faces' corner (a query) still maps to a cell.
    auto i = [](double v) { return int64_t(std::floor(std::clamp(v, -1e15, 1e15))); };
    return {i(q.x()), i(q.y()), i(q.z())};
  }
  size_t bucket(int64_t x, int64_t y, int64_t z) const {
    const uint64_t h = uint64_t(x) * 0x9E3779B185EBCA87ull ^ uint64_t(y) * 0xC2B2AE3D27D4EB4Full ^
                       uint64_t(z) * 0x165667B19E3779F9ull;
    return size_t((h ^ (h >> 29)) & mask_);
  }

  double cell_;
  Eigen::Vector3d origin_;
  size_t mask_ = 0;
  std::vector<uint32_t> start_, ids_, big_;
};

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
  const Neighbours adjacent = interface_neighbours(c.points.size(), faces);

  // Every candidate face: the interface's first, then the obstacles'. Degenerate faces (none in
  // a positive complex, but cheap to guard) are left out.
  Triangles triangles;
  std::vector<FaceGrid::Box> boxes;
  std::vector<std::array<uint32_t, 3>> corners;
  std::vector<Eigen::Vector3d> face_normal;
  std::vector<uint8_t> is_obstacle;
  const size_t count = faces.size() + obstacle_faces.size();
  triangles.reserve(count);
  boxes.reserve(count);
  corners.reserve(count);
  face_normal.reserve(count);
  is_obstacle.reserve(count);
  double extent = 0;  // summed largest box side
  auto add = [&](const std::array<uint32_t, 3>& f, bool obstacle) {
    const Eigen::Vector3d &a = c.points[f[0]], &b = c.points[f[1]], &d = c.points[f[2]];
    const Eigen::Vector3d n = (b - a).cross(d - a);
    if (!(n.squaredNorm() > 0)) return;
    triangles.emplace_back(cgal(a), cgal(b), cgal(d));
    boxes.push_back({a.cwiseMin(b).cwiseMin(d), a.cwiseMax(b).cwiseMax(d)});
    extent += (boxes.back()[1] - boxes.back()[0]).maxCoeff();
    corners.push_back(f);
    face_normal.push_back(n.normalized());
    is_obstacle.push_back(obstacle);
  };
  for (const auto& f : faces) add(f, false);
  for (const auto& f : obstacle_faces) add(f, true);
  if (triangles.empty()) return st;
  // Cells about a face across (each face in a few) and never narrower than a query box.
  const FaceGrid grid(boxes, std::max(2 * gap, extent / double(triangles.size())));

  std::vector<uint8_t> decision(c.points.size(), kNone);
  const double gap2 = gap * gap;
  tbb::parallel_for(tbb::blocked_range<uint32_t>(0, uint32_t(c.points.size())), [&](const tbb::blocked_range<uint32_t>& r) {
    std::vector<uint32_t> ids;
    for (uint32_t v = r.begin(); v != r.end(); ++v) {
      if (!c.on_interface[v] || c.frozen[v]) continue;
      const Eigen::Vector3d& p = c.points[v];
      // The faces whose boxes meet the box of half-side gap around v (closed intervals, as
      // CGAL's Bbox_3 overlap), in index order: obstacles last.
      const Eigen::Vector3d lo = p - Eigen::Vector3d::Constant(gap), hi = p + Eigen::Vector3d::Constant(gap);
      grid.query(lo, hi, ids);
      std::vector<uint32_t> near;
      bool near_known = false;
      uint8_t d = kNone;
      const auto ring = adjacent[v];
      auto at_or_next_to_v = [&](const std::array<uint32_t, 3>& f) {
        return std::any_of(f.begin(), f.end(), [&](uint32_t w) { return w == v || std::binary_search(ring.begin(), ring.end(), w); });
      };
      for (uint32_t i : ids) {
        // An interface face at v or at a neighbour of v has a corner near v along the interface
        // (near_along_interface always holds v and its 2-ring): it can never freeze v, so it is
        // not measured (these are most of the faces a query finds).
        if (!is_obstacle[i] && at_or_next_to_v(corners[i])) continue;
        const FaceGrid::Box& b = boxes[i];
        if (b[0].x() > hi.x() || b[1].x() < lo.x() || b[0].y() > hi.y() || b[1].y() < lo.y() || b[0].z() > hi.z() ||
            b[1].z() < lo.z())
          continue;
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
