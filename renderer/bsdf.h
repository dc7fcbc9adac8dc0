// BSDFs evaluated in the local shading frame (n = +z). One small tagged type with a switch
// keeps shading allocation-free; each lobe cites its model.
//   diffuse     Lambert
//   bark        Lambert base under a rough GGX dielectric coat (F0 = 0.08·specular); the base is
//               weighted by (1 - F(wo))(1 - F(wi)) so the sum is reciprocal and never exceeds 1
//   conductor   rough GGX with Schlick Fresnel, F0 = base colour
//   dielectric  rough GGX reflection + transmission (Walter et al. 2007); smooth when α < 1e-3
//   emissive    black
#pragma once

#include <optional>

#include "renderer/microfacet.h"
#include "util/math.h"

namespace phellem {

struct BSDFSample {
  Color f;  // BSDF value (for delta lobes: the weight such that f·|cos|/pdf is right)
  Vec3f wi;
  float pdf = 0;
  bool delta = false;
  float eta = 1;  // relative IOR crossed (for transmission)
};

struct BSDF {
  enum class Type { Diffuse, Bark, Conductor, Dielectric, Black } type = Type::Diffuse;
  Color base{0.8f, 0.8f, 0.8f};  // albedo of the diffuse part / F0 of conductors
  float alpha = 0.25f;           // GGX roughness (α = roughness²)
  float f0 = 0.04f;              // bark coat reflectance at normal incidence
  float f90 = 1.0f;              // bark coat reflectance at grazing incidence
  float eta = 1.5f;              // dielectric: interior / exterior

  bool is_delta() const { return (type == Type::Conductor || type == Type::Dielectric) && alpha < 1e-3f; }
  bool has_transmission() const { return type == Type::Dielectric; }

  Color eval(const Vec3f& wo, const Vec3f& wi) const;
  float pdf(const Vec3f& wo, const Vec3f& wi) const;
  std::optional<BSDFSample> sample(const Vec3f& wo, float uc, const Vec2f& u) const;
};

}  // namespace phellem
