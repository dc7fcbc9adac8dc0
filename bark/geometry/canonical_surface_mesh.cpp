#include "bark/geometry/canonical_surface_mesh.h"

#include <algorithm>
#include <array>
#include <map>
#include <vector>

namespace phellem::bark {

SurfaceMesh welded_surface_mesh(const TriMesh& t) {
  SurfaceMesh m;
  std::map<std::array<double, 3>, VertexId> index;
  std::vector<VertexId> v(t.positions.size());
  for (size_t i = 0; i < t.positions.size(); ++i) {
    const Eigen::Vector3d& p = t.positions[i];
    const auto [it, fresh] = index.try_emplace({p.x(), p.y(), p.z()});
    if (fresh) it->second = m.add_vertex(StressKernel::Point_3(p.x(), p.y(), p.z()));
    v[i] = it->second;
  }
  for (const auto& tri : t.triangles) {
    const VertexId a = v[tri[0]], b = v[tri[1]], c = v[tri[2]];
    if (a != b && b != c && a != c) m.add_face(a, b, c);  // (a degenerate or non-manifold face is left out)
  }
  return m;
}

std::optional<SurfaceMesh> canonical(const SurfaceMesh& m, SurfaceMesh::Property_map<EdgeId, bool>& flag) {
  using Key = std::array<double, 3>;
  auto key = [&](VertexId v) { return Key{m.point(v).x(), m.point(v).y(), m.point(v).z()}; };
  std::vector<VertexId> order(m.vertices().begin(), m.vertices().end());
  std::sort(order.begin(), order.end(), [&](VertexId a, VertexId b) { return key(a) < key(b); });
  SurfaceMesh out;
  std::vector<VertexId> renamed(m.number_of_vertices() + m.number_of_removed_vertices());
  for (VertexId v : order) renamed[v.idx()] = out.add_vertex(m.point(v));
  // Each face as its corners' new numbers, turned to start at the smallest (orientation kept).
  std::vector<std::array<VertexId, 3>> faces;
  for (FaceId f : m.faces()) {
    std::array<VertexId, 3> c;
    int k = 0;
    for (VertexId v : CGAL::vertices_around_face(m.halfedge(f), m)) c[size_t(k++)] = renamed[v.idx()];
    std::rotate(c.begin(), std::min_element(c.begin(), c.end()), c.end());
    faces.push_back(c);
  }
  std::sort(faces.begin(), faces.end());
  for (const auto& c : faces)
    if (out.add_face(c[0], c[1], c[2]) == SurfaceMesh::null_face()) return std::nullopt;
  auto out_flag = out.add_property_map<EdgeId, bool>("e:junction", false).first;
  for (EdgeId e : m.edges())
    if (flag[e]) {
      const auto [h, found] = CGAL::halfedge(renamed[m.vertex(e, 0).idx()], renamed[m.vertex(e, 1).idx()], out);
      if (found) out_flag[out.edge(h)] = true;
    }
  flag = out_flag;
  return out;
}

}  // namespace phellem::bark
