#include "bark/growth/volume_remesh.h"

#include <algorithm>

#include "bark/growth/tet_adjacency.h"
#include "util/errors.h"

namespace phellem::bark {

namespace {

// A face rotated to start at its smallest point (its orientation kept).
std::array<uint32_t, 3> rotated(std::array<uint32_t, 3> f) {
  std::rotate(f.begin(), std::min_element(f.begin(), f.end()), f.end());
  return f;
}

// The faces each rotated, sorted.
std::vector<std::array<uint32_t, 3>> canonical(std::vector<std::array<uint32_t, 3>> faces) {
  for (auto& f : faces) f = rotated(f);
  std::sort(faces.begin(), faces.end());
  return faces;
}

}  // namespace

bool retetrahedralize(TetComplex& c, const std::vector<GrowthObstacle>& obstacles, const TetSettings& settings,
                      const std::string& file, const std::string& where) {
  const auto faces = c.boundary_faces(TetComplex::kInside, c.on_interface);
  std::vector<uint32_t> kept;  // the interface points, ascending: TetGen's first points, in order
  for (uint32_t p = 0; p < c.points.size(); ++p)
    if (c.on_interface[p]) kept.push_back(p);
  std::vector<uint32_t> local(c.points.size(), 0);
  TriMesh surface;
  for (uint32_t i = 0; i < kept.size(); ++i) {
    local[kept[i]] = i;
    surface.positions.push_back(c.points[kept[i]]);
  }
  for (const auto& f : faces) surface.triangles.push_back({local[f[0]], local[f[1]], local[f[2]]});
  TetComplex fresh;
  try {
    fresh = tetrahedralize_surface(surface, obstacles, settings, file, where);
  } catch (const UserError&) {
    return false;  // TetGen refuses the interface as it is (it touches itself or an obstacle)
  }

  // Where each of TetGen's points goes: the interface points where they were, the others into
  // the slots of the old non-interface points (ascending), then appended.
  std::vector<uint32_t> index(fresh.points.size());
  uint32_t next_free = 0, next_new = uint32_t(c.points.size());
  for (uint32_t k = 0; k < fresh.points.size(); ++k) {
    if (k < kept.size()) {
      index[k] = kept[k];
      continue;
    }
    while (next_free < c.points.size() && c.on_interface[next_free]) ++next_free;
    index[k] = next_free < c.points.size() ? next_free++ : next_new++;
  }
  TetComplex out = c;
  const size_t n = std::max<size_t>(next_new, c.points.size());
  out.points.resize(n);
  out.on_interface.resize(n);
  out.on_box.resize(n);
  out.frozen.resize(n);
  out.source_vertex.resize(n);
  if (!out.uv.empty()) out.uv.resize(n);
  if (!out.speed.empty()) out.speed.resize(n);
  if (!out.direction.empty()) out.direction.resize(n);
  if (!out.on_crack.empty()) out.on_crack.resize(n);
  // Every slot that is not an interface point starts as an unused point without attributes.
  for (uint32_t p = 0; p < n; ++p) {
    if (p < c.points.size() && c.on_interface[p]) continue;
    out.on_interface[p] = 0;
    out.on_box[p] = 0;
    out.frozen[p] = 0;
    out.source_vertex[p] = -1;
    if (!out.uv.empty()) out.uv[p] = Eigen::Vector2d::Zero();
    if (!out.speed.empty()) out.speed[p] = 1.0f;
    if (!out.direction.empty()) out.direction[p] = Eigen::Vector3f::Zero();
    if (!out.on_crack.empty()) out.on_crack[p] = 0;
    if (p < out.parents.size()) out.parents[p] = {TetComplex::kNoParent, TetComplex::kNoParent};
  }
  for (uint32_t k = uint32_t(kept.size()); k < fresh.points.size(); ++k) {
    const uint32_t p = index[k];
    out.points[p] = fresh.points[k];
    out.on_box[p] = fresh.on_box[k];
    out.frozen[p] = fresh.frozen[k];  // the obstacles' corners
  }
  out.tets.resize(fresh.tets.size());
  out.label = fresh.label;
  for (size_t t = 0; t < fresh.tets.size(); ++t)
    for (int j = 0; j < 4; ++j) out.tets[t][size_t(j)] = index[fresh.tets[t][size_t(j)]];
  // The labels from the interface as it was, not from TetGen's regions (which call inside
  // whatever the box does not reach, such as a pocket of the outside the front closed over):
  // the tetrahedra connected without crossing an interface face share a label, inside where
  // they lie on the inner side of one of its faces (each oriented outwards from the inside).
  const auto oriented = canonical(faces);
  {
    const TetAdjacency adj(out);
    // 1: the face opposite corner j of t, as the interface has it from t's side outwards (t
    // inside); −1: the other way round (t outside); 0: not an interface face.
    auto side = [&](uint32_t t, int j) {
      const auto& T = out.tets[t];
      const auto f = rotated({T[size_t(kTetFace[j][0])], T[size_t(kTetFace[j][1])], T[size_t(kTetFace[j][2])]});
      if (!out.on_interface[f[0]] || !out.on_interface[f[1]] || !out.on_interface[f[2]]) return 0;  // (the kept points only)
      if (std::binary_search(oriented.begin(), oriented.end(), f)) return 1;
      if (std::binary_search(oriented.begin(), oriented.end(), std::array<uint32_t, 3>{f[0], f[2], f[1]})) return -1;
      return 0;
    };
    std::vector<uint8_t> visited(out.tets.size(), 0);
    std::vector<uint32_t> component, stack;
    for (uint32_t seed = 0; seed < out.tets.size(); ++seed) {
      if (visited[seed] || out.label[seed] == TetComplex::kObstacle) continue;
      component.clear();
      stack.assign(1, seed);
      visited[seed] = 1;
      uint8_t found = TetComplex::kOutside;  // a component no interface face bounds: outside
      while (!stack.empty()) {
        const uint32_t t = stack.back();
        stack.pop_back();
        component.push_back(t);
        for (int j = 0; j < 4; ++j) {
          if (const int sd = side(t, j); sd != 0) {
            found = sd > 0 ? TetComplex::kInside : TetComplex::kOutside;
            continue;
          }
          const long u = adj.across(out, t, j);
          if (u < 0 || visited[size_t(u)] || out.label[size_t(u)] == TetComplex::kObstacle) continue;
          visited[size_t(u)] = 1;
          stack.push_back(uint32_t(u));
        }
      }
      for (uint32_t t : component) out.label[t] = found;
    }
  }
  // Switch Y keeps the interface's triangles unless a point lies on one (a fold of the
  // interface onto itself, which TetGen splits the triangle at): then nothing changes.
  // (A triangle split at a point that was not on the interface loses faces here: no match either.)
  if (canonical(out.boundary_faces(TetComplex::kInside, out.on_interface)) != oriented) return false;
  c = std::move(out);
  return true;
}

}  // namespace phellem::bark
