#include "bark/growth/interface_curvature.h"

#include <algorithm>

#include "bark/growth/interface_motion.h"
#include "bark/growth/tet_adjacency.h"

namespace phellem::bark {

long smooth_interface_curvature(TetComplex& c, double rate, bool only_outwards) {
  const TetAdjacency adj(c);
  return smooth_interface_curvature(c, adj, c.interface_faces(), rate, only_outwards);
}

long smooth_interface_curvature(TetComplex& c, const TetAdjacency& adj, const std::vector<std::array<uint32_t, 3>>& faces,
                                double rate, bool only_outwards, std::vector<double>* owed) {
  const std::vector<Eigen::Vector3d> normals = interface_normals(c, faces);
  std::vector<Eigen::Vector3d> sum(c.points.size(), Eigen::Vector3d::Zero());
  std::vector<int> count(c.points.size(), 0);
  for (const auto& f : faces)
    for (int k = 0; k < 3; ++k) {  // each edge of a closed surface is seen twice, once per side
      sum[f[size_t(k)]] += c.points[f[size_t(k + 1) % 3]];
      ++count[f[size_t(k)]];
    }
  std::vector<Eigen::Vector3d> target(c.points.size());
  for (size_t v = 0; v < c.points.size(); ++v)
    if (count[v] > 0) {
      const Eigen::Vector3d lap = sum[v] / count[v] - c.points[v];
      const double along = normals[v].dot(lap);
      target[v] = c.points[v] + (only_outwards && along < 0 ? 0.0 : rate * along) * normals[v];
    }
  long moved = 0;
  for (uint32_t v = 0; v < c.points.size(); ++v) {
    if (count[v] == 0 || c.frozen[v]) continue;
    const Eigen::Vector3d start = c.points[v];
    Eigen::Vector3d delta = target[v] - start;
    if (delta.isZero(0)) continue;  // only outwards, and the surface is convex here: no move, nothing to test
    for (int h = 0; h < 4; ++h, delta *= 0.5) {
      c.points[v] = start + delta;
      bool ok = true;
      for (uint32_t t : adj.around(v)) ok = ok && positive_tet(c, c.tets[t]);  // any order: all must hold
      if (ok) break;
      c.points[v] = start;
    }
    moved += c.points[v] != start;
    if (owed && v < owed->size() && (*owed)[v] != 0) {
      double& o = (*owed)[v];
      const double lift = (c.points[v] - start).norm();
      o = o > 0 ? std::max(0.0, o - lift) : std::min(0.0, o + lift);
    }
  }
  return moved;
}

}  // namespace phellem::bark
