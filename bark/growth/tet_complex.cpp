#include "bark/growth/tet_complex.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/intersection.h>
#include <CGAL/Surface_mesh.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <optional>

#include "bark/geometry/uv_seams.h"
#include "bark/growth/growable_surface.h"
#include "bark/growth/outside_lattice.h"
#include "bark/growth/tetgen_process.h"
#include "util/errors.h"

namespace phellem::bark {

namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;

// The corners of a tetrahedron's face opposite corner f, outward for a positive tetrahedron.
constexpr int kFace[4][3] = {{1, 2, 3}, {0, 3, 2}, {0, 1, 3}, {0, 2, 1}};

K::Point_3 cgal(const Eigen::Vector3d& p) { return {p.x(), p.y(), p.z()}; }

CGAL::Orientation orientation(const TetComplex& c, const std::array<uint32_t, 4>& t) {
  return CGAL::orientation(cgal(c.points[t[0]]), cgal(c.points[t[1]]), cgal(c.points[t[2]]), cgal(c.points[t[3]]));
}

// Six times the signed volume a closed mesh encloses (> 0 when its triangles face outwards).
double signed_volume6(const TriMesh& m) {
  double v = 0;
  for (const auto& t : m.triangles) v += m.positions[t[0]].dot(m.positions[t[1]].cross(m.positions[t[2]]));
  return v;
}

using SurfaceMesh = CGAL::Surface_mesh<K::Point_3>;

// The mesh as a CGAL halfedge structure for the exact intersection test; empty when it is not
// a 2-manifold (a vertex whose triangles form more than one fan).
std::optional<SurfaceMesh> surface_mesh(const TriMesh& m) {
  SurfaceMesh sm;
  std::vector<SurfaceMesh::Vertex_index> v;
  v.reserve(m.positions.size());
  for (const auto& p : m.positions) v.push_back(sm.add_vertex(cgal(p)));
  for (const auto& t : m.triangles)
    if (sm.add_face(v[t[0]], v[t[1]], v[t[2]]) == SurfaceMesh::null_face()) return std::nullopt;
  return sm;
}

// Sec. 4.5 needs the growing surface and the obstacles apart at the start (the front meets an
// obstacle by growing into it): any shared point, crossing or one inside the other is an error.
void require_apart(const TriMesh& surface, const std::vector<GrowthObstacle>& obstacles, const std::string& file,
                   const std::string& where) {
  const auto manifold = [&](const TriMesh& m, const std::string& w, const std::string& what) {
    auto sm = surface_mesh(m);
    if (!sm) throw UserError(file, w, what + " must be a 2-manifold (a vertex has triangles in more than one fan)");
    return std::move(*sm);
  };
  namespace PMP = CGAL::Polygon_mesh_processing;
  const SurfaceMesh grow = manifold(surface, where, "the surface to grow");
  std::vector<SurfaceMesh> obs;
  for (size_t i = 0; i < obstacles.size(); ++i) {
    obs.push_back(manifold(obstacles[i].mesh, obstacles[i].where, "an obstacle"));
    const auto bounded = PMP::parameters::do_overlap_test_of_bounded_sides(true);
    if (PMP::do_intersect(grow, obs[i], bounded, PMP::parameters::default_values()))
      throw UserError(file, obstacles[i].where,
                      "the obstacle touches, intersects, contains or lies inside the surface to grow at " + where +
                          " (obstacles must be apart from the surface at the start; the surface grows into them)");
    for (size_t j = 0; j < i; ++j)
      if (PMP::do_intersect(obs[j], obs[i], bounded, PMP::parameters::default_values()))
        throw UserError(file, obstacles[i].where,
                        "the obstacle touches, intersects, contains or lies inside the obstacle at " + obstacles[j].where +
                            " (obstacles must be apart from each other)");
  }
}


// TetGen's arrays are freed by tetgenio's destructor with delete[], so they are made with new[]
// (the one place in the project that allocates so).
template <class T>
T* tetgen_array(size_t n) {
  return new T[std::max<size_t>(1, n)];
}

}  // namespace

std::vector<std::array<uint32_t, 3>> TetComplex::interface_faces() const { return boundary_faces(kInside); }

