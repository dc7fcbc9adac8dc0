#include "bark/growth/interface_flips.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <tuple>

#include "bark/growth/tet_flips.h"

namespace phellem::bark {

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr size_t kMaxRing = 12;
constexpr double kQualityFloor = 0.05;

double angle_at(const Eigen::Vector3d& p, const Eigen::Vector3d& x, const Eigen::Vector3d& y) {
  const Eigen::Vector3d u = x - p, v = y - p;
  return std::atan2(u.cross(v).norm(), u.dot(v));
}

Eigen::Vector3d face_normal(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c) {
  return (b - a).cross(c - a).normalized();
}

struct Faces {
  double opposite = 0;  // the two angles opposite the edge, summed (radians)
  bool flat = false;    // normals within the turn, the new faces turned the same way, the gap small
};

// The angle tests on edge a–b with apexes p (face a–b–p) and q (face b–a–q).
Faces test_faces(const TetComplex& c, uint32_t a, uint32_t b, uint32_t p, uint32_t q, const InterfaceFlipSettings& settings) {
  const double cos_turn = std::cos(settings.max_turn_deg * kPi / 180);
  const Eigen::Vector3d &A = c.points[a], &B = c.points[b], &P = c.points[p], &Q = c.points[q];
  Faces f;
  f.opposite = angle_at(P, A, B) + angle_at(Q, B, A);
  const Eigen::Vector3d n1 = face_normal(A, B, P), n2 = face_normal(B, A, Q);
  const Eigen::Vector3d m1 = face_normal(A, Q, P), m2 = face_normal(B, P, Q);  // a–q–p, b–p–q
  const Eigen::Vector3d mean = n1 + n2;
  f.flat = n1.dot(n2) > cos_turn && m1.dot(mean) > 0 && m2.dot(mean) > 0 && m1.dot(m2) > cos_turn;
  // The surface moves by at most the distance between the two diagonals (the height of the
  // tetrahedron a–b–p–q over them): a small part of the edges' length.
  const Eigen::Vector3d across = (B - A).cross(Q - P);
  const double gap = std::abs((P - A).dot(across)) / std::max(across.norm(), 1e-300);
  f.flat = f.flat && gap <= settings.max_gap * std::min((B - A).norm(), (Q - P).norm());
  // Which way the surface moves: inwards where p–q passes under a–b (a ridge cut off),
  // outwards where it passes over it (a valley filled).
  const bool inwards = ((P + Q) - (A + B)).dot(mean) < 0;
  double limit = inwards ? settings.max_inward : settings.max_outward;
  if (settings.moved) {
    const std::vector<double>& m = *settings.moved;
    auto at = [&](uint32_t v) { return v < m.size() ? m[v] : 0.0; };
    limit += 0.5 * std::min({at(a), at(b), at(p), at(q)});
  }
  f.flat = f.flat && gap <= limit;
  return f;
}

// Permutation parity of t against (w0, w1, w2, w3) (the same four points): true when even.
bool even_order(const std::array<uint32_t, 4>& t, const std::array<uint32_t, 4>& w) {
  std::array<int, 4> perm{};
  for (int i = 0; i < 4; ++i) perm[size_t(i)] = int(std::find(t.begin(), t.end(), w[size_t(i)]) - t.begin());
  int inversions = 0;
  for (int i = 0; i < 4; ++i)
    for (int j = i + 1; j < 4; ++j) inversions += perm[size_t(i)] > perm[size_t(j)];
  return inversions % 2 == 0;
}

}  // namespace

