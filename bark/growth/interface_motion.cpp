#include "bark/growth/interface_motion.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>

#include "bark/growth/point_marks.h"
#include "bark/growth/tet_flips.h"
#include "bark/growth/texture_transport.h"
#include "util/stopwatch.h"

namespace phellem::bark {

namespace {

constexpr int kMaxHalvings = 6;
constexpr int kRounds = 4;  // move, retessellate what blocks, move on

double signed_volume(const TetComplex& c, const std::array<uint32_t, 4>& t, uint32_t v, const Eigen::Vector3d& x) {
  auto p = [&](int i) -> const Eigen::Vector3d& { return t[size_t(i)] == v ? x : c.points[t[size_t(i)]]; };
  return (p(1) - p(0)).cross(p(2) - p(0)).dot(p(3) - p(0));
}

bool all_positive(const TetComplex& c, std::span<const uint32_t> tets) {
  for (uint32_t t : tets)
    if (!positive_tet(c, c.tets[t])) return false;
  return true;
}

// Moves v from where it is towards `target` as far as its tetrahedra allow: the whole way, or
// most of the way to where the first would flatten (the volumes are affine along the segment),
// halved while the exact predicate refuses. Returns 1 when it arrived, 0 when it stayed.
double move_towards(TetComplex& c, const TetAdjacency& adj, uint32_t v, const Eigen::Vector3d& target) {
  const Eigen::Vector3d start = c.points[v];
  const auto tets = adj.around(v);
  c.points[v] = target;  // most moves go the whole way: try that first
  if (all_positive(c, tets)) return 1;
  c.points[v] = start;
  double s = 1;
  for (uint32_t t : tets) {
    const double v0 = signed_volume(c, c.tets[t], v, start), v1 = signed_volume(c, c.tets[t], v, target);
    if (v1 <= 0) s = std::min(s, 0.9 * v0 / (v0 - v1));
  }
  for (int halvings = 0; halvings <= kMaxHalvings; ++halvings, s *= 0.5) {
    c.points[v] = s == 1 ? target : Eigen::Vector3d(start + s * (target - start));
    if (all_positive(c, tets)) return s;
  }
  c.points[v] = start;
  return 0;
}

bool free_point(const TetComplex& c, uint32_t w) { return !c.on_interface[w] && !c.on_box[w] && !c.frozen[w]; }

// Sec. 3: "smoothing of the interior/exterior meshes improves performance". The free vertices
// within two rings of the interface are carried along with it before it moves: those of the
// first ring by kCarry[0] of the mean displacement of their interface neighbours, those of the
// second by kCarry[1] of it (the mean over their first-ring neighbours), the second ring
// first. The tetrahedra the front moves into then keep most of their height instead of
// flattening against it, and far fewer moves block (each blocked move costs a retessellation).
// The first ring moves with the front (kCarry[0] = 1), so the gap in front of it stays: at
// 2/3 it closed by a third of a step each step, and a jittered log grown 5 steps past a fresh
// volume had 169 of 4051 moves blocked, against 24 at 1 (and 2109 with no carrying).
// Each vertex goes as far as its tetrahedra stay positive (move_towards); index order within a
// ring: deterministic.
constexpr double kCarry[2] = {1.0, 0.5};

void carry_free_vertices(TetComplex& c, const TetAdjacency& adj, const std::vector<uint32_t>& movers,
                         const std::vector<Eigen::Vector3d>& target, const std::vector<uint8_t>& active) {
  const size_t n = c.points.size();
  std::vector<Eigen::Vector3d> shift(n, Eigen::Vector3d::Zero());
  std::vector<uint8_t> ring(n, 0);  // 3: a moving interface vertex, 1, 2: its free rings
  for (size_t i = 0; i < movers.size(); ++i)
    if (active[i]) {
      shift[movers[i]] = target[i] - c.points[movers[i]];
      ring[movers[i]] = 3;
    }
  // Each free vertex of ring r + 1 takes the mean of its ring-r neighbours' shifts (ring 0: the
  // moving vertices), each counted once per tetrahedron the two share, gathered in parallel
  // and summed in ascending neighbour order (the same bits whatever the thread count).
  std::vector<uint32_t> rings[2];
  for (int r = 0; r < 2; ++r) {
    const uint8_t from = r == 0 ? 3 : 1;
    mark_next_to(c, ring, uint8_t(r + 1), [&](uint32_t p) { return ring[p] == from; }, [&](uint32_t w) { return free_point(c, w); });
    rings[r] = marked(ring, uint8_t(r + 1));
    const double factor = r == 0 ? kCarry[0] : kCarry[1] / kCarry[0];
    tbb::parallel_for(tbb::blocked_range<size_t>(0, rings[r].size(), 256), [&](const tbb::blocked_range<size_t>& range) {
      std::vector<uint32_t> from_points;
      for (size_t i = range.begin(); i != range.end(); ++i) {
        const uint32_t w = rings[r][i];
        from_points.clear();
        for (uint32_t t : adj.around(w))
          for (uint32_t v : c.tets[t])
            if (ring[v] == from) from_points.push_back(v);
        std::sort(from_points.begin(), from_points.end());
        for (uint32_t v : from_points) shift[w] += factor * shift[v];
        shift[w] /= double(from_points.size());
      }
    });
  }
  for (int r = 1; r >= 0; --r)  // the second ring first, each in index order
    for (uint32_t w : rings[r])
      if (shift[w].squaredNorm() > 0) move_towards(c, adj, w, c.points[w] + shift[w]);
}

// Smoothing of the free vertices within two rings of the interface: towards the mean of
// their tetrahedra's other corners, where every tetrahedron stays positive and the worst
// quality does not drop. In index order (each vertex sees its predecessors' moves).
long smooth_near_interface(TetComplex& c, const TetAdjacency& adj) {
  const size_t n = c.points.size();
  std::vector<uint8_t> ring(n, 0);
  auto off_interface = [&](uint32_t w) { return !c.on_interface[w]; };
  mark_next_to(c, ring, 1, [&](uint32_t p) { return c.on_interface[p] != 0; }, off_interface);
  mark_next_to(c, ring, 2, [&](uint32_t p) { return ring[p] == 1; }, off_interface);
  std::vector<uint32_t> movable;
  for (uint32_t v = 0; v < n; ++v)
    if (ring[v] && !c.on_box[v] && !c.frozen[v] && !adj.around(v).empty()) movable.push_back(v);
  long smoothed = 0;
  for (uint32_t v : movable) {
    const auto around = adj.around(v);
    Eigen::Vector3d mean = Eigen::Vector3d::Zero();
    int count = 0;
    double before = 1e300;
    uint32_t worst = around.front();
    for (uint32_t t : around) {
      const double q = tet_quality(c, c.tets[t]);
      if (q < before) {
        before = q;
        worst = t;
      }
      for (uint32_t w : c.tets[t])
        if (w != v) {
          mean += c.points[w];
          ++count;
        }
    }
    const Eigen::Vector3d from = c.points[v];
    c.points[v] = from + 0.5 * (mean / count - from);
    // No tetrahedron below the worst before: the worst first (the one a rejected move most
    // often makes worse), then the rest, stopping at the first below.
    bool kept = !(tet_quality(c, c.tets[worst]) < before);
    for (size_t i = 0; kept && i < around.size(); ++i) kept = !(tet_quality(c, c.tets[around[i]]) < before);
    if (kept && all_positive(c, around))
      ++smoothed;
    else
      c.points[v] = from;
  }
  return smoothed;
}

}  // namespace

std::vector<Eigen::Vector3d> interface_normals(const TetComplex& c) {
  const TetAdjacency adj(c);
  return interface_normals(c, interface_faces(c, adj));
}

std::vector<Eigen::Vector3d> interface_normals(const TetComplex& c, const std::vector<std::array<uint32_t, 3>>& faces) {
  std::vector<Eigen::Vector3d> n(c.points.size(), Eigen::Vector3d::Zero());
  for (const auto& f : faces) {
    const Eigen::Vector3d a = (c.points[f[1]] - c.points[f[0]]).cross(c.points[f[2]] - c.points[f[0]]);  // 2 × area × normal
    for (uint32_t v : f) n[v] += a;
  }
  for (auto& v : n)
    if (v.squaredNorm() > 0) v.normalize();
  return n;
}

InterfaceStepStats advance_interface(TetComplex& c, const GrowthFunction& growth, double t0, double t1) {
  TetAdjacency adj(c);
  return advance_interface(c, adj, growth, t0, t1);
}

InterfaceStepStats advance_interface(TetComplex& c, TetAdjacency& adj, const GrowthFunction& growth, double t0, double t1) {
  return advance_interface(c, adj, interface_faces(c, adj), growth, t0, t1);
}

InterfaceStepStats advance_interface(TetComplex& c, TetAdjacency& adj, const std::vector<std::array<uint32_t, 3>>& faces,
                                     const GrowthFunction& growth, double t0, double t1, std::vector<double>* owed,
                                     VolumeUpkeep* upkeep) {
  if (owed) owed->resize(c.points.size(), 0.0);
  InterfaceStepStats st;
  const std::vector<Eigen::Vector3d> normals = interface_normals(c, faces);
  std::vector<uint32_t> movers;
  for (uint32_t v = 0; v < c.points.size(); ++v)
    if (c.on_interface[v] && !c.frozen[v] && normals[v].squaredNorm() > 0) movers.push_back(v);
  // Eq. (1) integrated over the step: the thickening along the normal (a pure function of the
  // vertex, evaluated in parallel).
  std::vector<Eigen::Vector3d> target(movers.size());
  std::vector<uint8_t> active(movers.size(), 0);
  std::vector<double> thickening(movers.size(), 0.0), wanted(movers.size(), 0.0);  // this step's; with what is owed
  const bool turned = growth.has_directions() || !c.direction.empty();
  // Sec. 4.6: with growth turned off the normal, vertices slide, and their UVs move through
  // the texture Jacobian taken before the motion.
  const std::vector<TextureGradient> gradients =
      turned && !c.uv.empty() ? texture_gradients(c.points, c.uv, faces) : std::vector<TextureGradient>{};
  tbb::parallel_for(size_t(0), movers.size(), [&](size_t i) {
    const uint32_t v = movers[i];
    // Sec. 4.4: a painted speed map scales the growth where it is painted.
    const double d = growth.thickening(t0, t1, c.points[v].cast<float>(), normals[v].cast<float>()) *
                     (c.speed.empty() ? 1.0 : double(c.speed[v]));
    // Sec. 4.4: a stroke's direction, then a painted one, turn the growth from the normal.
    Eigen::Vector3d dir = normals[v];
    if (turned) {
      const Vec3f n = normals[v].cast<float>();
      Vec3f turn = growth.growth_direction(c.points[v].cast<float>(), n);
      if (!c.direction.empty()) turn = GrowthFunction::turned_towards(turn, n, c.direction[v]);
      dir = turn.cast<double>();
    }
    active[i] = d != 0 && std::isfinite(d);
    // What an earlier blocked move left owing, repaid at most at this step's own rate.
    double catch_up = 0;
    if (owed && active[i] && (*owed)[v] * d > 0) catch_up = std::copysign(std::min(std::abs((*owed)[v]), std::abs(d)), d);
    thickening[i] = d;
    wanted[i] = d + catch_up;
    target[i] = c.points[v] + wanted[i] * dir;
  });
  const std::vector<Eigen::Vector3d> start = [&] {
    std::vector<Eigen::Vector3d> s(movers.size());
    for (size_t i = 0; i < movers.size(); ++i) s[i] = c.points[movers[i]];
    return s;
  }();
  Stopwatch clock;
  // How many steps this carry covers: as many of this step's thickening as fit in the reach
  // (the catch-up of owed moves left out: it is at most as much again, on few vertices).
  int ahead = 1;
  if (upkeep && upkeep->steps_left > 0) {
    --upkeep->steps_left;
    st.upkeep = false;
  } else if (upkeep) {
    double largest = 0;
    for (size_t i = 0; i < movers.size(); ++i)
      if (active[i]) largest = std::max(largest, std::abs(thickening[i]));
    if (largest > 0 && upkeep->reach > largest)
      ahead = int(std::min<double>(VolumeUpkeep::kMaxSteps, std::floor(upkeep->reach / largest)));
    upkeep->steps_left = ahead - 1;
  }
  if (st.upkeep && ahead == 1) {
    carry_free_vertices(c, adj, movers, target, active);
  } else if (st.upkeep) {
    std::vector<Eigen::Vector3d> carried(movers.size());
    for (size_t i = 0; i < movers.size(); ++i) carried[i] = c.points[movers[i]] + ahead * (target[i] - c.points[movers[i]]);
    carry_free_vertices(c, adj, movers, carried, active);
  }
  st.carry_s = clock.lap();
  // Vertices move one at a time in index order, each checked against its own tetrahedra:
  // deterministic, and a vertex never validates against a neighbour's half-made move. Those
  // that stopped short get the tetrahedra in their way retessellated and try again.
  FlipStats fs;
  std::vector<size_t> pending;
  for (size_t i = 0; i < movers.size(); ++i)
    if (active[i]) pending.push_back(i);
  for (int round = 0; round < kRounds && !pending.empty(); ++round) {
    std::vector<size_t> blocked;
    for (size_t i : pending)
      if (move_towards(c, adj, movers[i], target[i]) < 1) blocked.push_back(i);
    // Index order moves a vertex before its neighbours with larger indices: an outside
    // tetrahedron on a moved neighbour and one still to move tilts and can flatten, although
    // all three moved together would keep it (on a sphere grown with the upkeep interval,
    // nearly all of one step's blocked moves). So the blocked ones try once more, after every
    // vertex has moved, before anything is retessellated. (More passes freed no more.)
    if (round == 0) {
      std::vector<size_t> again;
      for (size_t i : blocked)
        if (move_towards(c, adj, movers[i], target[i]) < 1) again.push_back(i);
      blocked = std::move(again);
    }
    st.moves_s += clock.lap();
    if (round + 1 == kRounds) break;
    std::vector<size_t> retry;
    for (size_t i : blocked)
      if (unblock_vertex(c, adj, movers[i], target[i], fs)) retry.push_back(i);
    pending = std::move(retry);
    st.unblock_s += clock.lap();
  }
  for (size_t i = 0; i < movers.size(); ++i) {
    if (!active[i]) continue;
    const uint32_t v = movers[i];
    if (c.points[v] == target[i])
      ++st.moved;
    else if (c.points[v] == start[i])
      ++st.clamped;
    else
      ++st.shortened;
  }
  if (owed)
    for (size_t i = 0; i < movers.size(); ++i) {
      const uint32_t v = movers[i];
      if (!active[i]) continue;
      // The share of the segment start → target the vertex went (the moves go straight along it).
      const double full = (target[i] - start[i]).norm();
      const double went = full > 0 ? (c.points[v] - start[i]).norm() / full : 1.0;
      const double left = (*owed)[v] + thickening[i] - went * wanted[i];
      // Never owed against the growth, and at most ten steps' worth.
      (*owed)[v] = left * thickening[i] > 0 ? std::copysign(std::min(std::abs(left), 10 * std::abs(thickening[i])), left) : 0.0;
    }
  if (!gradients.empty())
    for (size_t i = 0; i < movers.size(); ++i) {
      const uint32_t v = movers[i];
      c.uv[v] = transported_uv(c.uv[v], gradients[v], c.points[v] - start[i], normals[v]);
    }
  st.flips = fs.flips23 + fs.flips32 + fs.edge_removals;
  st.relocated = fs.relocated;
  st.removed = fs.removed;

  clock.lap();
  if (st.upkeep) st.smoothed = smooth_near_interface(c, adj);
  st.smooth_s = clock.lap();
  return st;
}

}  // namespace phellem::bark
