#include "bark/growth/tet_flips.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <limits>
#include <tuple>

#include "bark/growth/free_vertex_removal.h"

namespace phellem::bark {

namespace {

constexpr double kGain = 1e-9;  // a flip or move must raise the worst quality by more than this

const Eigen::Vector3d& at(const TetComplex& c, uint32_t p, const Probe& probe) {
  return p == probe.v ? probe.x : c.points[p];
}

// probe_quality, inlined where the repair evaluates it millions of times a step (the same
// operations, so the same bits under -ffp-contract=off).
[[gnu::always_inline]] inline double quality_seen(const TetComplex& c, const std::array<uint32_t, 4>& t, const Probe& probe) {
  return tet_quality(at(c, t[0], probe), at(c, t[1], probe), at(c, t[2], probe), at(c, t[3], probe));
}

bool free_vertex(const TetComplex& c, const TetAdjacency& adj, uint32_t v) {
  return !c.on_interface[v] && !c.on_box[v] && !c.frozen[v] && !adj.unused(v);
}

}  // namespace

double probe_quality(const TetComplex& c, const std::array<uint32_t, 4>& t, const Probe& probe) {
  return quality_seen(c, t, probe);
}

bool edge_ring(const TetComplex& c, const std::vector<uint32_t>& around_ab, uint32_t a, uint32_t b,
               std::vector<uint32_t>& ring, std::vector<uint32_t>& ring_tet) {
  thread_local std::vector<std::array<uint32_t, 2>> links;
  thread_local std::vector<uint8_t> used;
  thread_local std::vector<uint32_t> distinct;
  const size_t n = around_ab.size();
  if (n == 0) return false;
  // Each tetrahedron a–b–x–y links x to y; they must close.
  links.resize(n);
  for (size_t i = 0; i < n; ++i) {
    int k = 0;
    for (uint32_t w : c.tets[around_ab[i]])
      if (w != a && w != b) links[i][size_t(k++)] = w;
    if (k != 2) return false;
  }
  ring.assign({links[0][0], links[0][1]});
  ring_tet.assign({around_ab[0]});  // ring_tet[i] holds ring[i]–ring[i+1]
  used.assign(n, 0);
  used[0] = 1;
  while (ring.size() <= n) {
    bool found = false;
    for (size_t i = 0; i < n && !found; ++i) {
      if (used[i]) continue;
      const uint32_t last = ring.back();
      if (links[i][0] == last || links[i][1] == last) {
        ring.push_back(links[i][0] == last ? links[i][1] : links[i][0]);
        ring_tet.push_back(around_ab[i]);
        used[i] = 1;
        found = true;
      }
    }
    if (!found) break;
  }
  if (ring.size() != n + 1 || ring.back() != ring.front()) return false;
  ring.pop_back();
  distinct = ring;
  std::sort(distinct.begin(), distinct.end());
  return std::adjacent_find(distinct.begin(), distinct.end()) == distinct.end();
}

bool flip_23(TetComplex& c, TetAdjacency& adj, uint32_t t, int f, const Probe& probe, FlipStats& stats) {
  const uint8_t label = c.label[t];
  if (label == TetComplex::kObstacle) return false;
  const long ul = adj.across(c, t, f);
  if (ul < 0 || c.label[size_t(ul)] != label) return false;
  const uint32_t u = uint32_t(ul);
  const std::array<uint32_t, 4> T = c.tets[t], U = c.tets[u];
  const uint32_t d = T[size_t(f)];
  uint32_t e = U[0];
  for (uint32_t w : U)
    if (std::find(T.begin(), T.end(), w) == T.end()) e = w;
  if (e == d || adj.has_edge(c, d, e)) return false;
  // Never a new edge between two interface points through the outside: such an edge caps the
  // interface, and the cap flattens and blocks as the interface grows under it.
  if (label == TetComplex::kOutside && c.on_interface[d] && c.on_interface[e]) return false;
  // Each new tetrahedron is T with one face corner replaced by e: positive exactly when the
  // segment d–e crosses the shared face (the union is convex there).
  std::array<std::array<uint32_t, 4>, 3> made;
  int k = 0;
  for (int i = 0; i < 4; ++i) {
    if (i == f) continue;
    made[size_t(k)] = T;
    made[size_t(k)][size_t(i)] = e;
    ++k;
  }
  const double before = std::min(quality_seen(c, T, probe), quality_seen(c, U, probe));
  double after = 1e300;
  for (const auto& m : made) after = std::min(after, quality_seen(c, m, probe));
  if (!(after > before + kGain)) return false;
  for (const auto& m : made)
    if (!positive_tet(c, m)) return false;
  adj.set_tet(c, t, made[0]);
  adj.set_tet(c, u, made[1]);
  adj.add_tet(c, made[2], label);
  ++stats.flips23;
  return true;
}

bool flip_32(TetComplex& c, TetAdjacency& adj, uint32_t a, uint32_t b, const Probe& probe, FlipStats& stats) {
  return remove_edge(c, adj, a, b, probe, stats, 3);
}

void replace_tets(TetComplex& c, TetAdjacency& adj, std::span<const uint32_t> old, std::span<const std::array<uint32_t, 4>> made,
                  std::span<const uint8_t> labels) {
  thread_local std::vector<uint32_t> slots;
  slots.assign(old.begin(), old.end());
  std::sort(slots.begin(), slots.end());
  size_t k = 0;
  for (; k < std::min(slots.size(), made.size()); ++k) {
    adj.set_tet(c, slots[k], made[k]);
    c.label[slots[k]] = labels[k];
  }
  for (size_t i = k; i < made.size(); ++i) adj.add_tet(c, made[i], labels[i]);
  for (size_t i = slots.size(); i-- > k;) adj.erase_tet(c, slots[i]);  // last first: indices stay valid
}

bool remove_edge(TetComplex& c, TetAdjacency& adj, uint32_t a, uint32_t b, const Probe& probe, FlipStats& stats,
                 int max_ring) {
  // Scratch buffers kept per thread: a step tries this hundreds of thousands of times.
  thread_local std::vector<uint32_t> around_ab, ring, ring_tet;
  thread_local std::vector<std::array<uint32_t, 4>> best_made, made;
  thread_local std::vector<uint8_t> labels;
  adj.edge_tets(c, a, b, around_ab);
  const size_t n = around_ab.size();
  if (n < 3 || n > size_t(max_ring)) return false;
  const uint8_t label = c.label[around_ab[0]];
  if (label == TetComplex::kObstacle) return false;
  for (uint32_t t : around_ab)
    if (c.label[t] != label) return false;
  if (!edge_ring(c, around_ab, a, b, ring, ring_tet)) return false;
  double before = 1e300;
  for (uint32_t t : around_ab) before = std::min(before, quality_seen(c, c.tets[t], probe));
  // Each fan of the ring from one of its vertices r0: for every ring edge rj–rj+1 not at r0,
  // the old tetrahedron a–b–rj–rj+1 with b (then a) replaced by r0 — positive exactly when
  // the edge a–b crosses the fan's triangle r0–rj–rj+1 (the 3-2 flip is the case n = 3).
  auto all_interface = [&](const std::array<uint32_t, 4>& t) {
    return c.on_interface[t[0]] && c.on_interface[t[1]] && c.on_interface[t[2]] && c.on_interface[t[3]];
  };
  double best = before + kGain;
  best_made.clear();
  for (size_t apex = 0; apex < n; ++apex) {
    const uint32_t r0 = ring[apex];
    made.clear();
    bool ok = true;
    double q = 1e300;
    for (size_t j = 0; j < n && ok; ++j) {
      const uint32_t x = ring[j], y = ring[(j + 1) % n];
      if (x == r0 || y == r0) continue;
      // No new edge between two interface points through the outside (see flip_23).
      if (label == TetComplex::kOutside && j != (apex + 1) % n && c.on_interface[r0] && c.on_interface[x]) ok = false;
      std::array<uint32_t, 4> top = c.tets[ring_tet[j]], bottom = top;
      std::replace(top.begin(), top.end(), b, r0);
      std::replace(bottom.begin(), bottom.end(), a, r0);
      if (all_interface(top) || all_interface(bottom)) ok = false;
      q = std::min({q, quality_seen(c, top, probe), quality_seen(c, bottom, probe)});
      if (!(q > best)) ok = false;  // this fan cannot win: its worst only drops further
      made.push_back(top);
      made.push_back(bottom);
    }
    if (!ok || !(q > best)) continue;
    for (const auto& m : made) ok = ok && positive_tet(c, m);
    if (!ok) continue;
    best = q;
    best_made = made;
  }
  if (best_made.empty()) return false;
  // n old slots for 2(n − 2) new tetrahedra.
  labels.assign(best_made.size(), label);
  replace_tets(c, adj, around_ab, best_made, labels);
  if (n == 3)
    ++stats.flips32;
  else
    ++stats.edge_removals;
  return true;
}

bool relocate_free_vertex(TetComplex& c, TetAdjacency& adj, uint32_t v, const Probe& probe, FlipStats& stats) {
  if (!free_vertex(c, adj, v) || v == probe.v) return false;
  const std::span<const uint32_t> tets = adj.around(v);  // only positions change here
  // The worst quality of v's tetrahedra with v at x; stops (returning a quality ≤ floor) as
  // soon as one is at or below `floor`, which is all a candidate that must beat it needs.
  // The tetrahedron that stopped the last candidate is tried first (a free vertex of the coarse
  // outside has a hundred tetrahedra, and the same one usually stops every candidate).
  size_t first = 0;
  auto worst_at = [&](const Eigen::Vector3d& x, uint32_t* worst_tet, double floor) {
    Probe p = probe;
    const Eigen::Vector3d keep = c.points[v];
    c.points[v] = x;
    if (!worst_tet) {
      const double q0 = quality_seen(c, c.tets[tets[first]], p);
      if (q0 <= floor) {
        c.points[v] = keep;
        return q0;
      }
    }
    double q = 1e300;
    for (size_t i = 0; i < tets.size(); ++i) {
      const uint32_t t = tets[i];
      const double qt = quality_seen(c, c.tets[t], p);
      if (qt < q) {
        q = qt;
        if (worst_tet) {
          *worst_tet = t;
          first = i;
        }
        if (q <= floor) {
          first = i;
          break;
        }
      }
    }
    c.points[v] = keep;
    return q;
  };
  const Eigen::Vector3d start = c.points[v];
  uint32_t worst = tets.front();
  const double before = worst_at(start, &worst, -1e300);
  // Candidates: the mean of the neighbours (Laplacian smoothing) and pushes of v away from the
  // plane of its worst tetrahedron's opposite face (the direction that inflates it).
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  int n = 0;
  for (uint32_t t : tets)
    for (uint32_t w : c.tets[t])
      if (w != v) {
        mean += at(c, w, probe);
        ++n;
      }
  mean /= n;
  std::vector<Eigen::Vector3d> candidates{mean, 0.5 * (start + mean)};
  {
    const auto& T = c.tets[worst];
    const int i = int(std::find(T.begin(), T.end(), v) - T.begin());
    const Eigen::Vector3d &p0 = at(c, T[size_t(kTetFace[i][0])], probe), &p1 = at(c, T[size_t(kTetFace[i][1])], probe),
                          &p2 = at(c, T[size_t(kTetFace[i][2])], probe);
    // The face is oriented outwards from T, so v lies on its negative side: push along −normal.
    Eigen::Vector3d nrm = (p1 - p0).cross(p2 - p0);
    const double len = ((p1 - p0).norm() + (p2 - p1).norm() + (p0 - p2).norm()) / 3;
    if (nrm.squaredNorm() > 0) {
      nrm.normalize();
      const Eigen::Vector3d centroid = (p0 + p1 + p2) / 3;
      const Eigen::Vector3d ideal = centroid - nrm * (len * 0.8165);  // the regular tetrahedron's apex
      for (double s : {1.0, 0.5, 0.25, 0.1}) candidates.push_back(start + s * (ideal - start));
    }
  }
  double best = before;
  Eigen::Vector3d best_x = start;
  for (const auto& x : candidates) {
    const double q = worst_at(x, nullptr, best + kGain);
    if (q > best + kGain) {
      c.points[v] = x;
      bool ok = true;
      for (uint32_t t : tets) ok = ok && positive_tet(c, c.tets[t]);
      c.points[v] = start;
      if (ok) {
        best = q;
        best_x = x;
      }
    }
  }
  if (best_x == start) return false;
  c.points[v] = best_x;
  ++stats.relocated;
  return true;
}

uint32_t split_free_edge(TetComplex& c, TetAdjacency& adj, uint32_t a, uint32_t b, FlipStats& stats) {
  std::vector<uint32_t> shared;
  adj.edge_tets(c, a, b, shared);
  const uint32_t m = c.add_point_between(a, b, 0.5);
  c.on_interface[m] = 0;  // not an interface edge, though both ends may be interface points
  c.on_box[m] = 0;
  c.frozen[m] = 0;
  adj.split_edge_tets(c, a, b, m, shared);
  ++stats.splits;
  return m;
}

namespace {

// The operations (relocations, edge removals, 2-3 flips) that failed since the complex last
// changed, within one unblock_vertex (one probe): every change there is counted in its
// FlipStats, so an unchanged count means the same complex, and retrying such an operation
// would fail again (the tetrahedra around v share edges and free corners, so each is tried
// from several of them).
class FailedOps {
 public:
  using Key = std::array<uint32_t, 3>;  // {kind, and what it is on}
  // op() unless it is known to fail; remembers a failure.
  template <class Op>
  bool attempt(const Key& key, const FlipStats& s, Op&& op) {
    if (changes(s) != at_) {
      failed_.clear();
      at_ = changes(s);
    }
    if (std::find(failed_.begin(), failed_.end(), key) != failed_.end()) return false;
    if (op()) return true;
    failed_.push_back(key);
    return false;
  }

