#include "bark/geometry/irregular_remesh.h"

#include <CGAL/AABB_face_graph_triangle_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/Polygon_mesh_processing/remesh.h>

#include <Eigen/Geometry>
#include <cmath>
#include <map>

#include "bark/stress/stress_mesh.h"
#include "util/random.h"

namespace phellem::bark {

namespace {

namespace PMP = CGAL::Polygon_mesh_processing;
using Primitive = CGAL::AABB_face_graph_triangle_primitive<SurfaceMesh>;
using Tree = CGAL::AABB_tree<CGAL::AABB_traits<StressKernel, Primitive>>;

// The remesher and the jitter leave vertices on the input's flat triangles, up to a sagitta
// inside the curved surface they sample (0.25 mm on a 7852-triangle trunk of radius 0.16 m,
// seen as mottled shading under a low sun). Each vertex moves onto the Phong surface
// (Boubekeur & Alexa 2008) of the input face it projects onto, with α = ½, which reproduces
// circles and spheres to fourth order, from the input's vertex normals; not where that face
// touches a sharp feature (a corner normal more than half the feature angle off the face's).
void onto_phong_surface(const StressMesh& source, const Tree& all, SurfaceMesh& sm, double sharp_angle_deg) {
  const SurfaceMesh& src = source.mesh();
  const double cos_half = std::cos(0.5 * sharp_angle_deg * 3.141592653589793 / 180.0);
  std::vector<Eigen::Vector3d> normal(src.number_of_vertices());
  for (VertexId w : src.vertices()) normal[w.idx()] = source.vertex_normal(w);
  for (VertexId v : sm.vertices()) {
    const auto [point, face] = all.closest_point_and_primitive(sm.point(v));
    const Eigen::Vector3d q = to_eigen(point);
    std::array<Eigen::Vector3d, 3> p, n;
    int k = 0;
    for (VertexId w : CGAL::vertices_around_face(src.halfedge(face), src)) {
      p[size_t(k)] = source.point(w);
      n[size_t(k++)] = normal[w.idx()];
    }
    const Eigen::Vector3d& fn = source.face(face).normal;
    if (!(n[0].dot(fn) > cos_half && n[1].dot(fn) > cos_half && n[2].dot(fn) > cos_half)) continue;
    const Eigen::Vector3d b = barycentric(q, p[0], p[1], p[2]);
    Eigen::Vector3d offset = Eigen::Vector3d::Zero();
    for (size_t i = 0; i < 3; ++i) offset -= b[int(i)] * (q - p[i]).dot(n[i]) * n[i];
    const Eigen::Vector3d r = q + 0.5 * offset;
    sm.point(v) = StressKernel::Point_3(r.x(), r.y(), r.z());
  }
}

}  // namespace

TriMesh irregular_remesh(const TriMesh& in, const RemeshOptions& o) {
  const StressMesh source = StressMesh::from(in);  // welded, validated, UVs per corner
  const SurfaceMesh& src = source.mesh();
  SurfaceMesh sm = src;  // remeshed in place; `src` stays for the UV transfer
  // Constrained edges: borders, UV seams (the two faces disagree on an end's UV) and sharp edges.
  auto ecm = sm.add_property_map<EdgeId, bool>("e:remesh_constrained", false).first;
  const double cos_sharp = std::cos(o.sharp_angle_deg * 3.141592653589793 / 180.0);
  double mean_edge = 0;
  for (EdgeId e : src.edges()) {
    mean_edge += (source.point(src.vertex(e, 0)) - source.point(src.vertex(e, 1))).norm();
    const HalfedgeId h = src.halfedge(e), t = src.opposite(h);
    if (src.is_border(e)) {
      ecm[e] = true;
      continue;
    }
    const bool seam = source.has_uvs() && ((source.uv(h) - source.uv(src.prev(t))).norm() > 1e-9 ||
                                           (source.uv(t) - source.uv(src.prev(h))).norm() > 1e-9);
    const bool sharp = source.face(src.face(h)).normal.dot(source.face(src.face(t)).normal) < cos_sharp;
    ecm[e] = seam || sharp;
  }
  mean_edge /= double(std::max<size_t>(1, src.number_of_edges()));
  const double target = o.edge_length > 0 ? o.edge_length : mean_edge;
  // Equilateral triangles of side `target` over the surface: refuse a size that would not fit.
  double area = 0;
  for (FaceId f : src.faces()) area += source.face(f).area;
  const double expected = area / (0.4330127 * target * target);
  if (expected > double(kMaxRemeshTriangles))
    throw MeshError("edge_length", "an edge length of " + std::to_string(target) + " m would make about " +
                                       std::to_string(static_cast<long long>(expected)) + " triangles; at most " +
                                       std::to_string(kMaxRemeshTriangles) + " are allowed (use a longer edge_length)");
  // Patches: faces connected without crossing a constrained edge (UV charts); the remesher
  // keeps them up to date as it makes new faces.
  auto patch = sm.add_property_map<FaceId, int>("f:patch", -1).first;
  {
    int next = 0;
    std::vector<FaceId> stack;
    for (FaceId f : sm.faces()) {
      if (patch[f] >= 0) continue;
      patch[f] = next;
      stack.assign(1, f);
      while (!stack.empty()) {
        const FaceId g = stack.back();
        stack.pop_back();
        for (HalfedgeId h : CGAL::halfedges_around_face(sm.halfedge(g), sm)) {
          if (ecm[sm.edge(h)]) continue;
          const FaceId n = sm.face(sm.opposite(h));
          if (n != SurfaceMesh::null_face() && patch[n] < 0) {
            patch[n] = next;
            stack.push_back(n);
          }
        }
      }
      ++next;
    }
  }
  std::map<int, std::vector<FaceId>> source_patch;
  for (FaceId f : src.faces()) source_patch[patch[f]].push_back(f);  // same indices before remeshing
  PMP::isotropic_remeshing(faces(sm), target, sm,
                           CGAL::parameters::number_of_iterations(unsigned(o.iterations))
                               .edge_is_constrained_map(ecm)
                               .protect_constraints(false)
                               .collapse_constraints(false)
                               .face_patch_map(patch));
  sm.collect_garbage();
  // Jitter: each free vertex (not on a constrained edge: seams and features keep their place)
  // moves by a random tangential offset, projected back onto the input, if no triangle around it
  // flips or gets an angle below 25° (or below its worst angle before). CGAL's
  // random_perturbation checks neither and can leave degenerate triangles.
  Tree all(faces(src).first, faces(src).second, src);
  all.accelerate_distance_queries();
  if (o.jitter > 0) {
    std::vector<char> fixed(sm.number_of_vertices(), 0);
    for (EdgeId e : sm.edges())
      if (ecm[e]) fixed[sm.vertex(e, 0).idx()] = fixed[sm.vertex(e, 1).idx()] = 1;
    const double floor_angle = 25 * 3.141592653589793 / 180;
    // The fan around v: its smallest angle and its faces' (unnormalized) normals.
    auto fan = [&](VertexId v, std::vector<Eigen::Vector3d>& normals) {
      double worst = 1e9;
      normals.clear();
      for (FaceId f : CGAL::faces_around_target(sm.halfedge(v), sm)) {
        if (f == SurfaceMesh::null_face()) continue;
        std::array<Eigen::Vector3d, 3> p;
        int k = 0;
        for (VertexId w : CGAL::vertices_around_face(sm.halfedge(f), sm)) p[size_t(k++)] = to_eigen(sm.point(w));
        const Eigen::Vector3d a = p[1] - p[0], b = p[2] - p[0], c = p[2] - p[1];
        auto ang = [](const Eigen::Vector3d& x, const Eigen::Vector3d& y) { return std::atan2(x.cross(y).norm(), x.dot(y)); };
        worst = std::min({worst, ang(a, b), ang(-a, c), ang(b, c)});
        normals.push_back(a.cross(b));
      }
      return worst;
    };
    std::vector<Eigen::Vector3d> n_before, n_after;
    for (VertexId v : sm.vertices()) {
      if (fixed[v.idx()]) continue;
      StreamRng rng(o.seed ^ 0x6a6974ULL, v.idx(), 0);
      const Eigen::Vector3d old = to_eigen(sm.point(v));
      const Eigen::Vector3d offset(rng.symmetric(), rng.symmetric(), rng.symmetric());
      const double before = fan(v, n_before);
      const auto q = all.closest_point(StressKernel::Point_3(old.x() + o.jitter * target * offset.x(),
                                                             old.y() + o.jitter * target * offset.y(),
                                                             old.z() + o.jitter * target * offset.z()));
      sm.point(v) = q;
      bool ok = fan(v, n_after) >= std::min(floor_angle, before);
      for (size_t k = 0; ok && k < n_after.size(); ++k)
        ok = n_after[k].dot(n_before[k]) > 0.5 * n_after[k].norm() * n_before[k].norm();
      if (!ok) sm.point(v) = StressKernel::Point_3(old.x(), old.y(), old.z());
    }
  }
  if (o.smooth) onto_phong_surface(source, all, sm, o.sharp_angle_deg);
  // UVs: each corner from the source face (of its face's patch) nearest to the vertex, unless
  // that lands across a UV seam running through the patch (a cylinder cut once is one patch):
  // then from the source face under the face's centre, extrapolated.
  std::map<int, std::unique_ptr<Tree>> trees;
  for (auto& [id, faces] : source_patch) {
    trees[id] = std::make_unique<Tree>(faces.begin(), faces.end(), src);
    trees[id]->accelerate_distance_queries();
  }
  TriMesh out;
  std::map<std::pair<uint32_t, std::array<double, 2>>, uint32_t> index;
  for (FaceId f : sm.faces()) {
    std::array<uint32_t, 3> tri{};
    int k = 0;
    const auto tree = trees.find(patch[f]);
    auto uv_in = [&](FaceId sf, const Eigen::Vector3d& p) {
      const auto cs = source.corners(sf);
      const auto vs = source.vertices(sf);
      const Eigen::Vector3d b = barycentric(p, source.point(vs[0]), source.point(vs[1]), source.point(vs[2]));
      return Eigen::Vector2d(b[0] * source.uv(cs[0]) + b[1] * source.uv(cs[1]) + b[2] * source.uv(cs[2]));
    };
    FaceId centre_face;
    double centre_span = 0;
    if (source.has_uvs() && tree != trees.end()) {
      Eigen::Vector3d c = Eigen::Vector3d::Zero();
      for (VertexId v : CGAL::vertices_around_face(sm.halfedge(f), sm)) c += to_eigen(sm.point(v)) / 3.0;
      centre_face = tree->second->closest_point_and_primitive(StressKernel::Point_3(c.x(), c.y(), c.z())).second;
      const auto cs = source.corners(centre_face);
      for (int i = 0; i < 3; ++i)
        centre_span = std::max(centre_span, (source.uv(cs[size_t(i)]) - source.uv(cs[size_t((i + 1) % 3)])).norm());
    }
    for (HalfedgeId h : CGAL::halfedges_around_face(sm.halfedge(f), sm)) {
      const VertexId v = sm.target(h);
      const Eigen::Vector3d p = to_eigen(sm.point(v));
      Eigen::Vector2d uv = Eigen::Vector2d::Zero();
      if (centre_face != SurfaceMesh::null_face()) {
        const FaceId sf = tree->second->closest_point_and_primitive(sm.point(v)).second;
        const Eigen::Vector2d extrapolated = uv_in(centre_face, p);
        uv = uv_in(sf, p);
        if ((uv - extrapolated).norm() > 4 * centre_span) uv = extrapolated;
      }
      auto [it, fresh] = index.try_emplace({uint32_t(v.idx()), {uv.x(), uv.y()}}, uint32_t(out.positions.size()));
      if (fresh) {
        out.positions.push_back(p);
        if (source.has_uvs()) out.uvs.push_back(uv);
      }
      tri[size_t(k++)] = it->second;
    }
    out.triangles.push_back(tri);
  }
  return out;
}

}  // namespace phellem::bark
