#include "renderer/material.h"

namespace phellem {

Material compile_material(const MaterialDesc& d, TextureStore& textures) {
  Material m;
  m.type = d.type;
  m.base = d.base_color;
  m.roughness = d.roughness;
  m.f0 = 0.08f * d.specular;
  m.f90 = std::min(1.0f, 2.0f * d.specular);  // specular 0: no coat at all, even at grazing angles
  m.ior = d.ior;
  if (d.type == MaterialType::Emissive) m.emission = d.emission * d.strength;
  m.base_tex = textures.add(d.base_color_texture, {d.where.file, d.where.path + "/base_color_texture"});
  m.rough_tex = textures.add(d.roughness_texture, {d.where.file, d.where.path + "/roughness_texture"});
  m.normal_tex = textures.add(d.normal_texture, {d.where.file, d.where.path + "/normal_texture"});
  return m;
}

BSDF evaluate_bsdf(const Material& m, const TextureStore& tex, const ShadingInput& in, Color* albedo) {
  BSDF b;
  Color base = m.base;
  if (in.base_override)
    base = *in.base_override;
  else if (m.base_tex >= 0)
    base *= tex.rgb(m.base_tex, in.uv, in.footprint, in.primary);
  base = (base * in.base_scale).max(0.0f).min(1.0f);
  float rough = in.roughness_override >= 0 ? in.roughness_override : m.roughness;
  if (m.rough_tex >= 0) rough = std::clamp(rough * tex.scalar(m.rough_tex, in.uv, in.footprint, in.primary), 0.0f, 1.0f);
  b.base = base;
  b.alpha = rough * rough;
  switch (m.type) {
    case MaterialType::Diffuse:
      b.type = BSDF::Type::Diffuse;
      break;
    case MaterialType::Bark:
      // Without a coat (specular 0: F0 = F90 = 0) bark is exactly Lambertian; skip the GGX work.
      b.type = m.f90 > 0 ? BSDF::Type::Bark : BSDF::Type::Diffuse;
      b.f0 = m.f0;
      b.f90 = m.f90;
      break;
    case MaterialType::Conductor:
      b.type = BSDF::Type::Conductor;
      break;
    case MaterialType::Dielectric:
      b.type = BSDF::Type::Dielectric;
      b.eta = m.ior;
      break;
    case MaterialType::Emissive:
      b.type = BSDF::Type::Black;
      base = Color::Zero();
      break;
  }
  if (albedo) *albedo = m.type == MaterialType::Dielectric ? Color::Ones() : base;
  return b;
}

Vec3f apply_normal_map(const Material& m, const TextureStore& tex, const ShadingInput& in, const Vec3f& ns,
                       const Vec4f& tangent) {
  if (m.normal_tex < 0) return ns;
  const Color c = tex.rgb(m.normal_tex, in.uv, in.footprint, in.primary);
  const Vec3f t_local(2 * c[0] - 1, 2 * c[1] - 1, 2 * c[2] - 1);
  Vec3f t = tangent.head<3>();
  t = (t - ns * ns.dot(t));
  if (t.squaredNorm() < 1e-12f) return ns;
  t.normalize();
  const Vec3f bt = ns.cross(t) * (tangent.w() < 0 ? -1.0f : 1.0f);
  const Vec3f n = t * t_local.x() + bt * t_local.y() + ns * std::max(1e-3f, t_local.z());
  return n.normalized();
}

}  // namespace phellem
