#include "bark/stress/separation_tensor.h"

namespace phellem::bark {

Eigen::Matrix3d outer_m(const Eigen::Vector3d& a) {
  const double len = a.norm();
  return len > 0 ? Eigen::Matrix3d(a * a.transpose() / len) : Eigen::Matrix3d::Zero();
}

Eigen::Matrix3d separation_tensor(const StressTopology& t, const ForceField& forces, uint32_t v) {
  Eigen::Vector3d fplus = Eigen::Vector3d::Zero(), fminus = Eigen::Vector3d::Zero();
  Eigen::Matrix3d s = Eigen::Matrix3d::Zero();
  for (uint32_t k = t.vertex_begin[v]; k < t.vertex_begin[v + 1]; ++k) {
    const uint32_t slot = t.vertex_slots[k];
    const Eigen::Vector3d& tp = forces.tensile[slot];
    const Eigen::Vector3d& tm = forces.compressive[slot];
    fplus += tp;
    fminus += tm;
    s += outer_m(tp) - outer_m(tm);
  }
  s += outer_m(fminus) - outer_m(fplus);
  return 0.5 * s;  // eq. 4
}

}  // namespace phellem::bark
