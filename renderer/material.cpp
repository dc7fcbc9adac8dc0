#include "renderer/material.h"

namespace phellem {

namespace {

// A texture through a grown surface's chain of cell levels (Kratt et al., Woodification,
// sec. 4.6; bark/growth/texture_cells.h): level L along an axis repeats the texture 2^L times
// over the same texture coordinates; a fractional level blends the two levels around it, along
// u and v independently (four lookups at most, one where both levels are whole).
template <class T, class Lookup>
T through_cell_levels(const ShadingInput& in, T zero, const Lookup& lookup) {
  if (!(in.texture_levels.x() > 0) && !(in.texture_levels.y() > 0)) return lookup(in.uv, in.footprint);
  const float lu = std::floor(in.texture_levels.x()), lv = std::floor(in.texture_levels.y());
  const float fu = in.texture_levels.x() - lu, fv = in.texture_levels.y() - lv;
  T sum = zero;
  for (int i = 0; i < 2; ++i)
    for (int j = 0; j < 2; ++j) {
      const float w = (i ? fu : 1 - fu) * (j ? fv : 1 - fv);
      if (w <= 0) continue;
      const float su = std::exp2(lu + float(i)), sv = std::exp2(lv + float(j));
      sum += w * lookup(Vec2f(in.uv.x() * su, in.uv.y() * sv), in.footprint * std::max(su, sv));
    }
  return sum;
}

Color texture_rgb(const TextureStore& tex, int handle, const ShadingInput& in) {
  return through_cell_levels<Color>(in, Color::Zero(), [&](const Vec2f& uv, float footprint) {
    return tex.rgb(handle, uv, footprint, in.primary);
  });
}

float texture_scalar(const TextureStore& tex, int handle, const ShadingInput& in) {
  return through_cell_levels<float>(in, 0.0f, [&](const Vec2f& uv, float footprint) {
    return tex.scalar(handle, uv, footprint, in.primary);
  });
}

}  // namespace

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
    base *= texture_rgb(tex, m.base_tex, in);
  base = (base * in.base_scale).max(0.0f).min(1.0f);
  float rough = in.roughness_override >= 0 ? in.roughness_override : m.roughness;
  if (m.rough_tex >= 0) rough = std::clamp(rough * texture_scalar(tex, m.rough_tex, in), 0.0f, 1.0f);
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
  const Color c = texture_rgb(tex, m.normal_tex, in);
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
