#include "bark/stress/stress_forces.h"

#include <tbb/parallel_for.h>

#include <Eigen/Eigenvalues>

namespace phellem::bark {

std::pair<Eigen::Matrix2d, Eigen::Matrix2d> split_stress(const Eigen::Matrix2d& sigma) {
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> es(sigma);
  Eigen::Matrix2d plus = Eigen::Matrix2d::Zero(), minus = Eigen::Matrix2d::Zero();
  for (int i = 0; i < 2; ++i) {
    const double v = es.eigenvalues()[i];
    const Eigen::Vector2d n = es.eigenvectors().col(i);
    (v > 0 ? plus : minus) += v * n * n.transpose();  // eq. 2 / eq. 3
  }
  return {plus, minus};
}

std::array<Eigen::Vector3d, 3> nodal_forces(const StressMesh& m, FaceId f, const Eigen::Matrix2d& sigma) {
  const FaceState& s = m.face(f);
  const auto vs = m.vertices(f);
  // Σ_j p_j β_jl (3×2): the embedding of the local frame, E = P·B.
  const Eigen::Matrix<double, 3, 2> B = s.beta.leftCols<2>();
  Eigen::Matrix<double, 3, 2> PB = Eigen::Matrix<double, 3, 2>::Zero();
  for (int j = 0; j < 3; ++j) PB += m.point(vs[size_t(j)]) * B.row(j);
  const Eigen::Matrix<double, 3, 2> PBs = PB * sigma;
  std::array<Eigen::Vector3d, 3> out;
  for (int i = 0; i < 3; ++i) out[size_t(i)] = -s.area * (PBs * B.row(i).transpose());  // eq. 1
  return out;
}

void compute_forces(const StressMesh& m, ForceField& out) {
  const SurfaceMesh& g = m.mesh();
  out.tensile.assign(g.number_of_halfedges(), Eigen::Vector3d::Zero());
  out.compressive.assign(g.number_of_halfedges(), Eigen::Vector3d::Zero());
  out.total.assign(g.number_of_vertices(), Eigen::Vector3d::Zero());
  tbb::parallel_for(size_t(0), size_t(g.number_of_faces()), [&](size_t k) {
    const FaceId f(static_cast<SurfaceMesh::size_type>(k));
    const auto [plus, minus] = split_stress(m.face(f).sigma);
    const auto fp = nodal_forces(m, f, plus), fm = nodal_forces(m, f, minus);
    const auto cs = m.corners(f);
    for (int i = 0; i < 3; ++i) {
      out.tensile[cs[size_t(i)].idx()] = fp[size_t(i)];
      out.compressive[cs[size_t(i)].idx()] = fm[size_t(i)];
    }
  });
  tbb::parallel_for(size_t(0), size_t(g.number_of_vertices()), [&](size_t k) {
    const VertexId v(static_cast<SurfaceMesh::size_type>(k));
    Eigen::Vector3d sum = Eigen::Vector3d::Zero();
    for (HalfedgeId h : CGAL::halfedges_around_target(g.halfedge(v), g))
      if (!g.is_border(h)) sum += out.tensile[h.idx()] + out.compressive[h.idx()];
    out.total[k] = sum;
  });
}

}  // namespace phellem::bark
