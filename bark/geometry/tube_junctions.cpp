#include "bark/geometry/tube_junctions.h"

#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Polygon_mesh_processing/connected_components.h>
#include <CGAL/Polygon_mesh_processing/corefinement.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Polygon_mesh_processing/stitch_borders.h>
#include <CGAL/Polygon_mesh_processing/triangulate_hole.h>

#include <CGAL/boost/graph/Euler_operations.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <limits>
#include <map>
#include <optional>

#include "bark/geometry/canonical_surface_mesh.h"
#include "bark/stress/stress_mesh.h"

namespace phellem::bark {

namespace {

namespace PMP = CGAL::Polygon_mesh_processing;
using Point = StressKernel::Point_3;
using Triangle = StressKernel::Triangle_3;
using TriangleTree = CGAL::AABB_tree<
    CGAL::AABB_traits<StressKernel, CGAL::AABB_triangle_primitive<StressKernel, std::vector<Triangle>::const_iterator>>>;

// Removes the faces of the components listed (and what they leave isolated).
void remove_components(SurfaceMesh& m, const SurfaceMesh::Property_map<FaceId, std::size_t>& component,
                       const std::vector<std::size_t>& drop) {
  if (drop.empty()) return;
  PMP::remove_connected_components(m, drop, component);
  m.collect_garbage();
}

// Whether a face is a sliver by StressMesh::from's measure, with margin (StressMesh refuses
// a triangle_shape of 1e-12).
bool sliver(const SurfaceMesh& m, FaceId f) {
  std::array<Eigen::Vector3d, 3> p;
  int k = 0;
  for (VertexId v : CGAL::vertices_around_face(m.halfedge(f), m)) p[size_t(k++)] = to_eigen(m.point(v));
  return !(triangle_shape(p[0], p[1], p[2]) > 1e-9);
}

// Where the curve runs through vertices or along edges of either mesh (a seam, a ring),
// corefinement leaves slivers whose corners are collinear up to rounding: a needle loses its
// shortest edge (collapsed), a cap its longest (flipped towards the opposite corner).
// Returns whether none is left.
bool remove_slivers(SurfaceMesh& m) {
  for (int pass = 0; pass < 8; ++pass) {
    bool changed = false, left = false;
    for (FaceId f : m.faces()) {
      if (m.is_removed(f) || !sliver(m, f)) continue;
      SurfaceMesh::Halfedge_index shortest, longest;
      double lo = std::numeric_limits<double>::infinity(), hi = -1;
      for (auto h : CGAL::halfedges_around_face(m.halfedge(f), m)) {
        const double l = CGAL::squared_distance(m.point(m.source(h)), m.point(m.target(h)));
        if (l < lo) lo = l, shortest = h;
        if (l > hi) hi = l, longest = h;
      }
      if (lo < 1e-12 * hi && CGAL::Euler::does_satisfy_link_condition(m.edge(shortest), m)) {
        CGAL::Euler::collapse_edge(m.edge(shortest), m);
        changed = true;
      } else if (!m.is_border(m.edge(longest)) &&
                 !CGAL::halfedge(m.target(m.next(longest)), m.target(m.next(m.opposite(longest))), m).second) {
        CGAL::Euler::flip_edge(longest, m);
        changed = true;
      } else {
        left = true;
      }
    }
    if (!changed) return !left;
  }
  for (FaceId f : m.faces())
    if (sliver(m, f)) return false;
  return true;
}

// Cuts `branch` and `surface` along their intersection, drops the branch's piece inside the
// surface (every piece but the largest) and the surface's piece inside the branch (the smallest
// piece bounded by the curve), and stitches the rest together into `surface`. Returns an empty
// string, or why the branch was kept apart (then `surface` gets it unchanged).
std::string join_branch(SurfaceMesh& surface, SurfaceMesh branch) {
  // Whatever goes wrong, the surface is restored and gets the branch as it came.
  const SurfaceMesh surface_before = surface, branch_before = branch;
  auto apart = [&](std::string why) {
    surface = surface_before;
    surface.join(branch_before);
    return why;
  };
  auto on_curve_s = surface.add_property_map<SurfaceMesh::Edge_index, bool>("e:junction", false).first;
  auto on_curve_b = branch.add_property_map<SurfaceMesh::Edge_index, bool>("e:junction", false).first;
  try {
    PMP::corefine(surface, branch, CGAL::parameters::edge_is_constrained_map(on_curve_s).throw_on_self_intersection(true),
                  CGAL::parameters::edge_is_constrained_map(on_curve_b));
  } catch (const std::exception& e) {
    return apart(std::string("CGAL could not intersect it with its parent (") + e.what() + ")");
  }
  auto surface_c = canonical(surface, on_curve_s);
  auto branch_c = canonical(branch, on_curve_b);
  if (!surface_c || !branch_c) return apart("CGAL's intersection with its parent is not a manifold surface");
  surface = std::move(*surface_c);
  branch = std::move(*branch_c);
  auto comp_s = surface.add_property_map<FaceId, std::size_t>("f:junction_component").first;
  auto comp_b = branch.add_property_map<FaceId, std::size_t>("f:junction_component").first;
  const std::size_t ns = PMP::connected_components(surface, comp_s, CGAL::parameters::edge_is_constrained_map(on_curve_s));
  const std::size_t nb = PMP::connected_components(branch, comp_b, CGAL::parameters::edge_is_constrained_map(on_curve_b));
  std::vector<double> area_s(ns, 0.0), area_b(nb, 0.0);
  std::vector<char> touches_s(ns, 0);
  for (FaceId f : surface.faces()) {
    area_s[comp_s[f]] += PMP::face_area(f, surface);
    for (auto h : CGAL::halfedges_around_face(surface.halfedge(f), surface))
      touches_s[comp_s[f]] |= on_curve_s[surface.edge(h)] ? 1 : 0;
  }
  for (FaceId f : branch.faces()) area_b[comp_b[f]] += PMP::face_area(f, branch);
  // The surface splits into the rest and the patch inside the branch: two pieces on the curve.
  std::size_t hole = ns, on_curve = 0;
  for (std::size_t c = 0; c < ns; ++c)
    if (touches_s[c]) {
      ++on_curve;
      if (hole == ns || area_s[c] < area_s[hole]) hole = c;
    }
  if (nb < 2 || on_curve < 2) return apart("it does not pass through its parent's surface along a closed curve");
  std::size_t keep = 0;
  for (std::size_t c = 1; c < nb; ++c)
    if (area_b[c] > area_b[keep]) keep = c;
  std::vector<std::size_t> drop_b;
  for (std::size_t c = 0; c < nb; ++c)
    if (c != keep) drop_b.push_back(c);
  remove_components(surface, comp_s, {hole});
  remove_components(branch, comp_b, drop_b);
  surface.remove_property_map(comp_s);
  surface.remove_property_map(on_curve_s);
  branch.remove_property_map(comp_b);
  branch.remove_property_map(on_curve_b);
  SurfaceMesh joined = surface;
  joined.join(branch);
  PMP::stitch_borders(joined);
  if (!remove_slivers(joined)) return apart("its junction left triangles of zero area that could not be removed");
  joined.collect_garbage();
  surface = std::move(joined);
  return {};
}

}  // namespace

JoinedTubes join_tubes(const std::vector<TriMesh>& parts, const std::vector<int>& parent) {
  JoinedTubes out;
  if (parts.empty()) return out;
  SurfaceMesh surface = welded_surface_mesh(parts[0]);
  for (size_t k = 1; k < parts.size(); ++k) {
    SurfaceMesh branch = welded_surface_mesh(parts[k]);
    if (k >= parent.size() || parent[k] < 0 || size_t(parent[k]) >= k) {
      surface.join(branch);
      out.not_joined.push_back("branch " + std::to_string(k) + ": it has no parent before it");
      continue;
    }
    if (const std::string why = join_branch(surface, std::move(branch)); !why.empty())
      out.not_joined.push_back("branch " + std::to_string(k) + ": " + why);
  }
  // The open ends (the trunk's base and top, each limb's tip) are closed with flat caps
  // refined to the density around them, like sawn ends: a closed surface has no hollow ends to
  // show, and the crack depth's ray cast always finds the far side.
  std::vector<SurfaceMesh::Halfedge_index> borders;
  std::vector<char> seen(surface.number_of_halfedges(), 0);
  for (auto h : surface.halfedges()) {
    if (!surface.is_border(h) || seen[h.idx()]) continue;
    for (auto k : CGAL::halfedges_around_face(h, surface)) seen[k.idx()] = 1;
    borders.push_back(h);
  }
  for (auto h : borders) {
    std::vector<FaceId> added;
    std::vector<VertexId> inside;
    // Without the 3D Delaunay search, whose result varied from run to run (CGAL 5.5): the
    // caps, and with them the whole cracked tree, must not depend on the run.
    PMP::triangulate_and_refine_hole(surface, h, std::back_inserter(added), std::back_inserter(inside),
                                     CGAL::parameters::use_delaunay_triangulation(false));
    out.caps += added.empty() ? 0 : 1;
  }
  // Texture coordinates: each face belongs to the part whose surface it lies on, and each corner
  // reads that part's UVs through the part's triangle under the face's centre.
  std::vector<std::vector<Triangle>> triangles(parts.size());
  std::vector<std::unique_ptr<TriangleTree>> trees;
  for (size_t k = 0; k < parts.size(); ++k) {
    for (const auto& t : parts[k].triangles) {
      const auto& p = parts[k].positions;
      triangles[k].emplace_back(Point(p[t[0]].x(), p[t[0]].y(), p[t[0]].z()), Point(p[t[1]].x(), p[t[1]].y(), p[t[1]].z()),
                                Point(p[t[2]].x(), p[t[2]].y(), p[t[2]].z()));
    }
    trees.push_back(std::make_unique<TriangleTree>(triangles[k].begin(), triangles[k].end()));
    trees.back()->accelerate_distance_queries();
  }
  TriMesh& mesh = out.mesh;
  const bool uvs = std::all_of(parts.begin(), parts.end(), [](const TriMesh& p) { return p.has_uvs(); });
  for (FaceId f : surface.faces()) {
    std::array<Eigen::Vector3d, 3> corner;
    int n = 0;
    for (VertexId v : CGAL::vertices_around_face(surface.halfedge(f), surface)) corner[size_t(n++)] = to_eigen(surface.point(v));
    const Eigen::Vector3d centre = (corner[0] + corner[1] + corner[2]) / 3;
    const uint32_t first = uint32_t(mesh.positions.size());
    for (const auto& c : corner) mesh.positions.push_back(c);
    mesh.triangles.push_back({first, first + 1, first + 2});
    if (!uvs) continue;
    size_t part = 0;
    double best = std::numeric_limits<double>::infinity();
    std::ptrdiff_t source = 0;
    for (size_t k = 0; k < parts.size(); ++k) {
      const auto [point, it] = trees[k]->closest_point_and_primitive(Point(centre.x(), centre.y(), centre.z()));
      const double d = (to_eigen(point) - centre).squaredNorm();
      if (d < best) {
        best = d;
        part = k;
        source = it - triangles[k].begin();
      }
    }
    const TriMesh& p = parts[part];
    const auto& t = p.triangles[size_t(source)];
    for (const auto& c : corner) {
      const Eigen::Vector3d b = barycentric(c, p.positions[t[0]], p.positions[t[1]], p.positions[t[2]]);
      mesh.uvs.push_back(b[0] * p.uvs[t[0]] + b[1] * p.uvs[t[1]] + b[2] * p.uvs[t[2]]);
    }
  }
  return out;
}

}  // namespace phellem::bark