bool flip_interface_edge(TetComplex& c, TetAdjacency& adj, uint32_t a, uint32_t b, double max_length,
                         const InterfaceFlipSettings& settings) {
  if (a == b || !c.on_interface[a] || !c.on_interface[b]) return false;
  auto fixed = [&](uint32_t v) { return c.frozen[v] || c.on_box[v] || (!c.on_crack.empty() && c.on_crack[v]); };
  if (fixed(a) || fixed(b)) return false;
  thread_local std::vector<uint32_t> around_ab, ring, ring_tet;
  adj.edge_tets(c, a, b, around_ab);
  const size_t n = around_ab.size();
  if (n < 2 || n > kMaxRing) return false;
  for (uint32_t t : around_ab)
    if (c.label[t] == TetComplex::kObstacle) return false;
  // The ring of the edge (tet_flips.h): tetrahedron ring_tet[i] links ring[i] to ring[i + 1].
  if (!edge_ring(c, around_ab, a, b, ring, ring_tet)) return false;
  // The ring rotated to start at p, the first vertex of the inside run: ring_tet[0..k] inside,
  // ring_tet[k+1..n−1] outside. Exactly two label changes around the edge (an interface edge).
  size_t start = n;
  int changes = 0;
  for (size_t i = 0; i < n; ++i) {
    const uint8_t before = c.label[ring_tet[(i + n - 1) % n]], here = c.label[ring_tet[i]];
    if (before != here) {
      ++changes;
      if (here == TetComplex::kInside) start = i;
    }
  }
  if (changes != 2 || start == n) return false;
  std::rotate(ring.begin(), ring.begin() + long(start), ring.end());
  std::rotate(ring_tet.begin(), ring_tet.begin() + long(start), ring_tet.end());
  size_t k = 0;  // inside tetrahedra: k + 1
  while (c.label[ring_tet[k + 1]] == TetComplex::kInside) ++k;
  const uint32_t p = ring[0], q = ring[k + 1];
  if (!c.on_interface[p] || !c.on_interface[q]) return false;
  if ((c.points[p] - c.points[q]).norm() > max_length) return false;
  if (adj.has_edge(c, p, q)) return false;
  // The ring runs one way round the edge: tetrahedron a–b–ring[i]–ring[i+1] has one parity
  // for every i. Which interface face has which apex follows from it (the face opposite the
  // outside corner of an inside tetrahedron, oriented outwards from it).
  const bool even = even_order(c.tets[ring_tet[0]], {a, b, ring[0], ring[1]});
  for (size_t i = 1; i < n; ++i)
    if (even_order(c.tets[ring_tet[i]], {a, b, ring[i], ring[(i + 1) % n]}) != even) return false;
  auto base = [&](uint32_t x, uint32_t y) {
    return even ? std::array<uint32_t, 4>{a, b, x, y} : std::array<uint32_t, 4>{b, a, x, y};
  };
  // The interface faces on the edge, oriented outwards: those of the inside tetrahedra at the
  // two ends of the inside run.
  {
    // Face a–b–p belongs to the tetrahedron base(p, ring[1]) (inside) as its face opposite
    // ring[1]; its outward orientation decides which way round the test reads the apexes.
    const std::array<uint32_t, 4> t0 = base(p, ring[1]);
    const int j = 3;  // ring[1] is corner 3 of t0
    std::array<uint32_t, 3> f{t0[size_t(kTetFace[j][0])], t0[size_t(kTetFace[j][1])], t0[size_t(kTetFace[j][2])]};
    std::rotate(f.begin(), std::find(f.begin(), f.end(), p), f.end());  // p, x, y
    const uint32_t x = f[1], y = f[2];                                  // face p–x–y, {x, y} = {a, b}
    const Faces faces = test_faces(c, x, y, p, q, settings);
    if (!faces.flat || faces.opposite <= settings.min_opposite_deg * kPi / 180) return false;
  }
  double before = 1e300;
  for (uint32_t t : around_ab) before = std::min(before, tet_quality(c, c.tets[t]));
  const double floor = std::min(before, kQualityFloor);
  // The best fan of a part of the ring (closed by its last-to-first edge): its tetrahedra and
  // their worst quality, or nothing when no fan is positive.
  thread_local std::vector<std::array<uint32_t, 4>> made_in, made_out, fan;
  auto best_fan = [&](const std::vector<uint32_t>& part, std::vector<std::array<uint32_t, 4>>& out) {
    out.clear();
    const size_t m = part.size();
    if (m < 3) return 1e300;  // the run is a single tetrahedron: it goes, nothing replaces it
    double best = -1e300;
    for (size_t r = 0; r < m; ++r) {
      const uint32_t r0 = part[r];
      fan.clear();
      double worst = 1e300;
      bool ok = true;
      for (size_t j = 0; j < m && ok; ++j) {
        const uint32_t x = part[j], y = part[(j + 1) % m];
        if (x == r0 || y == r0) continue;
        std::array<uint32_t, 4> top = base(x, y), bottom = top;
        std::replace(top.begin(), top.end(), b, r0);
        std::replace(bottom.begin(), bottom.end(), a, r0);
        for (const auto& t : {top, bottom}) {
          if (c.on_interface[t[0]] && c.on_interface[t[1]] && c.on_interface[t[2]] && c.on_interface[t[3]]) ok = false;
          worst = std::min(worst, tet_quality(c, t));
          fan.push_back(t);
        }
        if (!(worst > best) || !(worst >= floor)) ok = false;
      }
      if (!ok) continue;
      for (const auto& t : fan) ok = ok && positive_tet(c, t);
      if (!ok) continue;
      best = worst;
      out = fan;
    }
    return out.empty() ? -1e300 : best;
  };
  const std::vector<uint32_t> inside(ring.begin(), ring.begin() + long(k + 2));  // p … q
  std::vector<uint32_t> outside(ring.begin() + long(k + 1), ring.end());         // q … back to p
  outside.push_back(p);
  if (best_fan(inside, made_in) < floor || best_fan(outside, made_out) < floor) return false;
  if (made_in.empty() && made_out.empty()) return false;
  // The n old slots for the new tetrahedra, the inside fan's then the outside one's.
  std::vector<std::array<uint32_t, 4>> made(made_in);
  made.insert(made.end(), made_out.begin(), made_out.end());
  std::vector<uint8_t> labels(made.size(), TetComplex::kOutside);
  std::fill_n(labels.begin(), made_in.size(), TetComplex::kInside);
  replace_tets(c, adj, around_ab, made, labels);
  return true;
}

