#include "bark/dressing/fracture_mesh.h"

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include <algorithm>
#include <cmath>
#include <unordered_map>

namespace phellem::bark {

namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Vb = CGAL::Triangulation_vertex_base_with_info_2<int, K>;
using Fb = CGAL::Constrained_triangulation_face_base_2<K>;
using Tds = CGAL::Triangulation_data_structure_2<Vb, Fb>;
// Exact_predicates_tag: silhouettes and depth iso-lines may cross; CGAL splits them there.
using CDT = CGAL::Constrained_Delaunay_triangulation_2<K, Tds, CGAL::Exact_predicates_tag>;

}  // namespace

std::vector<std::vector<Eigen::Vector2d>> contour_loops(const std::vector<float>& values, int W, int H, float level) {
  // Lattice nodes: columns i ∈ [0, W) (periodic), rows j ∈ [-1, H] where rows -1 and H are
  // padding below the level at y = 0 and y = H.
  const float pad = level - 1.0f;
  auto value = [&](int i, int j) { return j < 0 || j >= H ? pad : values[size_t(j) * W + size_t((i % W + W) % W)]; };
  auto node = [&](int i, int j) { return Eigen::Vector2d(i + 0.5, j < 0 ? 0.0 : j >= H ? double(H) : j + 0.5); };
  // A crossing is keyed by its lattice edge: horizontal (i, j)–(i+1, j) or vertical (i, j)–(i, j+1).
  auto hkey = [&](int i, int j) { return (int64_t(j + 1) * W + (i % W + W) % W) * 2; };
  auto vkey = [&](int i, int j) { return (int64_t(j + 1) * W + (i % W + W) % W) * 2 + 1; };
  std::unordered_map<int64_t, Eigen::Vector2d> point;
  std::unordered_map<int64_t, std::vector<int64_t>> next;
  auto crossing = [&](int64_t key, int i0, int j0, int i1, int j1) {
    if (!point.count(key)) {
      const float v0 = value(i0, j0), v1 = value(i1, j1);
      const double t = std::clamp(double(level - v0) / double(v1 - v0), 0.0, 1.0);
      Eigen::Vector2d p = node(i0, j0) + t * (node(i1, j1) - node(i0, j0));
      p.x() -= W * std::floor(p.x() / W);
      point.emplace(key, p);
    }
    return key;
  };
  auto link = [&](int64_t a, int64_t b) {
    next[a].push_back(b);
    next[b].push_back(a);
  };
  for (int j = -1; j < H; ++j)
    for (int i = 0; i < W; ++i) {
      const bool a = value(i, j) >= level, b = value(i + 1, j) >= level;
      const bool c = value(i + 1, j + 1) >= level, d = value(i, j + 1) >= level;
      const int code = a | b << 1 | c << 2 | d << 3;
      if (code == 0 || code == 15) continue;
      auto B = [&] { return crossing(hkey(i, j), i, j, i + 1, j); };
      auto R = [&] { return crossing(vkey(i + 1, j), i + 1, j, i + 1, j + 1); };
      auto T = [&] { return crossing(hkey(i, j + 1), i, j + 1, i + 1, j + 1); };
      auto L = [&] { return crossing(vkey(i, j), i, j, i, j + 1); };
      const bool centre = 0.25f * (value(i, j) + value(i + 1, j) + value(i + 1, j + 1) + value(i, j + 1)) >= level;
      switch (code) {
        case 1:
        case 14:
          link(L(), B());
          break;
        case 2:
        case 13:
          link(B(), R());
          break;
        case 3:
        case 12:
          link(L(), R());
          break;
        case 4:
        case 11:
          link(R(), T());
          break;
        case 6:
        case 9:
          link(B(), T());
          break;
        case 7:
        case 8:
          link(L(), T());
          break;
        case 5:  // a, c inside: joined through an inside centre, else cut off
          if (centre) {
            link(B(), R());
            link(T(), L());
          } else {
            link(L(), B());
            link(R(), T());
          }
          break;
        case 10:  // b, d inside
          if (centre) {
            link(L(), B());
            link(R(), T());
          } else {
            link(B(), R());
            link(T(), L());
          }
          break;
      }
    }
  // Every crossing has exactly two neighbours: walk the loops in key order (deterministic).
  std::vector<int64_t> keys;
  keys.reserve(next.size());
  for (const auto& kv : next) keys.push_back(kv.first);
  std::sort(keys.begin(), keys.end());
  std::unordered_map<int64_t, bool> used;
  std::vector<std::vector<Eigen::Vector2d>> loops;
  for (int64_t start : keys) {
    if (used[start]) continue;
    std::vector<Eigen::Vector2d> loop;
    int64_t prev = -1, cur = start;
    while (!used[cur]) {
      used[cur] = true;
      loop.push_back(point[cur]);
      const auto& n = next[cur];
      const int64_t go = n[0] != prev ? n[0] : n[1];
      prev = cur;
      cur = go;
    }
    loops.push_back(std::move(loop));
  }
  return loops;
}

