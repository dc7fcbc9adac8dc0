#include "bark/stress/separation_tensor.h"

namespace phellem::bark {

namespace {

// The six distinct entries of a symmetric 3×3 tensor, accumulated in scalars: as Eigen
// matrices returned by value, the sum stored and reloaded its halves (a store-forwarding
// stall per term). Each entry is m(p) − m(q), m(a) = a aᵀ / |a| (0 for a = 0).
struct Symmetric3 {
  double e[6] = {0, 0, 0, 0, 0, 0};  // xx, xy, xz, yy, yz, zz
  static constexpr int row[6] = {0, 0, 0, 1, 1, 2}, col[6] = {0, 1, 2, 1, 2, 2};

  void add_difference(const Eigen::Vector3d& p, const Eigen::Vector3d& q) {  // += m(p) − m(q)
    const double lp = p.norm(), lq = q.norm();
    for (int k = 0; k < 6; ++k) {
      const double mp = lp > 0 ? p[row[k]] * p[col[k]] / lp : 0.0;
      const double mq = lq > 0 ? q[row[k]] * q[col[k]] / lq : 0.0;
      e[k] += mp - mq;
    }
  }
  Eigen::Matrix3d matrix(double scale) const {
    Eigen::Matrix3d m;
    for (int k = 0; k < 6; ++k) m(row[k], col[k]) = m(col[k], row[k]) = scale * e[k];
    return m;
  }
};

}  // namespace

Eigen::Matrix3d separation_tensor(const StressTopology& t, const ForceField& forces, uint32_t v) {
  Eigen::Vector3d fplus = Eigen::Vector3d::Zero(), fminus = Eigen::Vector3d::Zero();
  Symmetric3 s;
  for (uint32_t k = t.vertex_begin[v]; k < t.vertex_begin[v + 1]; ++k) {
    const uint32_t slot = t.vertex_slots[k];
    const Eigen::Vector3d& tp = forces.tensile[slot];
    const Eigen::Vector3d& tm = forces.compressive[slot];
    fplus += tp;
    fminus += tm;
    s.add_difference(tp, tm);
  }
  s.add_difference(fminus, fplus);
  return s.matrix(0.5);  // eq. 4
}

}  // namespace phellem::bark