namespace {

// TetComplex::boundary_faces over the faces whose corners all pass `take`.
template <class Take>
std::vector<std::array<uint32_t, 3>> faces_between(const TetComplex& c, uint8_t which, Take take) {
  // Every face of every tetrahedron by its sorted corners, sorted: the two tetrahedra sharing a
  // face are next to each other (a sort of flat records, several times faster than a map over
  // the hundreds of thousands of tetrahedra of a grown volume).
  struct Record {
    std::array<uint32_t, 3> key;
    uint32_t tet;
    int face;
  };
  std::vector<Record> records;
  for (size_t t = 0; t < c.tets.size(); ++t) {
    const auto& T = c.tets[t];
    const bool taken[4] = {take(T[0]), take(T[1]), take(T[2]), take(T[3])};
    if (int(taken[0]) + int(taken[1]) + int(taken[2]) + int(taken[3]) < 3) continue;
    for (int f = 0; f < 4; ++f) {
      if (!taken[kFace[f][0]] || !taken[kFace[f][1]] || !taken[kFace[f][2]]) continue;
      std::array<uint32_t, 3> key{T[size_t(kFace[f][0])], T[size_t(kFace[f][1])], T[size_t(kFace[f][2])]};
      std::sort(key.begin(), key.end());
      records.push_back({key, uint32_t(t), f});
    }
  }
  std::sort(records.begin(), records.end(), [](const Record& a, const Record& b) { return a.key < b.key; });
  std::vector<std::array<uint32_t, 3>> out;
  for (size_t i = 0; i + 1 < records.size(); ++i) {
    const Record &r = records[i], &q = records[i + 1];
    if (r.key != q.key) continue;
    if ((c.label[r.tet] == which) != (c.label[q.tet] == which)) {
      // Oriented outwards from the tetrahedron labelled `which`.
      const Record& in = c.label[r.tet] == which ? r : q;
      const auto& T = c.tets[in.tet];
      out.push_back({T[size_t(kFace[in.face][0])], T[size_t(kFace[in.face][1])], T[size_t(kFace[in.face][2])]});
    }
    ++i;  // a face has two tetrahedra at most
  }
  std::sort(out.begin(), out.end());
  return out;
}

}  // namespace

std::vector<std::array<uint32_t, 3>> TetComplex::boundary_faces(uint8_t which) const {
  return faces_between(*this, which, [](uint32_t) { return true; });
}

std::vector<std::array<uint32_t, 3>> TetComplex::boundary_faces(uint8_t which, const std::vector<uint8_t>& corner) const {
  return faces_between(*this, which, [&](uint32_t v) { return v < corner.size() && corner[v] != 0; });
}

Eigen::Vector2d TetComplex::uv_between(const Eigen::Vector2d& a, const Eigen::Vector2d& b, double s) {
  return a + s * wrapped_uv_delta(a, b);
}

uint32_t TetComplex::add_point_between(uint32_t a, uint32_t b, double s) {
  const uint32_t m = uint32_t(points.size());
  points.push_back((1 - s) * points[a] + s * points[b]);
  on_interface.push_back(on_interface[a] && on_interface[b]);
  on_box.push_back(on_box[a] && on_box[b]);
  frozen.push_back(frozen[a] && frozen[b]);
  if (!uv.empty()) uv.push_back(uv_between(uv[a], uv[b], s));
  if (!speed.empty()) speed.push_back(float((1 - s) * double(speed[a]) + s * double(speed[b])));
  if (!direction.empty()) direction.push_back(float(1 - s) * direction[a] + float(s) * direction[b]);
  source_vertex.push_back(-1);
  if (!on_crack.empty()) on_crack.push_back(on_crack[a] && on_crack[b]);
  parents.resize(m, {kNoParent, kNoParent});
  parents.push_back({a, b});
  return m;
}

double TetComplex::volume(uint8_t which) const {
  double v = 0;
  for (size_t t = 0; t < tets.size(); ++t)
    if (label[t] == which) {
      const Eigen::Vector3d &a = points[tets[t][0]], &b = points[tets[t][1]], &c = points[tets[t][2]], &d = points[tets[t][3]];
      v += (b - a).cross(c - a).dot(d - a) / 6.0;
    }
  return v;
}

long TetComplex::first_inverted() const {
  for (size_t t = 0; t < tets.size(); ++t)
    if (orientation(*this, tets[t]) != CGAL::POSITIVE) return long(t);
  return -1;
}

TetComplex tetrahedralize_surface(const TriMesh& surface, const TetSettings& s, const std::string& file,
                                  const std::string& where) {
  return tetrahedralize_surface(surface, {}, s, file, where);
}

