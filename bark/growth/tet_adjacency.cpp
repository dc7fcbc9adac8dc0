#include "bark/growth/tet_adjacency.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <atomic>
#include <cmath>

namespace phellem::bark {

bool positive_tet_exact(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c,
                        const Eigen::Vector3d& d) {
  using K = CGAL::Exact_predicates_inexact_constructions_kernel;
  auto p = [](const Eigen::Vector3d& v) { return K::Point_3(v.x(), v.y(), v.z()); };
  return CGAL::orientation(p(a), p(b), p(c), p(d)) == CGAL::POSITIVE;
}

TetAdjacency::TetAdjacency(const TetComplex& c) {
  const size_t n = c.points.size();
  offset_.assign(n + 1, 0);
  for (const auto& t : c.tets)
    for (uint32_t v : t) ++offset_[v + 1];
  for (size_t i = 0; i < n; ++i) offset_[i + 1] += offset_[i];
  flat_.resize(offset_[n]);
  std::vector<uint32_t> fill(offset_.begin(), offset_.end() - 1);
  for (uint32_t t = 0; t < c.tets.size(); ++t)
    for (uint32_t v : c.tets[t]) flat_[fill[v]++] = t;
  own_.resize(n);
  owned_.assign(n, 0);
  hint_.assign(4 * c.tets.size(), kNoHint);
}

void TetAdjacency::hint(uint32_t t, int f, uint32_t u) const {
  const size_t i = 4 * size_t(t) + size_t(f);
  if (i < hint_.size()) std::atomic_ref<uint32_t>(hint_[i]).store(u, std::memory_order_relaxed);
}

std::vector<uint32_t>& TetAdjacency::row(uint32_t p) {
  if (p >= own_.size()) {
    own_.resize(size_t(p) + 1);
    owned_.resize(size_t(p) + 1, 0);
  }
  if (!owned_[p]) {
    if (size_t(p) + 1 < offset_.size()) own_[p].assign(flat_.begin() + offset_[p], flat_.begin() + offset_[p + 1]);
    owned_[p] = 1;
  }
  return own_[p];
}

void TetAdjacency::link(uint32_t t, const std::array<uint32_t, 4>& corners) {
  for (uint32_t v : corners) row(v).push_back(t);
}

void TetAdjacency::unlink(uint32_t t, const std::array<uint32_t, 4>& corners) {
  for (uint32_t v : corners) {
    auto& r = row(v);
    const auto it = std::find(r.begin(), r.end(), t);
    if (it != r.end()) r.erase(it);
  }
}

long TetAdjacency::across(const TetComplex& c, uint32_t t, int f) const {
  const auto& T = c.tets[t];
  uint32_t a = T[size_t(kTetFace[f][0])], b = T[size_t(kTetFace[f][1])], d = T[size_t(kTetFace[f][2])];
  // The face is held by tetrahedron u, which is not t, at its corner other than a, b and d
  // (-1 when u lacks one of them).
  auto opposite_in = [&](uint32_t u) {
    const auto& U = c.tets[u];
    int other = -1, held = 0;
    for (int j = 0; j < 4; ++j) {
      const uint32_t v = U[size_t(j)];
      if (v == a || v == b || v == d)
        ++held;
      else
        other = j;
    }
    return held == 3 ? other : -1;
  };
  const size_t i = 4 * size_t(t) + size_t(f);
  if (i < hint_.size()) {
    const uint32_t h = std::atomic_ref<uint32_t>(hint_[i]).load(std::memory_order_relaxed);
    if (h != kNoHint && h != t && h < c.tets.size() && opposite_in(h) >= 0) return long(h);
  }
  // Walk the shortest row (box corners are in thousands of tetrahedra).
  if (around(b).size() < around(a).size()) std::swap(a, b);
  if (around(d).size() < around(a).size()) std::swap(a, d);
  for (uint32_t u : around(a)) {
    if (u == t) continue;
    if (const int g = opposite_in(u); g >= 0) {
      hint(t, f, u);
      hint(u, g, t);
      return long(u);
    }
  }
  return -1;
}

void TetAdjacency::edge_tets(const TetComplex& c, uint32_t a, uint32_t b, std::vector<uint32_t>& out) const {
  out.clear();
  if (around(b).size() < around(a).size()) std::swap(a, b);
  for (uint32_t u : around(a))
    if (std::find(c.tets[u].begin(), c.tets[u].end(), b) != c.tets[u].end()) out.push_back(u);
}

bool TetAdjacency::has_edge(const TetComplex& c, uint32_t a, uint32_t b) const {
  if (around(b).size() < around(a).size()) std::swap(a, b);
  for (uint32_t u : around(a))
    if (std::find(c.tets[u].begin(), c.tets[u].end(), b) != c.tets[u].end()) return true;
  return false;
}

void TetAdjacency::erase_tet(TetComplex& c, uint32_t t) {
  const uint32_t last = uint32_t(c.tets.size() - 1);
  unlink(t, c.tets[t]);
  if (t != last) {
    unlink(last, c.tets[last]);
    c.tets[t] = c.tets[last];
    c.label[t] = c.label[last];
    link(t, c.tets[t]);
  }
  c.tets.pop_back();
  c.label.pop_back();
}

void TetAdjacency::set_tet(TetComplex& c, uint32_t t, const std::array<uint32_t, 4>& corners) {
  unlink(t, c.tets[t]);
  c.tets[t] = corners;
  link(t, corners);
}

uint32_t TetAdjacency::add_tet(TetComplex& c, const std::array<uint32_t, 4>& corners, uint8_t label) {
  const uint32_t t = uint32_t(c.tets.size());
  c.tets.push_back(corners);
  c.label.push_back(label);
  link(t, corners);
  if (hint_.size() < 4 * c.tets.size()) hint_.resize(std::max(4 * c.tets.size(), hint_.size() + hint_.size() / 2), kNoHint);
  return t;
}

void TetAdjacency::split_edge_tets(TetComplex& c, uint32_t a, uint32_t b, uint32_t m, const std::vector<uint32_t>& shared) {
  for (uint32_t t : shared) {
    std::array<uint32_t, 4> half = c.tets[t], kept = c.tets[t];
    std::replace(half.begin(), half.end(), a, m);
    std::replace(kept.begin(), kept.end(), b, m);
    set_tet(c, t, kept);
    add_tet(c, half, c.label[t]);
  }
}

bool split_keeps_positive(const TetComplex& c, uint32_t a, uint32_t b, const Eigen::Vector3d& x,
                          const std::vector<uint32_t>& shared) {
  for (uint32_t t : shared) {
    std::array<Eigen::Vector3d, 4> kept, half;
    for (size_t j = 0; j < 4; ++j) {
      const uint32_t q = c.tets[t][j];
      kept[j] = q == b ? x : c.points[q];
      half[j] = q == a ? x : c.points[q];
    }
    if (!positive_tet(kept[0], kept[1], kept[2], kept[3]) || !positive_tet(half[0], half[1], half[2], half[3])) return false;
  }
  return !shared.empty();
}

namespace {

// Whether the face opposite corner f of tetrahedron t (not outside) is one interface_faces
// reports from t: its corners on the interface, and across it another label, the outside or
// an earlier tetrahedron.
bool reported_face(const TetComplex& c, const TetAdjacency& adj, uint32_t t, int f, std::array<uint32_t, 3>& face) {
  const auto& T = c.tets[t];
  face = {T[size_t(kTetFace[f][0])], T[size_t(kTetFace[f][1])], T[size_t(kTetFace[f][2])]};
  if (!c.on_interface[face[0]] || !c.on_interface[face[1]] || !c.on_interface[face[2]]) return false;
  const long u = adj.across(c, t, f);
  if (u < 0 || c.label[size_t(u)] == c.label[t]) return false;
  return c.label[size_t(u)] == TetComplex::kOutside || size_t(u) < t;  // else the later one's
}

}  // namespace

void interface_faces_at(const TetComplex& c, const TetAdjacency& adj, uint32_t v, std::vector<std::array<uint32_t, 3>>& out) {
  out.clear();
  std::vector<uint32_t> star(adj.around(v).begin(), adj.around(v).end());
  std::sort(star.begin(), star.end());  // tetrahedron order, as interface_faces
  std::array<uint32_t, 3> face{};
  for (uint32_t t : star) {
    if (c.label[t] == TetComplex::kOutside) continue;
    for (int f = 0; f < 4; ++f)
      if (c.tets[t][size_t(f)] != v && reported_face(c, adj, t, f, face)) out.push_back(face);
  }
}

std::vector<std::array<uint32_t, 3>> interface_faces(const TetComplex& c, const TetAdjacency& adj) {
  // Fixed blocks of tetrahedra, each collected on its own and joined in block order: the same
  // faces in the same order whatever the thread count.
  constexpr size_t kBlock = 8192;
  const size_t blocks = (c.tets.size() + kBlock - 1) / kBlock;
  std::vector<std::vector<std::array<uint32_t, 3>>> found(blocks);
  tbb::parallel_for(size_t(0), blocks, [&](size_t b) {
    const size_t end = std::min(c.tets.size(), (b + 1) * kBlock);
    for (size_t t = b * kBlock; t < end; ++t) {
      if (c.label[t] == TetComplex::kOutside) continue;
      std::array<uint32_t, 3> face{};
      for (int f = 0; f < 4; ++f)
        if (reported_face(c, adj, uint32_t(t), f, face)) found[b].push_back(face);
    }
  });
  size_t n = 0;
  for (const auto& f : found) n += f.size();
  std::vector<std::array<uint32_t, 3>> out;
  out.reserve(n);
  for (const auto& f : found) out.insert(out.end(), f.begin(), f.end());
  return out;
}

}  // namespace phellem::bark
