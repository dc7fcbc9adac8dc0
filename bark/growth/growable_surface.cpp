#include "bark/growth/growable_surface.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Surface_mesh.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cstdio>
#include <map>
#include <numeric>
#include <optional>

#include "util/errors.h"

namespace phellem::bark {

namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using SurfaceMesh = CGAL::Surface_mesh<K::Point_3>;

// The mesh as a CGAL halfedge structure, its faces in the mesh's order; empty when a vertex's
// triangles form more than one fan (CGAL's add_face refuses the face that would make it so).
std::optional<SurfaceMesh> halfedge_mesh(const TriMesh& m) {
  SurfaceMesh sm;
  std::vector<SurfaceMesh::Vertex_index> v;
  v.reserve(m.positions.size());
  for (const auto& p : m.positions) v.push_back(sm.add_vertex(K::Point_3(p.x(), p.y(), p.z())));
  for (const auto& t : m.triangles)
    if (sm.add_face(v[t[0]], v[t[1]], v[t[2]]) == SurfaceMesh::null_face()) return std::nullopt;
  return sm;
}

std::string face_name(uint32_t t, const std::vector<uint32_t>& input_face) {
  return std::to_string(t < input_face.size() ? input_face[t] : t);
}

// A self-intersecting surface has no consistent inside; a triangle without area has no normal
// to grow along. The first such pair CGAL's box-intersection search meets is named.
void require_embedded(const SurfaceMesh& sm, const std::string& file, const std::string& where,
                      const std::vector<uint32_t>& input_face) {
  namespace PMP = CGAL::Polygon_mesh_processing;
  std::vector<std::pair<SurfaceMesh::Face_index, SurfaceMesh::Face_index>> pairs;
  PMP::self_intersections(sm, std::back_inserter(pairs), PMP::parameters::maximum_number(1));
  if (pairs.empty()) return;
  const uint32_t a = uint32_t(pairs.front().first), b = uint32_t(pairs.front().second);
  if (a == b)
    throw UserError(file, where,
                    "the surface to grow has a triangle without area: face " + face_name(a, input_face) +
                        " (its corners lie on a line; growth moves each face along its normal)");
  throw UserError(file, where,
                  "the surface to grow intersects itself: faces " + face_name(std::min(a, b), input_face) + " and " +
                      face_name(std::max(a, b), input_face) +
                      " intersect (a self-intersecting surface has no inside to grow; separate its parts)");
}

uint32_t find_root(std::vector<uint32_t>& parent, uint32_t v) {
  while (parent[v] != v) v = parent[v] = parent[parent[v]];
  return v;
}

// Each connected component of a closed surface encloses a positive volume when its triangles
// are wound counter-clockwise seen from outside (their normals point out of the wood).
void require_outwards(const TriMesh& m, const std::string& file, const std::string& where,
                      const std::vector<uint32_t>& input_face) {
  std::vector<uint32_t> parent(m.positions.size());
  std::iota(parent.begin(), parent.end(), 0u);
  for (const auto& t : m.triangles)
    for (int k = 1; k < 3; ++k) parent[find_root(parent, t[size_t(k)])] = find_root(parent, t[0]);
  std::map<uint32_t, std::pair<double, uint32_t>> volume6;  // component root -> (6 × volume, its first triangle)
  for (uint32_t i = 0; i < m.triangles.size(); ++i) {
    const auto& t = m.triangles[i];
    const auto [it, added] = volume6.emplace(find_root(parent, t[0]), std::make_pair(0.0, i));
    it->second.first += m.positions[t[0]].dot(m.positions[t[1]].cross(m.positions[t[2]]));
  }
  for (const auto& [root, v] : volume6) {
    if (v.first > 0) continue;
    char volume[32];
    std::snprintf(volume, sizeof volume, "%.3g", v.first / 6);
    const std::string part = volume6.size() == 1 ? "it" : "its part with face " + face_name(v.second, input_face);
    throw UserError(file, where,
                    "the mesh is inside out (faces wound clockwise seen from outside): " + part + " encloses " + volume +
                        " m³; reverse the order of each triangle's corners");
  }
}

}  // namespace

void require_closed(const TriMesh& m, const std::string& file, const std::string& where, const std::string& what) {
  // Every directed edge, sorted (a sort of flat pairs, several times faster than a map on a
  // mesh of 100k triangles); the first bad one in that order is reported.
  using Edge = std::pair<uint32_t, uint32_t>;
  std::vector<Edge> directed;
  directed.reserve(3 * m.triangles.size());
  for (const auto& t : m.triangles)
    for (int e = 0; e < 3; ++e) directed.emplace_back(t[size_t(e)], t[size_t(e + 1) % 3]);
  std::sort(directed.begin(), directed.end());
  const auto uses = [&](const Edge& e) {
    const auto [lo, hi] = std::equal_range(directed.begin(), directed.end(), e);
    return long(hi - lo);
  };
  for (size_t i = 0; i < directed.size();) {
    const Edge edge = directed[i];
    const long n = uses(edge), back = uses({edge.second, edge.first});
    if (n != 1 || back != 1)
      throw UserError(file, where,
                      what + " must be closed and consistently oriented: its edge between vertices " +
                          std::to_string(edge.first) + " and " + std::to_string(edge.second) + " is used " +
                          std::to_string(n) + " time(s) one way and " + std::to_string(back) + " the other");
    i += size_t(n);
  }
  if (m.triangles.empty()) throw UserError(file, where, what + " has no triangles");
  for (const auto& t : m.triangles)
    for (uint32_t v : t)
      if (v >= m.positions.size())
        throw UserError(file, where, what + " refers to vertex " + std::to_string(v) + " of " + std::to_string(m.positions.size()));
}

void require_growable(const TriMesh& m, const std::string& file, const std::string& where,
                      const std::vector<uint32_t>& input_face) {
  require_closed(m, file, where);
  const std::optional<SurfaceMesh> sm = halfedge_mesh(m);
  if (!sm) throw UserError(file, where, "the surface to grow must be a 2-manifold (a vertex has triangles in more than one fan)");
  // Orientation means nothing on a surface that passes through itself: intersections first.
  require_embedded(*sm, file, where, input_face);
  require_outwards(m, file, where, input_face);
}

}  // namespace phellem::bark