long flip_interface_edges(TetComplex& c, TetAdjacency& adj, const std::vector<std::array<uint32_t, 3>>& faces,
                          double max_length, const InterfaceFlipSettings& settings) {
  // The two angles opposite an edge sum past min_opposite only if the larger is past half of
  // it (120° for the default 240°). So the faces' angles are tested first, in parallel, and
  // only the edges opposite such an angle are paired up: sorting every face's edges took most
  // of this pass, for a few flips a step. The margins keep every edge whose rounded sum
  // passes, and the sum is of the same expressions as before, so the flips are the same.
  const double min_opposite = settings.min_opposite_deg * kPi / 180;
  const double least = 0.5 * min_opposite - 1e-9;
  // The cosine first (no arc tangent), with a margin far above its rounding.
  const double cos_least = std::cos(std::max(0.0, least - 1e-6));
  auto ends = [&](const std::array<uint32_t, 3>& f, int k) {
    const uint32_t x = f[size_t(k + 1) % 3], y = f[size_t(k + 2) % 3];
    return std::array<uint32_t, 2>{std::min(x, y), std::max(x, y)};
  };
  auto angle_opposite = [&](const std::array<uint32_t, 3>& f, int k) {
    const auto e = ends(f, k);
    return angle_at(c.points[f[size_t(k)]], c.points[e[0]], c.points[e[1]]);
  };
  constexpr size_t kBlock = 4096;
  std::vector<std::vector<std::array<uint32_t, 2>>> wide((faces.size() + kBlock - 1) / kBlock);
  tbb::parallel_for(size_t(0), wide.size(), [&](size_t b) {
    for (size_t i = b * kBlock; i < std::min(faces.size(), (b + 1) * kBlock); ++i)
      for (int k = 0; k < 3; ++k) {
        const Eigen::Vector3d& p = c.points[faces[i][size_t(k)]];
        const Eigen::Vector3d u = c.points[faces[i][size_t(k + 1) % 3]] - p, v = c.points[faces[i][size_t(k + 2) % 3]] - p;
        if (u.dot(v) < cos_least * std::sqrt(u.squaredNorm() * v.squaredNorm()) && angle_opposite(faces[i], k) > least)
          wide[b].push_back(ends(faces[i], k));
      }
  });
  std::vector<std::array<uint32_t, 2>> candidates;
  for (const auto& w : wide) candidates.insert(candidates.end(), w.begin(), w.end());
  std::sort(candidates.begin(), candidates.end());
  candidates.erase(std::unique(candidates.begin(), candidates.end()), candidates.end());
  // Each candidate edge with its apexes and their angles, sorted by edge then apex.
  struct Half {
    uint32_t lo, hi, apex;
    double angle;
  };
  std::vector<Half> halves;
  std::vector<uint8_t> at_candidate(c.points.size(), 0);
  for (const auto& e : candidates) at_candidate[e[0]] = at_candidate[e[1]] = 1;
  for (const auto& f : faces)
    for (int k = 0; k < 3; ++k) {
      const auto e = ends(f, k);
      if (at_candidate[e[0]] && at_candidate[e[1]] && std::binary_search(candidates.begin(), candidates.end(), e))
        halves.push_back({e[0], e[1], f[size_t(k)], angle_opposite(f, k)});
    }
  std::sort(halves.begin(), halves.end(),
            [](const Half& l, const Half& r) { return std::tie(l.lo, l.hi, l.apex) < std::tie(r.lo, r.hi, r.apex); });
  using Candidate = std::tuple<double, uint32_t, uint32_t>;  // −opposite, a < b
  std::vector<Candidate> todo;
  for (size_t i = 0; i + 1 < halves.size(); ++i) {
    const Half &h = halves[i], &g = halves[i + 1];
    if (h.lo != g.lo || h.hi != g.hi) continue;
    const double opposite = h.angle + g.angle;
    if (opposite > min_opposite) todo.push_back({-opposite, h.lo, h.hi});
  }
  std::sort(todo.begin(), todo.end());
  std::vector<uint8_t> touched(c.points.size(), 0);
  long flips = 0;
  for (const auto& [neg, a, b] : todo) {
    if (touched[a] || touched[b]) continue;
    if (!flip_interface_edge(c, adj, a, b, max_length, settings)) continue;
    ++flips;
    // The faces at a and b changed (and at the apexes, whose edges to a and b they share).
    for (uint32_t v : {a, b}) touched[v] = 1;
    for (uint32_t t : adj.around(a))
      for (uint32_t w : c.tets[t])
        if (c.on_interface[w]) touched[w] = 1;  // (flips add no points: w < touched.size())
  }
  return flips;
}

}  // namespace phellem::bark
