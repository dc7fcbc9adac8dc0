#include "bark/growth/growth_rings.h"

#include <map>

namespace phellem::bark {

GrowthRing record_ring(const TetComplex& c, int step) { return record_ring(c, c.interface_faces(), step); }

GrowthRing record_ring(const TetComplex& c, const std::vector<std::array<uint32_t, 3>>& faces, int step) {
  GrowthRing r;
  r.step = step;
  std::map<uint32_t, uint32_t> index;
  for (const auto& f : faces) {
    std::array<uint32_t, 3> g{};
    for (int k = 0; k < 3; ++k) {
      const auto [it, added] = index.emplace(f[size_t(k)], uint32_t(r.points.size()));
      if (added) r.points.push_back(c.points[f[size_t(k)]]);
      g[size_t(k)] = it->second;
    }
    r.faces.push_back(g);
  }
  return r;
}

std::vector<std::array<Eigen::Vector3d, 2>> slice_ring(const GrowthRing& ring, const Eigen::Vector3d& origin,
                                                         const Eigen::Vector3d& normal) {
  std::vector<std::array<Eigen::Vector3d, 2>> out;
  for (const auto& f : ring.faces) {
    double d[3];
    for (int k = 0; k < 3; ++k) d[k] = normal.dot(ring.points[f[size_t(k)]] - origin);
    std::vector<Eigen::Vector3d> hits;
    for (int k = 0; k < 3; ++k) {
      const int j = (k + 1) % 3;
      const Eigen::Vector3d &a = ring.points[f[size_t(k)]], &b = ring.points[f[size_t(j)]];
      if ((d[k] < 0 && d[j] >= 0) || (d[k] >= 0 && d[j] < 0)) hits.push_back(a + (b - a) * (d[k] / (d[k] - d[j])));
    }
    if (hits.size() == 2) out.push_back({hits[0], hits[1]});
  }
  return out;
}

}  // namespace phellem::bark
