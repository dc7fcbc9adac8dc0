#include "bark/growth/tet_complex.h"

#define TETLIBRARY
#include <tetgen.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <algorithm>
#include <cstdio>
#include <map>

#include "util/errors.h"

namespace phellem::bark {

namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;

K::Point_3 cgal(const Eigen::Vector3d& p) { return {p.x(), p.y(), p.z()}; }

CGAL::Orientation orientation(const TetComplex& c, const std::array<uint32_t, 4>& t) {
  return CGAL::orientation(cgal(c.points[t[0]]), cgal(c.points[t[1]]), cgal(c.points[t[2]]), cgal(c.points[t[3]]));
}

// A closed, consistently oriented surface uses every edge exactly once in each direction.
void require_closed(const TriMesh& m, const std::string& file, const std::string& where) {
  std::map<std::pair<uint32_t, uint32_t>, int> directed;
  for (const auto& t : m.triangles)
    for (int e = 0; e < 3; ++e) ++directed[{t[size_t(e)], t[size_t(e + 1) % 3]}];
  for (const auto& [edge, n] : directed) {
    const auto back = directed.find({edge.second, edge.first});
    if (n != 1 || back == directed.end() || back->second != 1)
      throw UserError(file, where,
                      "the surface to grow must be closed and consistently oriented: its edge between vertices " +
                          std::to_string(edge.first) + " and " + std::to_string(edge.second) + " is used " +
                          std::to_string(n) + " time(s) one way and " +
                          std::to_string(back == directed.end() ? 0 : back->second) + " the other");
  }
  if (m.triangles.empty()) throw UserError(file, where, "the surface to grow has no triangles");
}

// TetGen's arrays are freed by tetgenio's destructor with delete[], so they are made with new[]
// (the one place in the project that allocates so).
template <class T>
T* tetgen_array(size_t n) {
  return new T[std::max<size_t>(1, n)];
}

}  // namespace

std::vector<std::array<uint32_t, 3>> TetComplex::interface_faces() const {
  std::map<std::array<uint32_t, 3>, std::pair<size_t, int>> seen;  // sorted face -> (tet, opposite corner)
  std::vector<std::array<uint32_t, 3>> out;
  static constexpr int kFace[4][3] = {{1, 2, 3}, {0, 3, 2}, {0, 1, 3}, {0, 2, 1}};  // outward for a positive tet
  for (size_t t = 0; t < tets.size(); ++t)
    for (int f = 0; f < 4; ++f) {
      std::array<uint32_t, 3> face{tets[t][size_t(kFace[f][0])], tets[t][size_t(kFace[f][1])], tets[t][size_t(kFace[f][2])]};
      std::array<uint32_t, 3> key = face;
      std::sort(key.begin(), key.end());
      const auto it = seen.find(key);
      if (it == seen.end()) {
        seen.emplace(key, std::make_pair(t, f));
        continue;
      }
      const size_t u = it->second.first;
      if (label[t] != label[u]) {
        // Oriented outwards from the inside tetrahedron.
        const size_t in = label[t] ? t : u;
        const int fi = label[t] ? f : it->second.second;
        out.push_back({tets[in][size_t(kFace[fi][0])], tets[in][size_t(kFace[fi][1])], tets[in][size_t(kFace[fi][2])]});
      }
      seen.erase(it);
    }
  std::sort(out.begin(), out.end());
  return out;
}

