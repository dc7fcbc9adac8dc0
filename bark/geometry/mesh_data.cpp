#include "bark/geometry/mesh_data.h"

#include <array>
#include <bit>
#include <unordered_map>

namespace phellem {

namespace {
struct FloatTripleHash {
  size_t operator()(const std::array<float, 3>& p) const {
    size_t h = 0;
    for (float x : p) h = h * 0x9E3779B97F4A7C15ull + (x == 0 ? 0u : std::bit_cast<uint32_t>(x));  // -0 == 0
    return h;
  }
};
}  // namespace

std::vector<Vec3f> vertex_normals(const std::vector<Vec3f>& positions, const std::vector<uint32_t>& indices,
                                  bool weld_by_position) {
  // With welding, each vertex accumulates into the first vertex at its position.
  std::vector<uint32_t> rep;
  if (weld_by_position) {
    rep.resize(positions.size());
    std::unordered_map<std::array<float, 3>, uint32_t, FloatTripleHash> first;
    first.reserve(positions.size());
    for (uint32_t i = 0; i < positions.size(); ++i) {
      const Vec3f& p = positions[i];
      rep[i] = first.try_emplace({p.x(), p.y(), p.z()}, i).first->second;
    }
  }
  auto at = [&](uint32_t i) { return rep.empty() ? i : rep[i]; };
  std::vector<Vec3f> n(positions.size(), Vec3f::Zero());
  for (size_t f = 0; f + 2 < indices.size(); f += 3) {
    const uint32_t a = indices[f], b = indices[f + 1], c = indices[f + 2];
    const Vec3f fn = (positions[b] - positions[a]).cross(positions[c] - positions[a]);
    n[at(a)] += fn;
    n[at(b)] += fn;
    n[at(c)] += fn;
  }
  for (uint32_t i = 0; i < n.size(); ++i) {
    if (at(i) != i) continue;
    const float l = n[i].norm();
    n[i] = l > 0 ? Vec3f(n[i] / l) : Vec3f(0, 1, 0);
  }
  if (!rep.empty())
    for (size_t i = 0; i < n.size(); ++i) n[i] = n[rep[i]];
  return n;
}

void compute_vertex_normals(MeshData& m, bool weld_by_position) {
  m.normals = vertex_normals(m.positions, m.indices, weld_by_position);
}

void compute_tangents(MeshData& m) {
  if (m.uvs.size() != m.positions.size()) return;
  std::vector<Vec3f> t(m.positions.size(), Vec3f::Zero()), b(m.positions.size(), Vec3f::Zero());
  for (size_t f = 0; f + 2 < m.indices.size(); f += 3) {
    const uint32_t i0 = m.indices[f], i1 = m.indices[f + 1], i2 = m.indices[f + 2];
    const Vec3f e1 = m.positions[i1] - m.positions[i0], e2 = m.positions[i2] - m.positions[i0];
    const Vec2f d1 = m.uvs[i1] - m.uvs[i0], d2 = m.uvs[i2] - m.uvs[i0];
    const float det = d1.x() * d2.y() - d2.x() * d1.y();
    if (std::abs(det) < 1e-20f) continue;
    const float r = 1.0f / det;
    const Vec3f tu = (e1 * d2.y() - e2 * d1.y()) * r;
    const Vec3f tv = (e2 * d1.x() - e1 * d2.x()) * r;
    for (uint32_t i : {i0, i1, i2}) {
      t[i] += tu;
      b[i] += tv;
    }
  }
  m.tangents.resize(m.positions.size());
  for (size_t i = 0; i < t.size(); ++i) {
    const Vec3f n = m.normals.empty() ? Vec3f(0, 0, 1) : m.normals[i];
    Vec3f tt = t[i] - n * n.dot(t[i]);
    if (tt.squaredNorm() < 1e-20f) tt = Frame(n).s;
    tt.normalize();
    const float w = n.cross(tt).dot(b[i]) < 0.0f ? -1.0f : 1.0f;
    m.tangents[i] = Vec4f(tt.x(), tt.y(), tt.z(), w);
  }
}

}  // namespace phellem
