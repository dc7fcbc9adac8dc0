#include "bark/growth/free_vertex_removal.h"

#include <algorithm>

namespace phellem::bark {

namespace {

constexpr double kGain = 1e-9;  // as for the flips: the worst quality must rise by more than this

}  // namespace

bool remove_free_vertex(TetComplex& c, TetAdjacency& adj, uint32_t w, const Probe& probe, FlipStats& stats) {
  if (w == probe.v || c.on_interface[w] || c.on_box[w] || c.frozen[w] || adj.unused(w)) return false;
  thread_local std::vector<uint32_t> star, neighbours, gone;
  thread_local std::vector<std::array<uint32_t, 4>> made;
  star.assign(adj.around(w).begin(), adj.around(w).end());
  const uint8_t label = c.label[star.front()];
  if (label == TetComplex::kObstacle) return false;
  double before = 1e300;
  neighbours.clear();
  for (uint32_t t : star) {
    if (c.label[t] != label) return false;
    before = std::min(before, probe_quality(c, c.tets[t], probe));
    for (uint32_t x : c.tets[t])
      if (x != w) neighbours.push_back(x);
  }
  std::sort(neighbours.begin(), neighbours.end());
  neighbours.erase(std::unique(neighbours.begin(), neighbours.end()), neighbours.end());
  double best = before + kGain;
  uint32_t best_u = w;
  for (uint32_t u : neighbours) {
    double q = 1e300;
    bool ok = true;
    made.clear();
    for (uint32_t t : star) {
      std::array<uint32_t, 4> T = c.tets[t];
      if (std::find(T.begin(), T.end(), u) != T.end()) continue;  // around the edge w–u: goes
      std::replace(T.begin(), T.end(), w, u);
      int on = 0;
      for (uint32_t x : T) on += c.on_interface[x];
      if (on == 4) ok = false;
      // No new edge between two interface points through the outside (see flip_23).
      if (label == TetComplex::kOutside && c.on_interface[u])
        for (uint32_t x : T)
          if (x != u && c.on_interface[x] && !adj.has_edge(c, u, x)) ok = false;
      if (!ok) break;
      q = std::min(q, probe_quality(c, T, probe));
      if (!(q > best)) break;  // this neighbour cannot win
      made.push_back(T);
    }
    if (!ok || !(q > best)) continue;
    for (const auto& T : made) ok = ok && positive_tet(c, T);
    if (!ok) continue;
    best = q;
    best_u = u;
  }
  if (best_u == w) return false;
  gone.clear();
  for (uint32_t t : star) {
    std::array<uint32_t, 4> T = c.tets[t];
    if (std::find(T.begin(), T.end(), best_u) != T.end()) {
      gone.push_back(t);
      continue;
    }
    std::replace(T.begin(), T.end(), w, best_u);
    adj.set_tet(c, t, T);
  }
  std::sort(gone.begin(), gone.end());
  for (auto it = gone.rbegin(); it != gone.rend(); ++it) adj.erase_tet(c, *it);  // last first: indices stay valid
  ++stats.removed;
  return true;
}

}  // namespace phellem::bark
