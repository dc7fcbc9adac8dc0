#include "bark/geometry/branch_junction.h"

#include <CGAL/AABB_face_graph_triangle_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/Polygon_mesh_processing/compute_normal.h>
#include <CGAL/Polygon_mesh_processing/corefinement.h>
#include <CGAL/Polygon_mesh_processing/detect_features.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Polygon_mesh_processing/orientation.h>
#include <CGAL/Polygon_mesh_processing/remesh.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <stdexcept>
#include <tuple>
#include <vector>

#include "bark/geometry/canonical_surface_mesh.h"
#include "bark/geometry/procedural_meshes.h"
#include "util/random.h"

namespace phellem::bark {

namespace {

namespace PMP = CGAL::Polygon_mesh_processing;
using Point = StressKernel::Point_3;
using Tree = CGAL::AABB_tree<CGAL::AABB_traits<StressKernel, CGAL::AABB_face_graph_triangle_primitive<SurfaceMesh>>>;

constexpr double kPi = 3.141592653589793;
// Edges around the branch at the least: fewer, and the remeshed branch is a prism.
constexpr int kMinEdgesAroundBranch = 8;
// The fewest sides of the two cylinders that are united (the remeshing projects onto them):
// the polygon's area is within 1.1 % of the circle's.
constexpr int kMinInputSides = 24;

Point to_point(const Eigen::Vector3d& p) { return {p.x(), p.y(), p.z()}; }

// The branch's frame: its base on the trunk's axis, its axis leaving towards +X.
struct BranchFrame {
  Eigen::Vector3d base, axis;
};
BranchFrame branch_frame(const BranchJunctionParams& p) {
  const double a = p.branch_angle_deg * kPi / 180;
  return {Eigen::Vector3d(0, p.branch_height * p.height, 0), Eigen::Vector3d(std::sin(a), std::cos(a), 0)};
}

// The area of the junction's surface, about (the trunk's, plus the branch's outside it).
double surface_area(const BranchJunctionParams& p) {
  const double a = p.branch_angle_deg * kPi / 180, outside = p.branch_length - p.radius / std::sin(a);
  return 2 * kPi * p.radius * (p.height + p.radius) + 2 * kPi * p.branch_radius * outside +
         kPi * p.branch_radius * p.branch_radius;
}

// The edge of equilateral triangles that tile `area` with `triangles` of them.
double edge_for(double area, double triangles) { return std::sqrt(4 * area / (std::sqrt(3.0) * triangles)); }

// A capped cylinder of `radius` from `base` along `axis` for `length`, welded, its vertices
// about `edge` apart: the remeshing then mostly splits and flips (collapsing a finer input
// down to the edge converges slowly, and the count it gives is hard to predict).
SurfaceMesh capped_cylinder(double radius, double length, const Eigen::Vector3d& base, const Eigen::Vector3d& axis, double edge,
                            double turn) {
  const int sides = std::clamp(int(std::lround(2 * kPi * radius / edge)), kMinInputSides, 1024);
  TriMesh m = log_mesh(radius, length, sides, std::max(1, int(std::lround(length / edge))), 0.0, 0);
  // Turned about its axis by an odd fraction of a side, so that the two polygons' vertex
  // columns do not meet each other's edges exactly (at 90° the trunk's column at +X and the
  // branch's top and bottom lines did, and corefinement made zero-area faces there).
  const Eigen::Quaterniond q = Eigen::Quaterniond::FromTwoVectors(Eigen::Vector3d::UnitY(), axis) *
                               Eigen::Quaterniond(Eigen::AngleAxisd(turn * 2 * kPi / sides, Eigen::Vector3d::UnitY()));
  for (auto& x : m.positions) x = base + q * x;
  return welded_surface_mesh(m);
}

// Distance from p to the closed cylinder of `radius` from `base` along unit `axis` for
// `length`, and whether p is nearer its end cap(s) than its side.
struct CylinderDistance {
  double distance;
  bool on_cap;
};
CylinderDistance cylinder_distance(const Eigen::Vector3d& p, const Eigen::Vector3d& base, const Eigen::Vector3d& axis,
                                   double radius, double length) {
  const double t = (p - base).dot(axis);
  const double rho = (p - base - t * axis).norm();
  const double dr = rho - radius, dt = std::max(-t, t - length);
  if (dr <= 0 && dt <= 0) return {std::min(-dr, -dt), -dt < -dr};
  return {std::hypot(std::max(dr, 0.0), std::max(dt, 0.0)), dt > dr};
}

// A part's texture coordinates at p: u = angle about the axis / 2π from the +Z side (right
// hand about the axis, seam at −Z), v = metres along the axis / `scale`; on an end cap v
// continues by the distance inwards from the rim. `v0` is v at the base.
Eigen::Vector2d part_uv(const Eigen::Vector3d& p, const Eigen::Vector3d& base, const Eigen::Vector3d& axis, double radius,
                        double length, double scale, double v0) {
  const Eigen::Vector3d ea = Eigen::Vector3d::UnitZ(), eb = axis.cross(ea);
  const Eigen::Vector3d d = p - base;
  const double t = d.dot(axis);
  const Eigen::Vector3d radial = d - t * axis;
  const double u = (std::atan2(radial.dot(eb), radial.dot(ea)) + kPi) / (2 * kPi);
  const CylinderDistance cd = cylinder_distance(p, base, axis, radius, length);
  double v = t;
  if (cd.on_cap) v = t < length / 2 ? -(radius - radial.norm()) : length + (radius - radial.norm());
  return {u, v0 + v / scale};
}

// Sharp rims (the end caps) and the junction crease, flagged for the remeshing.
void flag_features(SurfaceMesh& m, SurfaceMesh::Property_map<EdgeId, bool>& flag) {
  auto sharp = m.add_property_map<EdgeId, bool>("e:branch_junction_sharp", false).first;
  PMP::detect_sharp_edges(m, 45.0, sharp);
  for (EdgeId e : m.edges()) flag[e] = flag[e] || sharp[e];
  m.remove_property_map(sharp);
}

void require(bool ok, const std::string& what) {
  if (!ok) throw std::runtime_error("branch junction: " + what);
}

// Vertices away from the features moved in their tangent plane by up to jitter × edge,
// back onto `input`; a move that would turn or squash an incident face is not made. In
// vertex order, each vertex's draw a function of (seed, vertex), so the result is
// deterministic.
void jitter_vertices(SurfaceMesh& m, const SurfaceMesh::Property_map<EdgeId, bool>& feature, const SurfaceMesh& input,
                     double jitter, double edge, uint64_t seed) {
  if (jitter <= 0) return;
  Tree tree(faces(input).first, faces(input).second, input);
  tree.accelerate_distance_queries();
  auto face_normal = [&](FaceId f, VertexId moved, const Eigen::Vector3d& at) {
    std::array<Eigen::Vector3d, 3> c;
    int k = 0;
    for (VertexId v : CGAL::vertices_around_face(m.halfedge(f), m)) c[size_t(k++)] = v == moved ? at : to_eigen(m.point(v));
    return Eigen::Vector3d((c[1] - c[0]).cross(c[2] - c[0]));
  };
  for (VertexId v : m.vertices()) {
    bool on_feature = false;
    for (auto h : CGAL::halfedges_around_target(m.halfedge(v), m)) on_feature = on_feature || feature[m.edge(h)];
    if (on_feature) continue;
    const auto n = PMP::compute_vertex_normal(v, m);
    const Eigen::Vector3d normal(n.x(), n.y(), n.z());
    const Eigen::Vector3d t1 = normal.unitOrthogonal(), t2 = normal.cross(t1);
    StreamRng rng(seed, v.idx(), 0);
    const double a = rng.symmetric(), b = rng.symmetric();
    const Eigen::Vector3d from = to_eigen(m.point(v));
    const Eigen::Vector3d to = to_eigen(tree.closest_point(to_point(from + jitter * edge * (a * t1 + b * t2))));
    bool fine = true;
    for (FaceId f : CGAL::faces_around_target(m.halfedge(v), m)) {
      if (f == SurfaceMesh::null_face()) continue;
      const Eigen::Vector3d before = face_normal(f, v, from), after = face_normal(f, v, to);
      fine = fine && after.dot(before) > 0.8 * before.norm() * after.norm() && after.norm() > 0.3 * before.norm();
    }
    if (fine) m.point(v) = to_point(to);
  }
}

// The union's polygons are inscribed in the cylinders, and the remeshing projects onto them:
// the sides' vertices are moved out onto the round cylinders (and the end caps' rims onto their
// circles), so the surface is as round as its edges allow. The junction crease stays where
// the polygons meet (at most a polygon's sagitta, ~0.5 % of the radius, inside the true curve).
// Returns the crease's vertices (flags by vertex index).
std::vector<char> snap_to_cylinders(SurfaceMesh& m, const SurfaceMesh::Property_map<EdgeId, bool>& feature,
                                    const BranchJunctionParams& p) {
  const BranchFrame frame = branch_frame(p);
  std::vector<char> crease(m.number_of_vertices(), 0);
  for (VertexId v : m.vertices()) {
    const Eigen::Vector3d x = to_eigen(m.point(v));
    const CylinderDistance trunk = cylinder_distance(x, Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitY(), p.radius, p.height);
    const CylinderDistance branch = cylinder_distance(x, frame.base, frame.axis, p.branch_radius, p.branch_length);
    const bool on_branch = branch.distance < trunk.distance;
    const Eigen::Vector3d base = on_branch ? frame.base : Eigen::Vector3d::Zero();
    const Eigen::Vector3d axis = on_branch ? frame.axis : Eigen::Vector3d::UnitY();
    const double radius = on_branch ? p.branch_radius : p.radius, length = on_branch ? p.branch_length : p.height;
    const double t = (x - base).dot(axis);
    const bool in_cap_plane = std::abs(t) < 1e-9 * length || std::abs(t - length) < 1e-9 * length;
    bool on_feature = false;
    for (auto h : CGAL::halfedges_around_target(m.halfedge(v), m)) on_feature = on_feature || feature[m.edge(h)];
    // Cap vertices stay (they are on their plane) but for the rim; crease vertices stay.
    crease[v.idx()] = on_feature && !in_cap_plane ? 1 : 0;
    if (in_cap_plane != on_feature) continue;
    const Eigen::Vector3d radial = x - base - t * axis;
    if (radial.norm() < 0.5 * radius) continue;
    m.point(v) = to_point(base + t * axis + radial * (radius / radial.norm()));
  }
  return crease;
}

// The junction's crease rounded into a fillet, as wood fills the crotch of a branch: the
// vertices within `rings` edges of the crease are smoothed towards the mean of their
// neighbours (umbrella operator, Jacobi steps, so the result does not depend on the order),
// fully on the crease and less with each ring out. Without it, the concave crease is where
// the growing surface meets itself first and freezes in a pit.
void fillet_crease(SurfaceMesh& m, const std::vector<char>& crease, int rings, int iterations) {
  const size_t n = m.number_of_vertices();
  std::vector<int> ring(n, rings);
  std::vector<VertexId> front;
  for (VertexId v : m.vertices())
    if (crease[v.idx()]) {
      ring[v.idx()] = 0;
      front.push_back(v);
    }
  for (int r = 1; r < rings && !front.empty(); ++r) {
    std::vector<VertexId> next;
    for (VertexId v : front)
      for (VertexId w : CGAL::vertices_around_target(m.halfedge(v), m))
        if (ring[w.idx()] > r) {
          ring[w.idx()] = r;
          next.push_back(w);
        }
    front.swap(next);
  }
  std::vector<Eigen::Vector3d> moved(n);
  for (int it = 0; it < iterations; ++it) {
    for (VertexId v : m.vertices()) {
      moved[v.idx()] = to_eigen(m.point(v));
      if (ring[v.idx()] >= rings) continue;
      Eigen::Vector3d mean = Eigen::Vector3d::Zero();
      int k = 0;
      for (VertexId w : CGAL::vertices_around_target(m.halfedge(v), m)) {
        mean += to_eigen(m.point(w));
        ++k;
      }
      const double weight = 0.5 * (1.0 - double(ring[v.idx()]) / rings);
      moved[v.idx()] += weight * (mean / k - moved[v.idx()]);
    }
    for (VertexId v : m.vertices()) m.point(v) = to_point(moved[v.idx()]);
  }
}

// The union of the trunk and the branch (their polygons about `edge` apart), its features
// flagged in "e:junction", and the same remeshed to `edge`.
struct RemeshedUnion {
  SurfaceMesh input, remeshed;
};
RemeshedUnion remeshed_union(const BranchJunctionParams& p, double edge) {
  const BranchFrame frame = branch_frame(p);
  SurfaceMesh trunk = capped_cylinder(p.radius, p.height, Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitY(), edge,
                                      0.381966);  // (3 − √5) / 2
  SurfaceMesh branch = capped_cylinder(p.branch_radius, p.branch_length, frame.base, frame.axis, edge, 0.618034);
  SurfaceMesh united;
  auto crease = united.add_property_map<EdgeId, bool>("e:branch_junction", false).first;
  require(PMP::corefine_and_compute_union(trunk, branch, united, CGAL::parameters::default_values(),
                                          CGAL::parameters::default_values(), CGAL::parameters::edge_is_constrained_map(crease)),
          "CGAL's union of the trunk and the branch is not a manifold surface");
  // Corefinement numbers its output by allocation addresses: rebuilt in an order of positions.
  auto canonical_union = canonical(united, crease);
  require(bool(canonical_union), "the union's faces do not make a manifold surface");
  RemeshedUnion out{std::move(*canonical_union), {}};
  auto feature = out.input.property_map<EdgeId, bool>("e:junction").first;
  flag_features(out.input, feature);
  out.remeshed = out.input;
  feature = out.remeshed.property_map<EdgeId, bool>("e:junction").first;
  PMP::isotropic_remeshing(faces(out.remeshed), edge, out.remeshed,
                           CGAL::parameters::number_of_iterations(5).edge_is_constrained_map(feature).relax_constraints(true));
  out.remeshed.collect_garbage();
  return out;
}

}  // namespace

std::optional<BranchJunctionProblem> check_branch_junction(const BranchJunctionParams& p) {
  auto problem = [](std::string parameter, std::string what) {
    return std::optional<BranchJunctionProblem>(BranchJunctionProblem{std::move(parameter), std::move(what)});
  };
  auto text = [](double x) {
    char s[32];
    std::snprintf(s, sizeof s, "%.4g", x);
    return std::string(s);
  };
  if (!(p.radius > 0)) return problem("radius", "radius must be > 0");
  if (!(p.height > 0)) return problem("height", "height must be > 0");
  if (!(p.branch_radius > 0 && p.branch_radius <= 0.9 * p.radius))
    return problem("branch_radius", "branch_radius must lie in (0, 0.9 × radius] = (0, " + text(0.9 * p.radius) + "] m");
  if (!(p.branch_angle_deg >= 20 && p.branch_angle_deg <= 90))
    return problem("branch_angle_deg", "branch_angle_deg must lie in [20, 90] (degrees from the trunk's axis)");
  if (!(p.branch_height > 0 && p.branch_height < 1))
    return problem("branch_height", "branch_height must lie in (0, 1) (fraction of the height)");
  if (!(p.jitter >= 0 && p.jitter <= 0.45))
    return problem("jitter", "jitter must lie in [0, 0.45] (fraction of the edge length)");
  const double a = p.branch_angle_deg * kPi / 180, r = p.branch_radius, R = p.radius, y0 = p.branch_height * p.height;
  // The branch's base cap (on the trunk's axis) inside the trunk, and the top of its cylinder
  // leaving through the trunk's side, each with a margin of a fifth of the branch's radius.
  const double low = y0 - r * std::sin(a), high = y0 + R / std::tan(a) + r / std::sin(a);
  if (low < 0.2 * r || high > p.height - 0.2 * r)
    return problem("branch_height", "the branch must leave through the trunk's side: its base reaches y = " + text(low) +
                                        " m and its top leaves the trunk at y = " + text(high) + " m, both must lie in [" +
                                        text(0.2 * r) + ", " + text(p.height - 0.2 * r) +
                                        "] (move branch_height, raise branch_angle_deg or height, or lower branch_radius)");
  // Its end cap wholly outside the trunk, by a branch radius.
  const double reach = (R + r + r * std::cos(a)) / std::sin(a);
  if (!(p.branch_length >= reach))
    return problem("branch_length", "branch_length must be at least " + text(reach) +
                                        " m here (from the trunk's axis, so that the branch reaches a branch radius past the "
                                        "trunk's side)");
  const int least = branch_junction_least_triangles(p);
  if (p.triangles < least || p.triangles > kBranchJunctionMaxTriangles)
    return problem("triangles", "triangles must lie in [" + std::to_string(least) + ", " +
                                    std::to_string(kBranchJunctionMaxTriangles) + "] here (at least " +
                                    std::to_string(kMinEdgesAroundBranch) + " edges around the branch)");
  return std::nullopt;
}

int branch_junction_least_triangles(const BranchJunctionParams& p) {
  const double edge = 2 * kPi * p.branch_radius / kMinEdgesAroundBranch;
  return int(std::min(1e9, std::ceil(4 * surface_area(p) / (std::sqrt(3.0) * edge * edge))));
}

double branch_junction_volume_estimate(const BranchJunctionParams& p) {
  const double a = p.branch_angle_deg * kPi / 180, r2 = p.branch_radius * p.branch_radius;
  return kPi * p.radius * p.radius * p.height + kPi * r2 * (p.branch_length - p.radius / std::sin(a));
}

TriMesh branch_junction_mesh(const BranchJunctionParams& p) {
  if (const auto problem = check_branch_junction(p)) throw std::invalid_argument(problem->parameter + ": " + problem->what);
  const BranchFrame frame = branch_frame(p);
  const Eigen::Vector3d trunk_base(0, 0, 0), up = Eigen::Vector3d::UnitY();
  // The count an edge gives depends on the shape (the features, the input's spacing, which
  // follows the edge), so the edge is corrected by the count each try gave, and everything
  // built again: up to three tries, the closest kept.
  double edge = edge_for(surface_area(p), p.triangles), best_edge = edge;
  std::optional<RemeshedUnion> best;
  auto off = [&](const RemeshedUnion& u) { return std::abs(std::log(double(u.remeshed.number_of_faces()) / p.triangles)); };
  for (int attempt = 0; attempt < 3; ++attempt) {
    RemeshedUnion u = remeshed_union(p, edge);
    const bool closer = !best || off(u) < off(*best);
    const double factor = std::sqrt(double(u.remeshed.number_of_faces()) / p.triangles);
    if (closer) {
      best = std::move(u);
      best_edge = edge;
    }
    if (off(*best) < 0.05) break;
    edge *= factor;
  }
  edge = best_edge;
  SurfaceMesh& mesh = best->remeshed;
  auto feature = mesh.property_map<EdgeId, bool>("e:junction").first;
  jitter_vertices(mesh, feature, best->input, p.jitter, edge, p.seed);
  fillet_crease(mesh, snap_to_cylinders(mesh, feature, p), 3, 8);
  require(CGAL::is_closed(mesh) && CGAL::is_valid_polygon_mesh(mesh), "the remeshed surface is not a closed 2-manifold");
  require(!PMP::does_self_intersect(mesh), "the remeshed surface intersects itself");
  require(PMP::is_outward_oriented(mesh) && PMP::volume(mesh) > 0, "the remeshed surface is not oriented outwards");
  // Each face takes its UVs from the part it lies on; corners are repeated per (part, turn).
  TriMesh out;
  std::map<std::tuple<uint32_t, int, int>, uint32_t> copy;
  for (FaceId f : mesh.faces()) {
    std::array<VertexId, 3> c;
    std::array<Eigen::Vector3d, 3> x;
    int k = 0;
    for (VertexId v : CGAL::vertices_around_face(mesh.halfedge(f), mesh)) {
      c[size_t(k)] = v;
      x[size_t(k++)] = to_eigen(mesh.point(v));
    }
    const Eigen::Vector3d centre = (x[0] + x[1] + x[2]) / 3;
    const bool on_branch = cylinder_distance(centre, frame.base, frame.axis, p.branch_radius, p.branch_length).distance <
                           cylinder_distance(centre, trunk_base, up, p.radius, p.height).distance;
    std::array<Eigen::Vector2d, 3> uv;
    for (size_t j = 0; j < 3; ++j)
      uv[j] = on_branch ? part_uv(x[j], frame.base, frame.axis, p.branch_radius, p.branch_length, p.height, 0)
                        : part_uv(x[j], trunk_base, up, p.radius, p.height, p.height, 0);
    const double lo = std::min({uv[0].x(), uv[1].x(), uv[2].x()}), hi = std::max({uv[0].x(), uv[1].x(), uv[2].x()});
    std::array<uint32_t, 3> tri;
    for (size_t j = 0; j < 3; ++j) {
      const int turn = hi - lo > 0.5 && uv[j].x() < 0.5 ? 1 : 0;  // a face across the seam: its low side one turn on
      const auto [it, fresh] = copy.try_emplace({uint32_t(c[j].idx()), on_branch ? 1 : 0, turn}, uint32_t(out.positions.size()));
      if (fresh) {
        out.positions.push_back(x[j]);
        out.uvs.push_back(uv[j] + Eigen::Vector2d(turn, 0));
      }
      tri[j] = it->second;
    }
    out.triangles.push_back(tri);
  }
  return out;
}

}  // namespace phellem::bark
