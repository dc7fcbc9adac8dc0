#include "bark/stress/stress_forces.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <cmath>

namespace phellem::bark {

std::pair<Eigen::Matrix2d, Eigen::Matrix2d> split_stress(const Eigen::Matrix2d& sigma) {
  // Closed-form eigen-decomposition of the symmetric 2×2 tensor [[a, b], [b, c]].
  const double a = sigma(0, 0), b = 0.5 * (sigma(0, 1) + sigma(1, 0)), c = sigma(1, 1);
  const double mean = 0.5 * (a + c), r = std::hypot(0.5 * (a - c), b);
  const double hi = mean + r, lo = mean - r;
  if (lo >= 0) return {sigma, Eigen::Matrix2d::Zero()};  // eq. 2: all tensile
  if (hi <= 0) return {Eigen::Matrix2d::Zero(), sigma};  // eq. 3: all compressive
  // One of each: σ⁺ = v_hi n n^T (eq. 2), σ⁻ = σ − σ⁺ = v_lo m m^T (eq. 3). The eigenvector of
  // `hi` from whichever row of (σ − hi·I) is better conditioned.
  const Eigen::Vector2d e1(b, hi - a), e2(hi - c, b);
  const Eigen::Vector2d n = (e1.squaredNorm() >= e2.squaredNorm() ? e1 : e2).normalized();
  const Eigen::Matrix2d plus = hi * n * n.transpose();
  return {plus, sigma - plus};
}

std::array<Eigen::Vector3d, 3> nodal_forces(const StressMesh& m, FaceId f, const Eigen::Matrix2d& sigma) {
  // Eq. 1: f_i = −A Σ_j p_j (β_i σ β_jᵀ) = −A (Σ_j p_j β_j) σ β_iᵀ, with β_i the first two
  // entries of β's row i; Σ_j p_j β_j is the embedding of the local frame, E = [u v], as the
  // vertices never move.
  const FaceState& s = m.face(f);
  const Eigen::Matrix<double, 3, 2> Es = s.frame * sigma;
  std::array<Eigen::Vector3d, 3> out;
  for (int i = 0; i < 3; ++i) out[size_t(i)] = -s.area * (Es * s.beta.row(i).head<2>().transpose());
  return out;
}

void compute_forces(const StressMesh& m, const StressTopology& t, ForceField& out, bool split) {
  const size_t nf = t.faces(), nv = t.vertices();
  out.tensile.resize(3 * nf);
  out.compressive.resize(split ? 3 * nf : 0);
  out.total.resize(nv);
  tbb::parallel_for(tbb::blocked_range<size_t>(0, nf, 256), [&](const tbb::blocked_range<size_t>& r) {
    for (size_t k = r.begin(); k != r.end(); ++k) {
      const FaceId f(static_cast<SurfaceMesh::size_type>(k));
      if (split) {
        const auto [plus, minus] = split_stress(m.face(f).sigma);
        // (A face in pure tension or pure compression is common: skip the zero half.)
        const std::array<Eigen::Vector3d, 3> zero{Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero()};
        const auto fp = plus.isZero(0) ? zero : nodal_forces(m, f, plus);
        const auto fm = minus.isZero(0) ? zero : nodal_forces(m, f, minus);
        for (size_t i = 0; i < 3; ++i) {
          out.tensile[3 * k + i] = fp[i];
          out.compressive[3 * k + i] = fm[i];
        }
      } else {
        const auto ft = nodal_forces(m, f, m.face(f).sigma);
        for (size_t i = 0; i < 3; ++i) out.tensile[3 * k + i] = ft[i];
      }
    }
  });
  tbb::parallel_for(tbb::blocked_range<size_t>(0, nv, 512), [&](const tbb::blocked_range<size_t>& r) {
    for (size_t v = r.begin(); v != r.end(); ++v) {
      Eigen::Vector3d sum = Eigen::Vector3d::Zero();
      for (uint32_t k = t.vertex_begin[v]; k < t.vertex_begin[v + 1]; ++k) {
        const uint32_t slot = t.vertex_slots[k];
        sum += split ? Eigen::Vector3d(out.tensile[slot] + out.compressive[slot]) : out.tensile[slot];
      }
      out.total[v] = sum;
    }
  });
}

}  // namespace phellem::bark
