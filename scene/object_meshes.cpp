#include "scene/object_meshes.h"

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
