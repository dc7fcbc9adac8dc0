#include "bark/stress/stress_relaxation.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <array>

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

void relax(StressMesh& m, const StressTopology& t, const ForceField& forces, double dt,
           std::vector<Eigen::Vector3d>* displacement, const std::vector<double>* stiffness) {
  std::vector<double> own;
  if (!stiffness) own = vertex_stiffness(m, t);
  const std::vector<double>& k = stiffness ? *stiffness : own;
  std::vector<Eigen::Vector3d> dp(t.vertices());
  for (size_t i = 0; i < dp.size(); ++i)
    dp[i] = k[i] > 0 ? Eigen::Vector3d(dt / k[i] * forces.total[i]) : Eigen::Vector3d::Zero();  // eq. 7
  tbb::parallel_for(tbb::blocked_range<size_t>(0, t.faces(), 256), [&](const tbb::blocked_range<size_t>& r) {
    for (size_t f = r.begin(); f != r.end(); ++f) {
      FaceState& s = m.face(FaceId(static_cast<SurfaceMesh::size_type>(f)));
      // Σ_m p_[m] β_m is the frame E (the vertices do not move); D = Σ_n Δp_n β_n its change.
      // Written out in scalars: Eigen's 3×2 temporaries were stored and reloaded in halves
      // (a store-forwarding stall per term; this loop was the simulation's hottest).
      const std::array<uint32_t, 3>& fv = t.face_vertices[f];
      const Eigen::Vector3d& d0 = dp[fv[0]];
      const Eigen::Vector3d& d1 = dp[fv[1]];
      const Eigen::Vector3d& d2 = dp[fv[2]];
      double D[3][2];
      for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 2; ++c) D[r][c] = d0[r] * s.beta(0, c) + d1[r] * s.beta(1, c) + d2[r] * s.beta(2, c);
      double G[2][2];  // Dᵀ E
      for (int a = 0; a < 2; ++a)
        for (int b = 0; b < 2; ++b) G[a][b] = D[0][a] * s.frame(0, b) + D[1][a] * s.frame(1, b) + D[2][a] * s.frame(2, b);
      for (int a = 0; a < 2; ++a)
        for (int b = 0; b < 2; ++b) s.sigma(a, b) += 0.5 * (G[a][b] + G[b][a]);  // eqs. 8–9
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
