#include "bark/stress/stress_relaxation.h"

#include <tbb/parallel_for.h>

namespace phellem::bark {

std::vector<double> vertex_stiffness(const StressMesh& m) {
  const SurfaceMesh& g = m.mesh();
  std::vector<double> k(g.number_of_vertices(), 0.0);
  tbb::parallel_for(size_t(0), size_t(g.number_of_vertices()), [&](size_t i) {
    const VertexId v(static_cast<SurfaceMesh::size_type>(i));
    double sum = 0;
    for (HalfedgeId h : CGAL::halfedges_around_target(g.halfedge(v), g)) {
      if (g.is_border(h)) continue;
      const FaceId f = g.face(h);
      const auto cs = m.corners(f);
      const int c = cs[0] == h ? 0 : cs[1] == h ? 1 : 2;  // v's row of β
      sum += m.face(f).area * m.face(f).beta.row(c).leftCols<2>().squaredNorm();
    }
    k[i] = sum;
  });
  return k;
}

void relax(StressMesh& m, const ForceField& forces, double dt, std::vector<Eigen::Vector3d>* displacement,
           const std::vector<double>* stiffness) {
  const SurfaceMesh& g = m.mesh();
  std::vector<double> own;
  if (!stiffness) own = vertex_stiffness(m);
  const std::vector<double>& k = stiffness ? *stiffness : own;
  std::vector<Eigen::Vector3d> dp(g.number_of_vertices());
  for (size_t i = 0; i < dp.size(); ++i) dp[i] = k[i] > 0 ? Eigen::Vector3d(dt / k[i] * forces.total[i]) : Eigen::Vector3d::Zero();  // eq. 7
  tbb::parallel_for(size_t(0), size_t(g.number_of_faces()), [&](size_t k) {
    const FaceId f(static_cast<SurfaceMesh::size_type>(k));
    FaceState& s = m.face(f);
    const auto vs = m.vertices(f);
    // Σ_m p_[m] β_m is the frame E (the vertices do not move); Σ_n Δp_n β_n its change.
    Eigen::Matrix<double, 3, 2> dPB = Eigen::Matrix<double, 3, 2>::Zero();
    for (int j = 0; j < 3; ++j) dPB += dp[vs[size_t(j)].idx()] * s.beta.row(j).head<2>();
    const Eigen::Matrix2d G = dPB.transpose() * s.frame;
    s.sigma += 0.5 * (G + G.transpose());  // eqs. 8–9
  });
  if (displacement) {
    displacement->resize(g.number_of_vertices(), Eigen::Vector3d::Zero());
    for (size_t i = 0; i < dp.size(); ++i) (*displacement)[i] += dp[i];
  }
}

double stress_energy(const StressMesh& m) {
  double e = 0;
  for (FaceId f : m.mesh().faces()) e += m.face(f).area * m.face(f).sigma.squaredNorm();
  return e;
}

}  // namespace phellem::bark