 private:
  static long changes(const FlipStats& s) {
    return s.flips23 + s.flips32 + s.relocated + s.splits + s.edge_removals + s.removed;
  }
  std::vector<Key> failed_;
  long at_ = -1;
};

// Flips and relocations that improve tetrahedron t (its faces, its edges, its free vertices);
// with max_length > 0, a split of its longest edge not between interface points if longer.
bool improve_tet(TetComplex& c, TetAdjacency& adj, uint32_t t, const Probe& probe, FlipStats& stats, int skip_corner,
                 double max_length, bool relocate, int max_ring, FailedOps* failed = nullptr) {
  const std::array<uint32_t, 4> T = c.tets[t];
  auto attempt = [&](const FailedOps::Key& key, auto&& op) { return failed ? failed->attempt(key, stats, op) : op(); };
  auto edge_removal = [&](uint32_t a, uint32_t b) {
    return attempt({0, a, b}, [&] { return remove_edge(c, adj, a, b, probe, stats, max_ring); });
  };
  // 3-2 flips of its edges (opposite skip_corner first when blocked). Flips are among outside
  // tetrahedra only, and t is one of those around each of its edges and faces: for any other
  // t every flip would refuse, so none is tried.
  static constexpr int kEdge[6][2] = {{0, 1}, {0, 2}, {0, 3}, {1, 2}, {1, 3}, {2, 3}};
  const bool outside = c.label[t] != TetComplex::kObstacle;  // (inside too)
  for (const auto& e : kEdge) {
    if (!outside || e[0] == skip_corner || e[1] == skip_corner) continue;
    if (edge_removal(T[size_t(e[0])], T[size_t(e[1])])) return true;
  }
  for (int f = 0; f < 4; ++f) {
    if (!outside || (skip_corner >= 0 && f != skip_corner)) continue;
    if (attempt({1, t, uint32_t(f)}, [&] { return flip_23(c, adj, t, f, probe, stats); })) return true;
  }
  if (outside && skip_corner >= 0)
    for (const auto& e : kEdge)
      if (e[0] == skip_corner || e[1] == skip_corner)
        if (edge_removal(T[size_t(e[0])], T[size_t(e[1])])) return true;
  // A free corner pressed against the rest (the front pushes the outside together): removed.
  for (int i = 0; i < 4; ++i) {
    if (i == skip_corner) continue;
    const uint32_t w = T[size_t(i)];
    if (attempt({3, w, 0}, [&] { return remove_free_vertex(c, adj, w, probe, stats); })) return true;
  }
  if (max_length > 0) {
    double longest = max_length;
    int best = -1;
    for (int k = 0; k < 6; ++k) {
      const uint32_t a = T[size_t(kEdge[k][0])], b = T[size_t(kEdge[k][1])];
      if ((c.on_interface[a] && c.on_interface[b]) || (c.on_box[a] && c.on_box[b])) continue;
      const double len = (c.points[a] - c.points[b]).norm();
      if (len > longest) {
        longest = len;
        best = k;
      }
    }
    if (best >= 0) {
      split_free_edge(c, adj, T[size_t(kEdge[best][0])], T[size_t(kEdge[best][1])], stats);
      return true;
    }
  }
  if (!relocate) return false;
  bool moved = false;
  for (int i = 0; i < 4; ++i) {
    if (i == skip_corner) continue;
    const uint32_t w = T[size_t(i)];
    moved = attempt({2, w, 0}, [&] { return relocate_free_vertex(c, adj, w, probe, stats); }) || moved;
  }
  return moved;
}

long find_tet(const TetComplex& c, const TetAdjacency& adj, const std::array<uint32_t, 4>& corners) {
  uint32_t p = corners[0];
  for (uint32_t w : corners)
    if (adj.around(w).size() < adj.around(p).size()) p = w;
  for (uint32_t t : adj.around(p))
    if (c.tets[t] == corners) return long(t);
  return -1;
}

}  // namespace

bool unblock_vertex(TetComplex& c, TetAdjacency& adj, uint32_t v, const Eigen::Vector3d& target, FlipStats& stats) {
  const Probe probe{v, target};
  constexpr double kBlocking = 0.02;
  bool changed = false;
  FailedOps failed;
  for (int round = 0; round < 4; ++round) {
    std::vector<std::pair<double, std::array<uint32_t, 4>>> blocking;
    for (uint32_t t : adj.around(v)) {
      const double q = quality_seen(c, c.tets[t], probe);
      if (q < kBlocking) blocking.push_back({q, c.tets[t]});
    }
    if (blocking.empty()) break;
    std::sort(blocking.begin(), blocking.end());
    bool any = false;
    for (const auto& [q, corners] : blocking) {
      const long t = find_tet(c, adj, corners);
      if (t < 0) continue;
      const int i = int(std::find(corners.begin(), corners.end(), v) - corners.begin());
      any = improve_tet(c, adj, uint32_t(t), probe, stats, i, 0, true, 6, &failed) || any;
    }
    changed = changed || any;
    if (!any) break;
  }
  return changed;
}

FlipStats improve_tets_near(TetComplex& c, TetAdjacency& adj, const std::vector<uint32_t>& points, double threshold,
                            double max_length, int passes, bool relocate) {
  FlipStats stats;
  const Probe none;
  std::vector<uint8_t> dirty(c.points.size(), 0);
  std::vector<uint32_t> changed;                    // the points dirty marks (with repeats)
  std::vector<uint8_t> listed(c.points.size(), 0);  // 1 at the given points
  for (uint32_t p : points)
    if (p < listed.size()) listed[p] = 1;
  for (int pass = 0; pass < passes; ++pass) {
    // The poor outside tetrahedra at the points (in the first pass all of them, afterwards only
    // those with a corner the previous pass changed or made), each once: from its smallest
    // listed corner.
    auto smallest_listed = [&](const std::array<uint32_t, 4>& T) {
      uint32_t s = std::numeric_limits<uint32_t>::max();
      for (uint32_t w : T)
        if (w < listed.size() && listed[w]) s = std::min(s, w);
      return s;
    };
    std::vector<std::pair<double, std::array<uint32_t, 4>>> bad;
    if (pass == 0) {
      // Collected in fixed blocks of points in parallel, joined in order: deterministic.
      constexpr size_t kBlock = 1024;
      const size_t blocks = (points.size() + kBlock - 1) / kBlock;
      std::vector<std::vector<std::pair<double, std::array<uint32_t, 4>>>> found(blocks);
      tbb::parallel_for(size_t(0), blocks, [&](size_t b) {
        for (size_t k = b * kBlock; k < std::min(points.size(), (b + 1) * kBlock); ++k) {
          const uint32_t p = points[k];
          for (uint32_t t : adj.around(p)) {
            if (c.label[t] == TetComplex::kObstacle || smallest_listed(c.tets[t]) != p) continue;
            const double q = tet_quality(c, c.tets[t]);
            if (q < threshold) found[b].push_back({q, c.tets[t]});
          }
        }
      });
      for (const auto& f : found) bad.insert(bad.end(), f.begin(), f.end());
    } else {
      // From the changed points and the new ones (few) rather than from every listed point:
      // the same tetrahedra, each once (the order is the sort's below).
      std::sort(changed.begin(), changed.end());
      changed.erase(std::unique(changed.begin(), changed.end()), changed.end());
      for (uint32_t m = uint32_t(dirty.size()); m < c.points.size(); ++m) changed.push_back(m);
      for (uint32_t d : changed)
        for (uint32_t t : adj.around(d)) {
          if (c.label[t] == TetComplex::kObstacle || smallest_listed(c.tets[t]) == std::numeric_limits<uint32_t>::max())
            continue;
          const double q = tet_quality(c, c.tets[t]);
          if (q < threshold) bad.push_back({q, c.tets[t]});
        }
      std::sort(bad.begin(), bad.end());
      bad.erase(std::unique(bad.begin(), bad.end()), bad.end());
    }
    changed.clear();
    std::fill(dirty.begin(), dirty.end(), 0);
    dirty.resize(c.points.size(), 0);
    if (bad.empty()) break;
    // The worst first, and a bounded number a pass (a coarse outside can hold tens of
    // thousands of needles to the box corners, most of which no flip improves): the step's
    // cost stays linear in the interface, and the rest waits for the next step.
    const size_t budget = std::max<size_t>(64, points.size() / 4);
    if (bad.size() > budget) {
      std::partial_sort(bad.begin(), bad.begin() + long(budget), bad.end());
      bad.resize(budget);
    } else {
      std::sort(bad.begin(), bad.end());
    }
    bool any = false;
    for (const auto& [q, corners] : bad) {
      const long t = find_tet(c, adj, corners);
      if (t < 0) continue;
      if (improve_tet(c, adj, uint32_t(t), none, stats, -1, max_length, relocate, 3)) {
        any = true;
        for (uint32_t w : corners)
          if (w < dirty.size()) {
            dirty[w] = 1;
            changed.push_back(w);
          }
      }
    }
    if (!any) break;
  }
  return stats;
}

}  // namespace phellem::bark
