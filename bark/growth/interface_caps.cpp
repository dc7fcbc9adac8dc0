#include "bark/growth/interface_caps.h"

#include <algorithm>
#include <cmath>

#include "bark/growth/interface_coarsening.h"

namespace phellem::bark {

namespace {

// Whether some angle of the triangle may exceed `cos_bound`'s angle: a corner's cosine
// below it plus a margin far above rounding (so largest_angle decides every triangle
// near the bound).
bool may_have_angle_above(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c, double cos_bound) {
  const std::array<Eigen::Vector3d, 3> p{a, b, c};
  for (int k = 0; k < 3; ++k) {
    const Eigen::Vector3d u = p[size_t(k + 1) % 3] - p[size_t(k)], v = p[size_t(k + 2) % 3] - p[size_t(k)];
    const double uv = u.norm() * v.norm();
    if (!(u.dot(v) > (cos_bound + 1e-6) * uv)) return true;
  }
  return false;
}

// The largest angle of a triangle and its corner.
std::pair<double, int> largest_angle(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c) {
  const std::array<Eigen::Vector3d, 3> p{a, b, c};
  double best = -1;
  int at = 0;
  for (int k = 0; k < 3; ++k) {
    const Eigen::Vector3d u = p[size_t(k + 1) % 3] - p[size_t(k)], v = p[size_t(k + 2) % 3] - p[size_t(k)];
    const double ang = std::atan2(u.cross(v).norm(), u.dot(v));
    if (ang > best) {
      best = ang;
      at = k;
    }
  }
  return {best, at};
}

}  // namespace

CapStats remove_interface_caps(TetComplex& c, TetAdjacency& adj, double max_angle) {
  CapStats st;
  std::vector<uint32_t> shared;
  const double cos_max = std::cos(max_angle);
  // Each pass works on the faces as they were; a removed cap changes its neighbours, so the
  // faces are found again until no cap is left that can be removed.
  for (int pass = 0; pass < 4; ++pass) {
    long removed = 0;
    bool changed = false;  // a split, kept or collapsed
    std::vector<std::array<uint32_t, 3>> faces = interface_faces(c, adj);
    std::sort(faces.begin(), faces.end());
    std::vector<uint8_t> touched(c.points.size(), 0);
    for (const auto& f : faces) {
      if (touched[f[0]] || touched[f[1]] || touched[f[2]]) continue;  // changed in this pass
      if (!may_have_angle_above(c.points[f[0]], c.points[f[1]], c.points[f[2]], cos_max)) continue;
      const auto [angle, k] = largest_angle(c.points[f[0]], c.points[f[1]], c.points[f[2]]);
      if (!(angle > max_angle)) continue;
      if (pass == 0) ++st.found;
      const uint32_t p = f[size_t(k)], a = f[size_t(k + 1) % 3], b = f[size_t(k + 2) % 3];
      if (c.on_box[a] || c.on_box[b]) continue;
      const Eigen::Vector3d ab = c.points[b] - c.points[a];
      const double t = std::clamp((c.points[p] - c.points[a]).dot(ab) / ab.squaredNorm(), 0.05, 0.95);
      const Eigen::Vector3d x = (1 - t) * c.points[a] + t * c.points[b];
      adj.edge_tets(c, a, b, shared);
      if (!split_keeps_positive(c, a, b, x, shared)) continue;
      const uint32_t m = c.add_point_between(a, b, t);
      if (!c.on_crack.empty()) c.on_crack[m] = 0;  // may merge into p even when a–b is a crack edge
      adj.split_edge_tets(c, a, b, m, shared);
      changed = true;
      touched.resize(c.points.size(), 0);
      touched[a] = touched[b] = touched[p] = touched[m] = 1;
      if (collapse_interface_edge(c, adj, m, p)) {
        ++removed;
        ++st.removed;
        if (c.on_interface[m])
          st.merged.emplace_back(p, m);
        else
          st.merged.emplace_back(m, p);
      }
    }
    if (!changed) {
      st.faces = std::move(faces);
      break;
    }
    if (removed == 0) break;
  }
  if (st.faces.empty()) {
    st.faces = interface_faces(c, adj);
    std::sort(st.faces.begin(), st.faces.end());
  }
  return st;
}

}  // namespace phellem::bark