TetComplex tetrahedralize_surface(const TriMesh& surface, const std::vector<GrowthObstacle>& obstacles,
                                  const TetSettings& s, const std::string& file, const std::string& where) {
  require_closed(surface, file, where);
  for (const auto& o : obstacles) require_closed(o.mesh, file, o.where, "an obstacle");
  if (!obstacles.empty()) require_apart(surface, obstacles, file, where);

  // The box: the surface padded by `padding` × its largest extent, grown to hold every obstacle
  // with the same padding around it (TetSettings::padding).
  Eigen::Vector3d lo = surface.positions.front(), hi = lo;
  for (const auto& p : surface.positions) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  const double pad = s.padding * (hi - lo).maxCoeff();
  for (const auto& o : obstacles)
    for (const auto& p : o.mesh.positions) {
      lo = lo.cwiseMin(p);
      hi = hi.cwiseMax(p);
    }
  lo.array() -= pad;
  hi.array() += pad;

  // The input points: the surface's, then each obstacle's (first[k] is obstacle k's first),
  // then the box's 8 corners.
  const size_t n = surface.positions.size();
  std::vector<size_t> first{n};
  for (const auto& o : obstacles) first.push_back(first.back() + o.mesh.positions.size());
  const size_t n_all = first.back();
  size_t n_triangles = surface.triangles.size();
  for (const auto& o : obstacles) n_triangles += o.mesh.triangles.size();

  // Graded lattice points around the surface and the obstacles (outside_lattice.h), after the
  // box corners, from TetSettings::lattice × the padding away.
  std::vector<Eigen::Vector3d> lattice;
  if (s.lattice > 0) {
    std::vector<const TriMesh*> meshes{&surface};
    for (const auto& o : obstacles) meshes.push_back(&o.mesh);
    lattice = outside_lattice(meshes, lo, hi, s.lattice * pad);
  }

  tetgenio in;
  in.numberofpoints = int(n_all + 8 + lattice.size());
  in.pointlist = tetgen_array<REAL>(3 * (n_all + 8 + lattice.size()));
  auto set_point = [&](size_t i, const Eigen::Vector3d& p) {
    for (int k = 0; k < 3; ++k) in.pointlist[3 * i + size_t(k)] = p[k];
  };
  for (size_t i = 0; i < n; ++i) set_point(i, surface.positions[i]);
  for (size_t k = 0; k < obstacles.size(); ++k)
    for (size_t i = 0; i < obstacles[k].mesh.positions.size(); ++i) set_point(first[k] + i, obstacles[k].mesh.positions[i]);
  for (int c = 0; c < 8; ++c)
    set_point(n_all + size_t(c), Eigen::Vector3d((c & 1) ? hi.x() : lo.x(), (c & 2) ? hi.y() : lo.y(), (c & 4) ? hi.z() : lo.z()));
  for (size_t i = 0; i < lattice.size(); ++i) set_point(n_all + 8 + i, lattice[i]);
  const int box[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  in.numberoffacets = int(n_triangles + 6);
  in.facetlist = tetgen_array<tetgenio::facet>(size_t(in.numberoffacets));
  auto polygon = [&](tetgenio::facet& f, std::initializer_list<int> corners) {
    f.numberofpolygons = 1;
    f.polygonlist = tetgen_array<tetgenio::polygon>(1);
    f.numberofholes = 0;
    f.holelist = nullptr;
    f.polygonlist[0].numberofvertices = int(corners.size());
    f.polygonlist[0].vertexlist = tetgen_array<int>(corners.size());
    std::copy(corners.begin(), corners.end(), f.polygonlist[0].vertexlist);
  };
  // Each input triangle (sorted corners) -> its owner (−1: the surface, k: obstacle k) and its
  // corners oriented towards the owner's outside, for the labels below.
  std::map<std::array<uint32_t, 3>, std::pair<int, std::array<uint32_t, 3>>> owner;
  size_t facet = 0;
  auto add_triangles = [&](const TriMesh& m, size_t offset, int who, bool flip) {
    for (const auto& t : m.triangles) {
      std::array<uint32_t, 3> f{uint32_t(offset + t[0]), uint32_t(offset + t[1]), uint32_t(offset + t[2])};
      polygon(in.facetlist[facet++], {int(f[0]), int(f[1]), int(f[2])});
      if (flip) std::swap(f[1], f[2]);
      std::array<uint32_t, 3> key = f;
      std::sort(key.begin(), key.end());
      owner.emplace(key, std::make_pair(who, f));
    }
  };
  add_triangles(surface, 0, -1, false);
  for (size_t k = 0; k < obstacles.size(); ++k)
    add_triangles(obstacles[k].mesh, first[k], int(k), signed_volume6(obstacles[k].mesh) < 0);
  for (int f = 0; f < 6; ++f)
    polygon(in.facetlist[facet++], {int(n_all) + box[f][0], int(n_all) + box[f][1], int(n_all) + box[f][2], int(n_all) + box[f][3]});

  // p: a piecewise linear complex; Y: its facets keep their vertices (no Steiner points on the
  // surface); q: quality; A: a region attribute per region the facets enclose; Q: quiet.
  char switches[96];
  if (s.max_volume > 0)
    std::snprintf(switches, sizeof switches, "pYAQq%.6ga%.9g", s.quality, s.max_volume);
  else
    std::snprintf(switches, sizeof switches, "pYAQq%.6g", s.quality);
  TetgenMesh out;
  try {
    out = tetrahedralize_in_child(switches, in, s.time_limit);
  } catch (const TetgenFailure& e) {
    const bool late = e.timed_out();
    throw UserError(file, where,
                    "TetGen cannot tetrahedralize the surface" + std::string(obstacles.empty() ? "" : " and its obstacles") +
                        " (" + e.what() +
                        (late ? "; \"tetrahedra\": {\"time_limit\"} raises the limit, or the surface may be degenerate)"
                              : "; a self-intersecting or degenerate surface?)"));
  }

  TetComplex c;
  c.points.resize(out.points.size() / 3);
  for (size_t i = 0; i < c.points.size(); ++i)
    c.points[i] = Eigen::Vector3d(out.points[3 * i], out.points[3 * i + 1], out.points[3 * i + 2]);
  c.tets.resize(out.tets.size() / 4);
  c.label.resize(c.tets.size());
  for (size_t t = 0; t < c.tets.size(); ++t) {
    for (int k = 0; k < 4; ++k) c.tets[t][size_t(k)] = uint32_t(out.tets[4 * t + size_t(k)]);
    if (orientation(c, c.tets[t]) == CGAL::NEGATIVE) std::swap(c.tets[t][2], c.tets[t][3]);
  }
  // Labels per region (TetGen numbers the regions the facets enclose): the region that touches
  // the box is outside; a region on the inner side of an obstacle's triangle (the side its
  // outward orientation faces away from, decided by the exact predicate) is that obstacle's;
  // every other region (the surface's inside, several if it has several components) is inside.
  const size_t n_attributes = size_t(out.attributes_per_tet);
  auto attribute = [&](size_t t) { return out.attributes[t * n_attributes]; };
  std::map<double, uint8_t> region_label;
  for (size_t t = 0; t < c.tets.size(); ++t) {
    for (uint32_t v : c.tets[t])
      if (v >= n_all && v < n_all + 8) region_label[attribute(t)] = TetComplex::kOutside;
    for (int f = 0; f < 4; ++f) {
      std::array<uint32_t, 3> key{c.tets[t][size_t(kFace[f][0])], c.tets[t][size_t(kFace[f][1])], c.tets[t][size_t(kFace[f][2])]};
      std::sort(key.begin(), key.end());
      if (key[0] < n || key[2] >= n_all) continue;  // not all three an obstacle's points: no obstacle triangle
      const auto it = owner.find(key);
      if (it == owner.end() || it->second.first < 0) continue;
      const auto& [a, b, d] = it->second.second;
      const uint32_t opposite = c.tets[t][size_t(f)];
      if (CGAL::orientation(cgal(c.points[a]), cgal(c.points[b]), cgal(c.points[d]), cgal(c.points[opposite])) ==
          CGAL::NEGATIVE)
        region_label[attribute(t)] = TetComplex::kObstacle;
    }
  }
  for (size_t t = 0; t < c.tets.size(); ++t) {
    const auto it = region_label.find(attribute(t));
    c.label[t] = it == region_label.end() ? TetComplex::kInside : it->second;
  }
  // Switch Y adds no point on the input triangles: the interface's corners are the surface's.
  std::vector<uint8_t> from_surface(c.points.size(), 0);
  std::fill(from_surface.begin(), from_surface.begin() + std::ptrdiff_t(std::min(n, c.points.size())), 1);
  c.on_interface.assign(c.points.size(), 0);
  for (const auto& f : c.boundary_faces(TetComplex::kInside, from_surface))
    for (uint32_t v : f) c.on_interface[v] = 1;
  c.on_box.assign(c.points.size(), 0);
  for (size_t i = 0; i < c.points.size(); ++i)
    for (int k = 0; k < 3; ++k)
      if (c.points[i][k] == lo[k] || c.points[i][k] == hi[k]) c.on_box[i] = 1;
  // Sec. 4.5: obstacles do not grow or give way; every corner of their tetrahedra is fixed.
  c.frozen.assign(c.points.size(), 0);
  for (size_t t = 0; t < c.tets.size(); ++t)
    if (c.label[t] == TetComplex::kObstacle)
      for (uint32_t v : c.tets[t]) c.frozen[v] = 1;
  // TetGen keeps the input points first and in order (switch Y adds none on the facets).
  c.source_vertex.assign(c.points.size(), -1);
  for (size_t i = 0; i < n; ++i) c.source_vertex[i] = int32_t(i);
  if (!surface.uvs.empty()) {
    c.uv.assign(c.points.size(), Eigen::Vector2d::Zero());
    for (size_t i = 0; i < n; ++i) c.uv[i] = surface.uvs[i].cast<double>();
  }
  return c;
}

}  // namespace phellem::bark
