// StressMesh: the triangle mesh of the stress-field cracking model (Spicker 2014 sec. 3.1,
// after Iben & O'Brien 2006) with what the model keeps per face, corner, edge and vertex.
//
// The mesh is a CGAL Surface_mesh, so crack insertion splits edges and faces with CGAL's
// Euler operations and the mesh stays a valid, consistently oriented 2-manifold (with
// boundary). Vertices never move: forces only accumulate a virtual displacement (sec. 3.1.4).
#pragma once

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <Eigen/Core>
#include <array>
#include <memory>
#include <stdexcept>
#include <string>

#include "bark/geometry/tri_mesh.h"

namespace phellem::bark {

using StressKernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using SurfaceMesh = CGAL::Surface_mesh<StressKernel::Point_3>;
using VertexId = SurfaceMesh::Vertex_index;
using FaceId = SurfaceMesh::Face_index;

inline Eigen::Vector3d to_eigen(const StressKernel::Point_3& p) { return {p.x(), p.y(), p.z()}; }
using HalfedgeId = SurfaceMesh::Halfedge_index;
using EdgeId = SurfaceMesh::Edge_index;

// A mesh the model cannot take: `where` names the element ("triangle 12", "vertex 3").
struct MeshError : std::runtime_error {
  MeshError(std::string where_, const std::string& what) : std::runtime_error(what), where(std::move(where_)) {}
  std::string where;
};

// What the model keeps per face: the local frame of Figure 10 (u along the face's first
// edge, v = n × u), the barycentric basis matrix β (sec. 3.1.2), the area and the stress
// tensor σ in the local frame.
struct FaceState {
  Eigen::Matrix<double, 3, 2> frame = Eigen::Matrix<double, 3, 2>::Zero();  // columns u, v
  Eigen::Vector3d normal = Eigen::Vector3d::Zero();
  Eigen::Matrix3d beta = Eigen::Matrix3d::Zero();
  double area = 0;
  Eigen::Matrix2d sigma = Eigen::Matrix2d::Zero();
};

class StressMesh {
 public:
  // Welds corners that share a position (their UVs stay per corner, so UV seams survive) and
  // builds the half-edge mesh. Throws MeshError for an empty mesh, an index out of range, a
  // degenerate triangle (zero area or a repeated vertex), a non-finite coordinate, or an
  // edge shared by more than two triangles / triangles of opposite orientation (non-manifold).
  static StressMesh from(const TriMesh& in);

  SurfaceMesh& mesh() { return *mesh_; }
  const SurfaceMesh& mesh() const { return *mesh_; }
  Eigen::Vector3d point(VertexId v) const { return to_eigen(mesh_->point(v)); }
  FaceState& face(FaceId f) { return face_[f]; }
  const FaceState& face(FaceId f) const { return face_[f]; }
  // Texture coordinate of target(h) as seen from face(h).
  Eigen::Vector2d& uv(HalfedgeId h) { return uv_[h]; }
  const Eigen::Vector2d& uv(HalfedgeId h) const { return uv_[h]; }
  bool crack(EdgeId e) const { return crack_[e]; }
  void set_crack(EdgeId e, bool on) { crack_[e] = on; }
  bool has_uvs() const { return has_uvs_; }

  // The face's three vertices in frame order (source and target of halfedge(f), then the third).
  std::array<VertexId, 3> vertices(FaceId f) const;
  std::array<HalfedgeId, 3> corners(FaceId f) const;  // halfedges whose targets are vertices(f)
  // Recomputes the frame, normal, area and β of f from its vertices (σ is not touched).
  // Returns false for a degenerate face.
  bool update_geometry(FaceId f);
  // σ as a 3×3 world-space tensor E σ Eᵀ (E: the frame), and back (projected onto the frame).
  Eigen::Matrix3d world_stress(FaceId f) const;
  void set_world_stress(FaceId f, const Eigen::Matrix3d& s);
  // Area-weighted vertex normal.
  Eigen::Vector3d vertex_normal(VertexId v) const;
  // Largest singular value of β over all faces.
  double max_beta_singular_value() const;

  // The mesh as an indexed triangle mesh; vertices are split where corners disagree on UVs.
  // `source` (if given) receives each output vertex's mesh vertex.
  TriMesh to_trimesh(std::vector<VertexId>* source = nullptr) const;

 private:
  StressMesh();
  // Owned through a pointer: the property maps refer into it, and stay valid when a
  // StressMesh is moved.
  std::unique_ptr<SurfaceMesh> mesh_;
  SurfaceMesh::Property_map<FaceId, FaceState> face_;
  SurfaceMesh::Property_map<HalfedgeId, Eigen::Vector2d> uv_;
  SurfaceMesh::Property_map<EdgeId, bool> crack_;
  bool has_uvs_ = false;
};

}  // namespace phellem::bark