FractureMesh mesh_fracture_field(const FractureField& f, double max_depth, const std::vector<double>& depth_levels, int grid) {
  const int W = f.width, H = f.height;
  FractureMesh m;
  m.width = W;
  m.height = H;
  m.silhouettes = contour_loops(f.opening, W, H, 0.5f);
  std::vector<std::vector<Eigen::Vector2d>> lines = m.silhouettes;
  for (double lv : depth_levels) {
    auto iso = contour_loops(f.depth, W, H, float(lv * max_depth));
    lines.insert(lines.end(), iso.begin(), iso.end());
  }
  // Every point first (one spatially sorted insertion), then the constraints between them by
  // index: inserting segment by segment located each end from scratch, which took minutes on
  // large fields.
  std::vector<K::Point_2> points;
  std::vector<std::pair<size_t, size_t>> segments;
  auto add = [&](double x, double y) {
    points.emplace_back(x, y);
    return points.size() - 1;
  };
  std::vector<double> seam_y;
  for (int y = 0; y <= H; y += grid) seam_y.push_back(y);
  seam_y.push_back(H);
  for (int x = 0; x <= W; x += grid) {
    add(x, 0);
    add(x, H);
  }
  for (int y = grid; y < H; y += grid)
    for (int x = grid; x < W; x += grid) add(x, y);
  for (const auto& loop : lines) {
    const size_t first = points.size();
    for (const Eigen::Vector2d& p : loop) add(p.x(), p.y());
    for (size_t k = 0; k < loop.size(); ++k) {
      const size_t ia = first + k, ib = first + (k + 1) % loop.size();
      const Eigen::Vector2d a = loop[k], b = loop[(k + 1) % loop.size()];
      if (std::abs(b.x() - a.x()) <= 0.5 * W) {
        if ((a - b).squaredNorm() > 1e-18) segments.emplace_back(ia, ib);
        continue;
      }
      // Across the seam: split at x = W ≡ 0, the same height on both sides.
      const bool rightwards = a.x() > b.x();  // a near W, b near 0
      const double bx = rightwards ? b.x() + W : b.x() - W, edge = rightwards ? W : 0.0;
      const double y = a.y() + (edge - a.x()) / (bx - a.x()) * (b.y() - a.y());
      segments.emplace_back(ia, add(edge, y));
      segments.emplace_back(add(W - edge, y), ib);
      seam_y.push_back(y);
    }
  }
  for (double y : seam_y) {  // both sides of the seam carry the same vertices
    add(0, y);
    add(W, y);
  }
  CDT cdt;
  // CGAL's insert_constraints(points, indices) inserts no point when there is no constraint
  // (bark without an open fracture or a depth level): then the points alone.
  if (segments.empty())
    cdt.insert(points.begin(), points.end());
  else
    cdt.insert_constraints(points.begin(), points.end(), segments.begin(), segments.end());
  int id = 0;
  for (auto v = cdt.finite_vertices_begin(); v != cdt.finite_vertices_end(); ++v) {
    v->info() = id++;
    const Eigen::Vector2d p(v->point().x(), v->point().y());
    m.param.push_back(p);
    m.depth.push_back(sample_wrapped(f.depth, W, H, p.x(), p.y()));
  }
  for (auto fc = cdt.finite_faces_begin(); fc != cdt.finite_faces_end(); ++fc) {
    const Eigen::Vector3i t(fc->vertex(0)->info(), fc->vertex(1)->info(), fc->vertex(2)->info());
    const Eigen::Vector2d c = (m.param[t[0]] + m.param[t[1]] + m.param[t[2]]) / 3.0;
    m.triangles.push_back(t);
    m.fracture.push_back(sample_wrapped(f.opening, W, H, c.x(), c.y()) > 0.5f ? 1 : 0);
  }
  return m;
}

}  // namespace phellem::bark
