#include "bark/stress/separation_tensor.h"

namespace phellem::bark {

Eigen::Matrix3d outer_m(const Eigen::Vector3d& a) {
  const double len = a.norm();
  return len > 0 ? Eigen::Matrix3d(a * a.transpose() / len) : Eigen::Matrix3d::Zero();
}

Eigen::Matrix3d separation_tensor(const StressMesh& m, const ForceField& forces, VertexId v) {
  const SurfaceMesh& g = m.mesh();
  Eigen::Vector3d fplus = Eigen::Vector3d::Zero(), fminus = Eigen::Vector3d::Zero();
  Eigen::Matrix3d s = Eigen::Matrix3d::Zero();
  for (HalfedgeId h : CGAL::halfedges_around_target(g.halfedge(v), g)) {
    if (g.is_border(h)) continue;
    const Eigen::Vector3d& tp = forces.tensile[h.idx()];
    const Eigen::Vector3d& tm = forces.compressive[h.idx()];
    fplus += tp;
    fminus += tm;
    s += outer_m(tp) - outer_m(tm);
  }
  s += outer_m(fminus) - outer_m(fplus);
  return 0.5 * s;  // eq. 4
}

}  // namespace phellem::bark
