#include "scene/object_meshes.h"

#include <algorithm>
#include <cmath>

namespace phellem {

MeshData plane_mesh(const ObjectDesc& o) {
  const Frame f(o.normal);
  MeshData m;
  const float hx = 0.5f * o.size.x(), hy = 0.5f * o.size.y();
  const Vec2f corners[4] = {{-hx, -hy}, {hx, -hy}, {hx, hy}, {-hx, hy}};
  for (const auto& c : corners) {
    m.positions.push_back(o.point + f.s * c.x() + f.t * c.y());
    m.normals.push_back(o.normal);
    m.uvs.push_back(c / o.uv_scale);
    m.tangents.emplace_back(f.s.x(), f.s.y(), f.s.z(), 1.0f);
  }
  m.indices = {0, 1, 2, 0, 2, 3};
  return m;
}

PatchFrame patch_frame(const ObjectDesc& o) {
  PatchFrame f;
  f.centre = o.point;
  f.normal = o.normal.normalized();
  f.up = (o.up - o.up.dot(f.normal) * f.normal).normalized();
  f.right = f.up.cross(f.normal);  // right, up, normal: right-handed, so the patch faces along +normal
  return f;
}

namespace {

constexpr float kPatchCell = 0.02f;  // m: the dicer's patches on a `patch` object

Vec3f patch_point(const PatchFrame& f, const Vec2f& size, float u, float v) {
  return f.centre + (u - 0.5f) * size.x() * f.right + (v - 0.5f) * size.y() * f.up;
}

}  // namespace

ParametricSurface patch_surface(const ObjectDesc& o, const DisplacementFn& disp) {
  const PatchFrame f = patch_frame(o);
  ParametricSurface s;
  s.position = [f, size = o.size, disp](float u, float v, float* offset) {
    const Vec3f p = patch_point(f, size, u, v);
    const float d = disp ? disp(Vec2f(u, v), p) : 0.0f;
    if (offset) *offset = d;
    return Vec3f(p + d * f.normal);
  };
  s.texcoord = [](float u, float v) { return Vec2f(u, v); };
  s.patches_u = std::clamp(int(std::ceil(o.size.x() / kPatchCell)), 1, 4096);
  s.patches_v = std::clamp(int(std::ceil(o.size.y() / kPatchCell)), 1, 4096);
  return s;
}

MeshData patch_mesh(const ObjectDesc& o, int nu, int nv) {
  const PatchFrame f = patch_frame(o);
  MeshData m;
  for (int j = 0; j <= nv; ++j)
    for (int i = 0; i <= nu; ++i) {
      const float u = float(i) / float(nu), v = float(j) / float(nv);
      m.positions.push_back(patch_point(f, o.size, u, v));
      m.normals.push_back(f.normal);
      m.uvs.emplace_back(u, v);
      m.tangents.emplace_back(f.right.x(), f.right.y(), f.right.z(), 1.0f);
    }
  for (int j = 0; j < nv; ++j)
    for (int i = 0; i < nu; ++i) {
      const uint32_t a = uint32_t(j * (nu + 1) + i), b = a + 1, c = a + uint32_t(nu) + 1, e = c + 1;
      m.indices.insert(m.indices.end(), {a, b, e, a, e, c});
    }
  return m;
}

MeshData sphere_mesh(const Vec3f& c, float r, int nu, int nv) {
  MeshData m;
  for (int j = 0; j <= nv; ++j)
    for (int i = 0; i <= nu; ++i) {
      const float th = kPi * j / nv, ph = kTwoPi * i / nu;
      const Vec3f n(std::sin(th) * std::cos(ph), std::cos(th), std::sin(th) * std::sin(ph));
      m.positions.push_back(c + r * n);
      m.normals.push_back(n);
      m.uvs.emplace_back(float(i) / nu, 1.0f - float(j) / nv);
    }
  for (int j = 0; j < nv; ++j)
    for (int i = 0; i < nu; ++i) {
      const uint32_t a = j * (nu + 1) + i, b = a + 1, d = a + nu + 1, e = d + 1;
      m.indices.insert(m.indices.end(), {a, e, b, a, d, e});
    }
  return m;
}

}  // namespace phellem
