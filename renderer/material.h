// Runtime materials: a MaterialDesc with its textures registered, turned into a BSDF at a hit.
#pragma once

#include "renderer/bsdf.h"
#include "renderer/textures.h"
#include "scene/scene_desc.h"

namespace phellem {

struct Material {
  MaterialType type = MaterialType::Diffuse;
  Color base{0.8f, 0.8f, 0.8f};
  int base_tex = -1, rough_tex = -1, normal_tex = -1;
  float roughness = 0.5f;
  float f0 = 0.04f, f90 = 1.0f;
  float ior = 1.5f;
  Color emission = Color::Zero();  // radiance of emissive materials
  bool emissive() const { return type == MaterialType::Emissive; }
};

Material compile_material(const MaterialDesc& d, TextureStore& textures);

struct ShadingInput {
  Vec2f uv;
  float footprint;                       // texture filter width in uv units
  bool primary = true;                   // camera-ray hit: full-quality (bicubic) texture filtering
  const Color* base_override = nullptr;  // dressed bark albedo replacing the base colour
  Color base_scale = Color::Ones();      // multiplies the base colour (crack depth darkening, bark tint)
  float roughness_override = -1;         // the bark's own roughness replacing the material's (< 0: none)
  Vec2f texture_levels{0, 0};            // a grown surface's texture cell levels along u and v (≥ 0)
};

BSDF evaluate_bsdf(const Material& m, const TextureStore& tex, const ShadingInput& in, Color* albedo);
// Perturbs the shading normal by the material's normal map (tangent space, OpenGL convention).
Vec3f apply_normal_map(const Material& m, const TextureStore& tex, const ShadingInput& in, const Vec3f& ns, const Vec4f& tangent);

}  // namespace phellem
