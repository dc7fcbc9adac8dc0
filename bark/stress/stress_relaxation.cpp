#include "bark/stress/stress_relaxation.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

namespace phellem::bark {

std::vector<double> vertex_stiffness(const StressMesh& m, const StressTopology& t) {
  std::vector<double> k(t.vertices(), 0.0);
  tbb::parallel_for(tbb::blocked_range<size_t>(0, t.vertices(), 512), [&](const tbb::blocked_range<size_t>& r) {
    for (size_t v = r.begin(); v != r.end(); ++v) {
      double sum = 0;
      for (uint32_t i = t.vertex_begin[v]; i < t.vertex_begin[v + 1]; ++i) {
        const uint32_t slot = t.vertex_slots[i];
        const FaceState& s = m.face(FaceId(slot / 3));
        sum += s.area * s.beta.row(int(slot % 3)).head<2>().squaredNorm();
      }
      k[v] = sum;
    }
  });
  return k;
}

void relax(StressMesh& m, const StressTopology& t, const ForceField& forces, double dt, std::vector<Eigen::Vector3d>* displacement,
           const std::vector<double>* stiffness) {
  std::vector<double> own;
  if (!stiffness) own = vertex_stiffness(m, t);
  const std::vector<double>& k = stiffness ? *stiffness : own;
  std::vector<Eigen::Vector3d> dp(t.vertices());
  for (size_t i = 0; i < dp.size(); ++i) dp[i] = k[i] > 0 ? Eigen::Vector3d(dt / k[i] * forces.total[i]) : Eigen::Vector3d::Zero();  // eq. 7
  tbb::parallel_for(tbb::blocked_range<size_t>(0, t.faces(), 256), [&](const tbb::blocked_range<size_t>& r) {
    for (size_t f = r.begin(); f != r.end(); ++f) {
      FaceState& s = m.face(FaceId(static_cast<SurfaceMesh::size_type>(f)));
      // Σ_m p_[m] β_m is the frame E (the vertices do not move); Σ_n Δp_n β_n its change.
      Eigen::Matrix<double, 3, 2> dPB = Eigen::Matrix<double, 3, 2>::Zero();
      for (int j = 0; j < 3; ++j) dPB += dp[t.face_vertices[f][size_t(j)]] * s.beta.row(j).head<2>();
      const Eigen::Matrix2d G = dPB.transpose() * s.frame;
      s.sigma += 0.5 * (G + G.transpose());  // eqs. 8–9
    }
  });
  if (displacement) {
    displacement->resize(t.vertices(), Eigen::Vector3d::Zero());
    for (size_t i = 0; i < dp.size(); ++i) (*displacement)[i] += dp[i];
  }
}

double stress_energy(const StressMesh& m) {
  double e = 0;
  for (FaceId f : m.mesh().faces()) e += m.face(f).area * m.face(f).sigma.squaredNorm();
  return e;
}

}  // namespace phellem::bark
