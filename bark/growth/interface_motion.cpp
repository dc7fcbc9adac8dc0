#include "bark/growth/interface_motion.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <algorithm>

namespace phellem::bark {

namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
constexpr int kMaxHalvings = 6;

bool positive(const TetComplex& c, const std::array<uint32_t, 4>& t) {
  auto p = [&](uint32_t i) { return K::Point_3(c.points[i].x(), c.points[i].y(), c.points[i].z()); };
  return CGAL::orientation(p(t[0]), p(t[1]), p(t[2]), p(t[3])) == CGAL::POSITIVE;
}

// The tetrahedra around each point.
std::vector<std::vector<uint32_t>> incident_tets(const TetComplex& c) {
  std::vector<std::vector<uint32_t>> around(c.points.size());
  for (uint32_t t = 0; t < c.tets.size(); ++t)
    for (uint32_t v : c.tets[t]) around[v].push_back(t);
  return around;
}

bool all_positive(const TetComplex& c, const std::vector<uint32_t>& tets) {
  for (uint32_t t : tets)
    if (!positive(c, c.tets[t])) return false;
  return true;
}

}  // namespace

std::vector<Eigen::Vector3d> interface_normals(const TetComplex& c) { return interface_normals(c, c.interface_faces()); }

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
  InterfaceStepStats st;
  const std::vector<Eigen::Vector3d> normals = interface_normals(c);
  const auto around = incident_tets(c);
  // Eq. (1) integrated over the step: the thickening along the normal. Vertices move one at a
  // time in index order, each checked against its own tetrahedra: deterministic, and a
  // vertex never validates against a neighbour's half-made move.
  for (uint32_t v = 0; v < c.points.size(); ++v) {
    if (!c.on_interface[v] || c.frozen[v] || normals[v].squaredNorm() == 0) continue;
    const Eigen::Vector3d start = c.points[v];
    const double d = growth.thickening(t0, t1, start.cast<float>(), normals[v].cast<float>());
    if (!(d != 0)) continue;
    double step = d;
    int halvings = 0;
    for (;; ++halvings) {
      c.points[v] = start + step * normals[v];
      if (all_positive(c, around[v])) break;
      if (halvings == kMaxHalvings) {
        c.points[v] = start;
        break;
      }
      step *= 0.5;
    }
    if (c.points[v] == start)
      ++st.clamped;
    else if (halvings > 0)
      ++st.shortened;
    else
      ++st.moved;
  }
  // Smoothing of the free vertices: towards the mean of their tetrahedra's other corners.
  for (uint32_t v = 0; v < c.points.size(); ++v) {
    if (c.on_interface[v] || c.on_box[v] || c.frozen[v] || around[v].empty()) continue;
    Eigen::Vector3d mean = Eigen::Vector3d::Zero();
    int n = 0;
    for (uint32_t t : around[v])
      for (uint32_t w : c.tets[t])
        if (w != v) {
          mean += c.points[w];
          ++n;
        }
    const Eigen::Vector3d start = c.points[v];
    c.points[v] = start + 0.5 * (mean / n - start);
    if (all_positive(c, around[v]))
      ++st.smoothed;
    else
      c.points[v] = start;
  }
  return st;
}

}  // namespace phellem::bark
