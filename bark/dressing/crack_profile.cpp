#include "bark/dressing/crack_profile.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "util/noise.h"

namespace phellem {

namespace {
// Noise over this many cells per metre modulates width and depth along the cracks.
constexpr float kNoiseFrequency = 60.0f;
}  // namespace

CrackProfile::CrackProfile(const bark::CrackedMesh& c, const CrackLook& look, uint32_t seed) : look_(look), seed_(seed) {
  auto half_width = [&](uint32_t v) {
    const float gap = v < c.displacement.size() ? look.gap * c.displacement[v].norm() : 0.0f;  // sec. 3.1.6
    return std::clamp(look.min_width + look.width_per_edge * c.crack_width[v] + gap, look.min_width, look.max_width);
  };
  const std::vector<float> chain = chain_coordinates(c, seed);
  for (size_t i = 0; i < c.crack_edges.size(); ++i) {
    const auto& e = c.crack_edges[i];
    seg_.push_back({c.mesh.positions[e[0]].cast<float>(), c.mesh.positions[e[1]].cast<float>(), half_width(e[0]),
                    half_width(e[1]), chain[i]});
  }
  reach_ = look.max_width * (1 + look.noise) + look.shoulder_width;
  cell_ = std::max(reach_, 1e-4f);
  for (uint32_t i = 0; i < seg_.size(); ++i) {
    const Vec3f lo = seg_[i].a.cwiseMin(seg_[i].b).array() - reach_, hi = seg_[i].a.cwiseMax(seg_[i].b).array() + reach_;
    if (!(cells_spanned(lo, hi) <= kMaxCells)) {
      long_.push_back(i);
      continue;
    }
    for (int x = int(std::floor(lo.x() / cell_)); x <= int(std::floor(hi.x() / cell_)); ++x)
      for (int y = int(std::floor(lo.y() / cell_)); y <= int(std::floor(hi.y() / cell_)); ++y)
        for (int z = int(std::floor(lo.z() / cell_)); z <= int(std::floor(hi.z() / cell_)); ++z)
          grid_[cell_key(x, y, z)].push_back(i);
  }
  for (const auto& t : c.mesh.triangles) {
    auto p = [&](uint32_t k) { return K::Point_3(c.mesh.positions[k].x(), c.mesh.positions[k].y(), c.mesh.positions[k].z()); };
    triangles_.emplace_back(p(t[0]), p(t[1]), p(t[2]));
  }
  tree_ = std::make_unique<Tree>(triangles_.begin(), triangles_.end());
}

std::vector<float> CrackProfile::chain_coordinates(const bark::CrackedMesh& c, uint32_t seed) {
  // Union the two edges at every vertex of degree 2; junctions (3 or more) and ends split chains.
  const size_t n = c.crack_edges.size();
  std::unordered_map<uint32_t, std::vector<uint32_t>> at;
  for (uint32_t i = 0; i < n; ++i)
    for (uint32_t v : c.crack_edges[i]) at[v].push_back(i);
  std::vector<uint32_t> parent(n);
  for (uint32_t i = 0; i < n; ++i) parent[i] = i;
  auto find = [&](uint32_t i) {
    while (parent[i] != i) i = parent[i] = parent[parent[i]];
    return i;
  };
  for (const auto& [v, edges] : at)
    if (edges.size() == 2) {
      const uint32_t a = find(edges[0]), b = find(edges[1]);
      parent[std::max(a, b)] = std::min(a, b);  // the root is the chain's first edge
    }
  std::vector<float> coord(n);
  for (uint32_t i = 0; i < n; ++i) coord[i] = lattice_hash01(find(i), 0, seed ^ 0x6c8e9cf5u, 0, 0);
  return coord;
}

int64_t CrackProfile::cell_key(int x, int y, int z) const {
  return (int64_t(x) & 0x1fffff) | ((int64_t(y) & 0x1fffff) << 21) | ((int64_t(z) & 0x1fffff) << 42);
}

double CrackProfile::cells_spanned(const Vec3f& lo, const Vec3f& hi) const {
  double cells = 1;
  for (int k = 0; k < 3; ++k) {
    const double a = std::floor(double(lo[k]) / cell_), b = std::floor(double(hi[k]) / cell_);
    if (!(std::abs(a) < 1e9 && std::abs(b) < 1e9)) return std::numeric_limits<double>::infinity();
    cells *= b - a + 1;
  }
  return cells;
}

template <class F>
void CrackProfile::for_near(const Vec3f& lo, const Vec3f& hi, F&& f) const {
  // Every segment near the box, some more than once or farther (f measures): the few long
  // ones, then the grid's cells under the box — or every segment when the box spans too many.
  if (!(cells_spanned(lo, hi) <= kMaxCells)) {
    for (uint32_t i = 0; i < seg_.size(); ++i)
      if (f(i)) return;
    return;
  }
  for (uint32_t i : long_)
    if (f(i)) return;
  for (int x = int(std::floor(lo.x() / cell_)); x <= int(std::floor(hi.x() / cell_)); ++x)
    for (int y = int(std::floor(lo.y() / cell_)); y <= int(std::floor(hi.y() / cell_)); ++y)
      for (int z = int(std::floor(lo.z() / cell_)); z <= int(std::floor(hi.z() / cell_)); ++z) {
        const auto it = grid_.find(cell_key(x, y, z));
        if (it == grid_.end()) continue;
        for (uint32_t i : it->second)
          if (f(i)) return;
      }
}

CrackProfile::Sample CrackProfile::at(const Vec3f& p, const Vec3f& n) const {
  // The deepest V among the cracks whose width reaches p (sec. 4.2: ψ = k·(d_max − d)/d_max).
  Sample s;
  const float mod_w = 1 + look_.noise * fbm(p * kNoiseFrequency, seed_, 3);
  float mod_d = 1 + look_.noise * fbm(p * kNoiseFrequency, seed_ + 101, 3);
  if (look_.wall_noise > 0) mod_d *= 1 + look_.wall_noise * fbm(p / look_.wall_size, seed_ + 202, 4);
  float outside = std::numeric_limits<float>::infinity();  // distance beyond the nearest crack's half-width
  for_near(p, p, [&](uint32_t i) {
    const Segment& g = seg_[i];
    const Vec3f ab = g.b - g.a;
    const float len2 = ab.squaredNorm();
    const float t = len2 > 0 ? std::clamp((p - g.a).dot(ab) / len2, 0.0f, 1.0f) : 0.0f;
    Vec3f off = p - (g.a + t * ab);
    off -= off.dot(n) * n;  // distance across the surface
    const float d = off.norm();
    const float w = ((1 - t) * g.wa + t * g.wb) * mod_w;
    if (d - w < outside) {
      outside = d - w;
      s.chain = g.chain;
    }
    if (d >= w) return false;
    const float depth = std::min(look_.max_depth, look_.depth_per_width * w) * mod_d * (1 - d / w);
    if (depth > s.depth) s.depth = depth;
    s.mask = 1;
    return false;
  });
  if (s.depth > 0) {
    // Never through the other side: at most 45 % of the thickness along the inward normal.
    const K::Ray_3 ray(K::Point_3(p.x() - 1e-5f * n.x(), p.y() - 1e-5f * n.y(), p.z() - 1e-5f * n.z()),
                       K::Vector_3(-n.x(), -n.y(), -n.z()));
    if (const auto hit = tree_->first_intersection(ray)) {
      if (const K::Point_3* q = boost::get<K::Point_3>(&hit->first)) {
        const float thickness = float(std::sqrt(CGAL::squared_distance(*q, K::Point_3(p.x(), p.y(), p.z()))));
        s.depth = std::min(s.depth, 0.45f * thickness);
      }
    }
  }
  s.relative = look_.max_depth > 0 ? std::clamp(s.depth / look_.max_depth, 0.0f, 1.0f) : 0.0f;
  if (look_.shoulder > 0 && look_.shoulder_width > 0 && outside < std::numeric_limits<float>::infinity()) {
    const float t = std::clamp(outside / look_.shoulder_width, 0.0f, 1.0f);
    s.depth += look_.shoulder * look_.max_depth * (1 - t) * (1 - t);  // the parabolic shoulder (bark_relief.h)
  }
  if (look_.detail > 0) s.depth += look_.detail * look_.max_depth * fbm(p / look_.detail_size, seed_ + 303, 4);
  return s;
}

bool CrackProfile::reaches(const Vec3f& a, const Vec3f& b) const {
  bool found = false;
  for_near(a.cwiseMin(b), a.cwiseMax(b), [&](uint32_t i) {
    const Segment& g = seg_[i];
    // Segment–segment distance by sampling the edge (edges are short next to the reach).
    for (int k = 0; k <= 8 && !found; ++k) {
      const Vec3f p = a + (b - a) * (k / 8.0f);
      const Vec3f ab = g.b - g.a;
      const float len2 = ab.squaredNorm();
      const float t = len2 > 0 ? std::clamp((p - g.a).dot(ab) / len2, 0.0f, 1.0f) : 0.0f;
      found = (p - (g.a + t * ab)).norm() < reach_ + (b - a).norm() / 16;
    }
    return found;
  });
  return found;
}

}  // namespace phellem