uint32_t TetComplex::add_point_between(uint32_t a, uint32_t b, double s) {
  const uint32_t m = uint32_t(points.size());
  points.push_back((1 - s) * points[a] + s * points[b]);
  on_interface.push_back(on_interface[a] && on_interface[b]);
  on_box.push_back(on_box[a] && on_box[b]);
  frozen.push_back(frozen[a] && frozen[b]);
  if (!uv.empty()) uv.push_back((1 - s) * uv[a] + s * uv[b]);
  source_vertex.push_back(-1);
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
  require_closed(surface, file, where);
  Eigen::Vector3d lo = surface.positions.front(), hi = lo;
  for (const auto& p : surface.positions) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  const double pad = s.padding * (hi - lo).maxCoeff();
  lo.array() -= pad;
  hi.array() += pad;

  tetgenio in, out;
  const size_t n = surface.positions.size();
  in.numberofpoints = int(n + 8);
  in.pointlist = tetgen_array<REAL>(3 * (n + 8));
  for (size_t i = 0; i < n; ++i)
    for (int k = 0; k < 3; ++k) in.pointlist[3 * i + size_t(k)] = surface.positions[i][k];
  for (int c = 0; c < 8; ++c) {
    const Eigen::Vector3d p((c & 1) ? hi.x() : lo.x(), (c & 2) ? hi.y() : lo.y(), (c & 4) ? hi.z() : lo.z());
    for (int k = 0; k < 3; ++k) in.pointlist[3 * (n + size_t(c)) + size_t(k)] = p[k];
  }
  const int box[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  in.numberoffacets = int(surface.triangles.size() + 6);
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
  for (size_t t = 0; t < surface.triangles.size(); ++t)
    polygon(in.facetlist[t], {int(surface.triangles[t][0]), int(surface.triangles[t][1]), int(surface.triangles[t][2])});
  for (int f = 0; f < 6; ++f)
    polygon(in.facetlist[surface.triangles.size() + size_t(f)],
            {int(n) + box[f][0], int(n) + box[f][1], int(n) + box[f][2], int(n) + box[f][3]});

  // p: a piecewise linear complex; Y: its facets keep their vertices (no Steiner points on the
  // surface); q: quality; A: a region attribute per region the facets enclose; Q: quiet.
  char switches[96];
  if (s.max_volume > 0)
    std::snprintf(switches, sizeof switches, "pYAQq%.6ga%.9g", s.quality, s.max_volume);
  else
    std::snprintf(switches, sizeof switches, "pYAQq%.6g", s.quality);
  try {
    tetrahedralize(switches, &in, &out);
  } catch (int code) {
    throw UserError(file, where,
                    "TetGen cannot tetrahedralize the surface (code " + std::to_string(code) +
                        "; a self-intersecting or degenerate surface?)");
  }

  TetComplex c;
  c.points.resize(size_t(out.numberofpoints));
  for (size_t i = 0; i < c.points.size(); ++i)
    c.points[i] = Eigen::Vector3d(out.pointlist[3 * i], out.pointlist[3 * i + 1], out.pointlist[3 * i + 2]);
  c.tets.resize(size_t(out.numberoftetrahedra));
  c.label.resize(c.tets.size());
  // The region that touches the box is outside; every other region (the surface's inside,
  // several if it has several components) is inside.
  const double outside_attribute = [&] {
    for (size_t t = 0; t < c.tets.size(); ++t)
      for (int k = 0; k < 4; ++k)
        if (size_t(out.tetrahedronlist[4 * t + size_t(k)]) >= n && size_t(out.tetrahedronlist[4 * t + size_t(k)]) < n + 8)
          return out.tetrahedronattributelist[t * size_t(out.numberoftetrahedronattributes)];
    return -1.0;
  }();
  for (size_t t = 0; t < c.tets.size(); ++t) {
    for (int k = 0; k < 4; ++k) c.tets[t][size_t(k)] = uint32_t(out.tetrahedronlist[4 * t + size_t(k)]);
    if (orientation(c, c.tets[t]) == CGAL::NEGATIVE) std::swap(c.tets[t][2], c.tets[t][3]);
    c.label[t] = out.tetrahedronattributelist[t * size_t(out.numberoftetrahedronattributes)] == outside_attribute ? 0 : 1;
  }
  c.on_interface.assign(c.points.size(), 0);
  for (const auto& f : c.interface_faces())
    for (uint32_t v : f) c.on_interface[v] = 1;
  c.on_box.assign(c.points.size(), 0);
  for (size_t i = 0; i < c.points.size(); ++i)
    for (int k = 0; k < 3; ++k)
      if (c.points[i][k] == lo[k] || c.points[i][k] == hi[k]) c.on_box[i] = 1;
  c.frozen.assign(c.points.size(), 0);
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
