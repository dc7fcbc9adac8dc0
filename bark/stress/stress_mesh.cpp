#include "bark/stress/stress_mesh.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_reduce.h>

#include <Eigen/Geometry>
#include <Eigen/LU>
#include <Eigen/SVD>
#include <cmath>
#include <map>

namespace phellem::bark {

StressMesh::StressMesh() : mesh_(std::make_unique<SurfaceMesh>()) {
  face_ = mesh_->add_property_map<FaceId, FaceState>("f:stress").first;
  uv_ = mesh_->add_property_map<HalfedgeId, Eigen::Vector2d>("h:uv", Eigen::Vector2d::Zero()).first;
  crack_ = mesh_->add_property_map<EdgeId, bool>("e:crack", false).first;
}

StressMesh StressMesh::from(const TriMesh& in) {
  if (in.triangles.empty()) throw MeshError("mesh", "has no triangles");
  if (in.has_uvs() && in.uvs.size() != in.positions.size())
    throw MeshError("mesh", "has " + std::to_string(in.uvs.size()) + " texture coordinates for " +
                                std::to_string(in.positions.size()) + " positions");
  for (size_t i = 0; i < in.positions.size(); ++i)
    if (!in.positions[i].allFinite()) throw MeshError("vertex " + std::to_string(i), "has a non-finite coordinate");
  StressMesh m;
  m.has_uvs_ = in.has_uvs();
  SurfaceMesh& g = *m.mesh_;
  g.reserve(SurfaceMesh::size_type(in.positions.size()), SurfaceMesh::size_type(3 * in.triangles.size() / 2 + 3),
            SurfaceMesh::size_type(in.triangles.size()));
  // Weld: one mesh vertex per distinct position (exact match), in first-use order.
  std::map<std::array<double, 3>, VertexId> welded;
  std::vector<VertexId> vertex_of(in.positions.size());
  for (size_t i = 0; i < in.positions.size(); ++i) {
    const Eigen::Vector3d& p = in.positions[i];
    auto [it, fresh] = welded.try_emplace({p.x(), p.y(), p.z()}, VertexId());
    if (fresh) it->second = g.add_vertex(StressKernel::Point_3(p.x(), p.y(), p.z()));
    vertex_of[i] = it->second;
  }
  for (size_t t = 0; t < in.triangles.size(); ++t) {
    const auto& tri = in.triangles[t];
    auto where_t = [t] { return "triangle " + std::to_string(t); };  // made only for an error
    for (uint32_t k : tri)
      if (k >= in.positions.size())
        throw MeshError(where_t(), "vertex index " + std::to_string(k) + " is out of range (" + std::to_string(in.positions.size()) +
                                   " positions)");
    const VertexId a = vertex_of[tri[0]], b = vertex_of[tri[1]], c = vertex_of[tri[2]];
    if (a == b || b == c || a == c) throw MeshError(where_t(), "is degenerate (a vertex repeats)");
    const Eigen::Vector3d pa = in.positions[tri[0]], pb = in.positions[tri[1]], pc = in.positions[tri[2]];
    if (!(triangle_shape(pa, pb, pc) > 1e-12)) throw MeshError(where_t(), "is degenerate (zero area)");
    const FaceId f = g.add_face(a, b, c);
    if (f == SurfaceMesh::null_face())
      throw MeshError(where_t(),
                      "makes the mesh non-manifold (an edge already used by two triangles, a triangle of opposite orientation, "
                      "or a pinched vertex)");
    if (m.has_uvs_) {
      const HalfedgeId h = g.halfedge(f);  // target(h) is the face's last vertex given to add_face
      for (HalfedgeId c2 : CGAL::halfedges_around_face(h, g)) {
        const VertexId v = g.target(c2);
        const uint32_t k = v == a ? tri[0] : v == b ? tri[1] : tri[2];
        m.uv_[c2] = in.uvs[k];
      }
    }
  }
  // Each face's geometry from its own corners (fixed once the face is added): in parallel.
  tbb::parallel_for(tbb::blocked_range<size_t>(0, g.num_faces(), 1024), [&](const tbb::blocked_range<size_t>& r) {
    for (size_t i = r.begin(); i != r.end(); ++i) m.update_geometry(FaceId{uint32_t(i)});
  });
  // Unreferenced positions would be isolated vertices: drop them.
  for (VertexId v : g.vertices())
    if (g.is_isolated(v)) g.remove_vertex(v);
  g.collect_garbage();
  return m;
}

std::array<VertexId, 3> StressMesh::vertices(FaceId f) const {
  const HalfedgeId h = mesh_->halfedge(f);
  return {mesh_->source(h), mesh_->target(h), mesh_->target(mesh_->next(h))};
}

std::array<HalfedgeId, 3> StressMesh::corners(FaceId f) const {
  const HalfedgeId h = mesh_->halfedge(f);
  return {mesh_->prev(h), h, mesh_->next(h)};
}

bool StressMesh::update_geometry(FaceId f) {
  // Figure 10: u along the first edge, n the face normal, v = n × u; local coordinates
  // m_i = (p_i − p_0)·(u, v); β = [m_u; m_v; 1]⁻¹ (sec. 3.1.2, the barycentric basis matrix).
  FaceState& s = face_[f];
  const auto vs = vertices(f);
  const Eigen::Vector3d p0 = point(vs[0]), p1 = point(vs[1]), p2 = point(vs[2]);
  const Eigen::Vector3d e1 = p1 - p0, e2 = p2 - p0, n = e1.cross(e2);
  const double twice_area = n.norm();
  if (!(twice_area > 0) || !(e1.norm() > 0)) return false;
  s.normal = n / twice_area;
  const Eigen::Vector3d u = e1.normalized(), v = s.normal.cross(u);
  s.frame.col(0) = u;
  s.frame.col(1) = v;
  s.area = 0.5 * twice_area;
  Eigen::Matrix3d M;
  M << 0, e1.dot(u), e2.dot(u),  //
      0, e1.dot(v), e2.dot(v),   //
      1, 1, 1;
  s.beta = M.inverse();
  return true;
}

Eigen::Matrix3d StressMesh::world_stress(FaceId f) const {
  const FaceState& s = face_[f];
  return s.frame * s.sigma * s.frame.transpose();
}

void StressMesh::set_world_stress(FaceId f, const Eigen::Matrix3d& w) {
  FaceState& s = face_[f];
  const Eigen::Matrix2d local = s.frame.transpose() * w * s.frame;
  s.sigma = 0.5 * (local + local.transpose());
}

Eigen::Vector3d StressMesh::vertex_normal(VertexId v) const {
  Eigen::Vector3d n = Eigen::Vector3d::Zero();
  for (FaceId f : CGAL::faces_around_target(mesh_->halfedge(v), *mesh_))
    if (f != SurfaceMesh::null_face()) n += face_[f].area * face_[f].normal;
  const double len = n.norm();
  return len > 0 ? Eigen::Vector3d(n / len) : Eigen::Vector3d::UnitZ();
}

double StressMesh::max_beta_singular_value() const {
  // σ₁(β)² is the largest eigenvalue of βᵀβ: at least its largest diagonal entry (a column's
  // squared norm), at most its largest absolute row sum (Gershgorin). Only faces whose upper
  // bound reaches every face's lower bound (less a margin far above rounding) can hold the
  // maximum, and only those take the SVD: the same maximum as the SVD of every face, at a
  // fraction of the cost. Maxima: the same whatever the thread count. (num_faces counts
  // removed faces too.)
  const size_t n = mesh_->num_faces();
  std::vector<double> upper(n, -1);
  auto max_of = [](double a, double b) { return std::max(a, b); };
  const double lower = tbb::parallel_reduce(
      tbb::blocked_range<size_t>(0, n, 1024), 0.0,
      [&](const tbb::blocked_range<size_t>& r, double m) {
        for (size_t i = r.begin(); i != r.end(); ++i) {
          const FaceId f{uint32_t(i)};
          if (mesh_->is_removed(f)) continue;
          const Eigen::Matrix3d g = face_[f].beta.transpose() * face_[f].beta;
          m = std::max(m, g.diagonal().maxCoeff());
          upper[i] = g.cwiseAbs().rowwise().sum().maxCoeff();
        }
        return m;
      },
      max_of);
  const double needed = lower * (1 - 1e-6);
  return tbb::parallel_reduce(
      tbb::blocked_range<size_t>(0, n, 1024), 0.0,
      [&](const tbb::blocked_range<size_t>& r, double m) {
        for (size_t i = r.begin(); i != r.end(); ++i)
          if (upper[i] >= needed)
            m = std::max(m, Eigen::JacobiSVD<Eigen::Matrix3d>(face_[FaceId{uint32_t(i)}].beta).singularValues()[0]);
        return m;
      },
      max_of);
}

TriMesh StressMesh::to_trimesh(std::vector<VertexId>* source) const {
  TriMesh out;
  if (source) source->clear();
  const SurfaceMesh& g = *mesh_;
  // One output vertex per (mesh vertex, UV) pair.
  std::map<std::pair<uint32_t, std::array<double, 2>>, uint32_t> index;
  for (FaceId f : g.faces()) {
    std::array<uint32_t, 3> tri{};
    const auto cs = corners(f);
    for (int k = 0; k < 3; ++k) {
      const VertexId v = g.target(cs[size_t(k)]);
      const Eigen::Vector2d t = has_uvs_ ? uv_[cs[size_t(k)]] : Eigen::Vector2d::Zero();
      auto [it, fresh] = index.try_emplace({uint32_t(v), {t.x(), t.y()}}, uint32_t(out.positions.size()));
      if (fresh) {
        out.positions.push_back(point(v));
        if (source) source->push_back(v);
        if (has_uvs_) out.uvs.push_back(t);
      }
      tri[size_t(k)] = it->second;
    }
    out.triangles.push_back(tri);
  }
  return out;
}

}  // namespace phellem::bark
