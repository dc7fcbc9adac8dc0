#include "renderer/bsdf.h"

#include "renderer/sampling.h"

namespace phellem {

namespace {

// Schlick's Fresnel from F0 at normal incidence to F90 at grazing (F90 < 1 lets a coat fade
// out entirely, as glTF's KHR_materials_specular does).
inline float schlick_scalar(float f0, float f90, float cos_t) {
  const float m = std::clamp(1.0f - cos_t, 0.0f, 1.0f);
  return f0 + (f90 - f0) * m * m * m * m * m;
}

// Probability of sampling the bark coat rather than the base, from the coat's share of
// the reflected energy at wo (any positive choice is unbiased).
inline float bark_coat_probability(const BSDF& b, float cos_o) {
  if (b.f90 <= 0.0f) return 0.0f;  // no coat (F0 ≤ F90 = 0): never sample it
  const float fo = schlick_scalar(b.f0, b.f90, cos_o);
  const float base = (1.0f - fo) * std::max(0.02f, luminance(b.base));
  return std::clamp(fo / (fo + base), 0.1f, 0.9f);
}

// ---- rough dielectric (Walter et al. 2007; pdf and radiance scaling as in pbrt-v4 9.7)
struct DielectricEval {
  Color f;
  float pdf;
};

DielectricEval rough_dielectric(const BSDF& b, const Vec3f& wo, const Vec3f& wi) {
  const GGX ggx(b.alpha);
  const float cos_o = wo.z(), cos_i = wi.z();
  if (cos_o == 0 || cos_i == 0) return {Color::Zero(), 0};
  const bool reflect_lobe = cos_i * cos_o > 0;
  float etap = 1;
  if (!reflect_lobe) etap = cos_o > 0 ? b.eta : 1.0f / b.eta;
  Vec3f wm = wi * etap + wo;
  if (wm.squaredNorm() == 0) return {Color::Zero(), 0};
  wm.normalize();
  if (wm.z() < 0) wm = -wm;
  // Discard back-facing microfacets.
  if (wm.dot(wi) * cos_i < 0 || wm.dot(wo) * cos_o < 0) return {Color::Zero(), 0};
  const float F = fresnel_dielectric(wo.dot(wm), b.eta);
  const float R = F, T = 1 - F;
  if (reflect_lobe) {
    const float f = ggx.D(wm) * ggx.G(wo, wi) * F / std::abs(4 * cos_i * cos_o);
    const float pdf = ggx.visible_pdf(wo, wm) / (4 * std::abs(wo.dot(wm))) * R;
    return {Color::Constant(f), pdf};
  }
  const float denom = sqr(wi.dot(wm) + wo.dot(wm) / etap);
  const float ft = T * ggx.D(wm) * ggx.G(wo, wi) * std::abs(wi.dot(wm) * wo.dot(wm) / (cos_i * cos_o * denom)) / sqr(etap);
  const float dwm_dwi = std::abs(wi.dot(wm)) / denom;
  const float pdf = ggx.visible_pdf(wo, wm) * dwm_dwi * T;
  return {Color::Constant(ft), pdf};
}

}  // namespace

Color BSDF::eval(const Vec3f& wo, const Vec3f& wi) const {
  switch (type) {
    case Type::Black:
      return Color::Zero();
    case Type::Diffuse:
      if (wo.z() <= 0 || wi.z() <= 0) return Color::Zero();
      return base * kInvPi;
    case Type::Bark: {
      if (wo.z() <= 0 || wi.z() <= 0) return Color::Zero();
      const GGX ggx(alpha);
      const Vec3f wm = (wo + wi).normalized();
      const float F = schlick_scalar(f0, f90, wo.dot(wm));
      const float coat = ggx.D(wm) * ggx.G(wo, wi) * F / (4 * wo.z() * wi.z());
      const float t = (1 - schlick_scalar(f0, f90, wo.z())) * (1 - schlick_scalar(f0, f90, wi.z()));
      return base * (kInvPi * t) + coat;
    }
    case Type::Conductor: {
      if (is_delta() || wo.z() <= 0 || wi.z() <= 0) return Color::Zero();
      const GGX ggx(alpha);
      const Vec3f wm = (wo + wi).normalized();
      return fresnel_schlick(base, wo.dot(wm)) * (ggx.D(wm) * ggx.G(wo, wi) / (4 * wo.z() * wi.z()));
    }
    case Type::Dielectric:
      if (is_delta()) return Color::Zero();
      return rough_dielectric(*this, wo, wi).f;
  }
  return Color::Zero();
}

float BSDF::pdf(const Vec3f& wo, const Vec3f& wi) const {
  switch (type) {
    case Type::Black:
      return 0;
    case Type::Diffuse:
      if (wo.z() <= 0 || wi.z() <= 0) return 0;
      return cosine_hemisphere_pdf(wi.z());
    case Type::Bark: {
      if (wo.z() <= 0 || wi.z() <= 0) return 0;
      const GGX ggx(alpha);
      const Vec3f wm = (wo + wi).normalized();
      const float pc = bark_coat_probability(*this, wo.z());
      return pc * ggx.visible_pdf(wo, wm) / (4 * wo.dot(wm)) + (1 - pc) * cosine_hemisphere_pdf(wi.z());
    }
    case Type::Conductor: {
      if (is_delta() || wo.z() <= 0 || wi.z() <= 0) return 0;
      const GGX ggx(alpha);
      const Vec3f wm = (wo + wi).normalized();
      return ggx.visible_pdf(wo, wm) / (4 * wo.dot(wm));
    }
    case Type::Dielectric:
      if (is_delta()) return 0;
      return rough_dielectric(*this, wo, wi).pdf;
  }
  return 0;
}

std::optional<BSDFSample> BSDF::sample(const Vec3f& wo, float uc, const Vec2f& u) const {
  BSDFSample s;
  switch (type) {
    case Type::Black:
      return std::nullopt;
    case Type::Diffuse:
      if (wo.z() <= 0) return std::nullopt;
      s.wi = sample_cosine_hemisphere(u);
      if (s.wi.z() <= 0) return std::nullopt;
      s.pdf = cosine_hemisphere_pdf(s.wi.z());
      s.f = base * kInvPi;
      return s;
    case Type::Bark: {
      if (wo.z() <= 0) return std::nullopt;
      if (uc < bark_coat_probability(*this, wo.z())) {
        const Vec3f wm = GGX(alpha).sample_visible(wo, u);
        s.wi = reflect(wo, wm);
      } else {
        s.wi = sample_cosine_hemisphere(u);
      }
      if (s.wi.z() <= 0) return std::nullopt;
      s.pdf = pdf(wo, s.wi);
      s.f = eval(wo, s.wi);
      if (s.pdf <= 0) return std::nullopt;
      return s;
    }
    case Type::Conductor: {
      if (wo.z() <= 0) return std::nullopt;
      if (is_delta()) {
        s.wi = Vec3f(-wo.x(), -wo.y(), wo.z());
        s.pdf = 1;
        s.delta = true;
        s.f = fresnel_schlick(base, wo.z()) / wo.z();
        return s;
      }
      const GGX ggx(alpha);
      const Vec3f wm = ggx.sample_visible(wo, u);
      s.wi = reflect(wo, wm);
      if (s.wi.z() <= 0) return std::nullopt;
      s.pdf = ggx.visible_pdf(wo, wm) / (4 * wo.dot(wm));
      s.f = fresnel_schlick(base, wo.dot(wm)) * (ggx.D(wm) * ggx.G(wo, s.wi) / (4 * wo.z() * s.wi.z()));
      if (!(s.pdf > 0)) return std::nullopt;
      return s;
    }
    case Type::Dielectric: {
      if (wo.z() == 0) return std::nullopt;
      if (is_delta()) {
        const float R = fresnel_dielectric(wo.z(), eta), T = 1 - R;
        if (uc < R) {
          s.wi = Vec3f(-wo.x(), -wo.y(), wo.z());
          s.pdf = R;
          s.f = Color::Constant(R / std::abs(s.wi.z()));
        } else {
          float etap;
          if (!refract(wo, Vec3f(0, 0, 1), eta, &etap, &s.wi)) return std::nullopt;
          s.pdf = T;
          s.f = Color::Constant(T / std::abs(s.wi.z()) / sqr(etap));
          s.eta = etap;
        }
        s.delta = true;
        return s;
      }
      const GGX ggx(alpha);
      const Vec3f wm = ggx.sample_visible(wo, u);
      const float R = fresnel_dielectric(wo.dot(wm), eta);
      if (uc < R) {
        s.wi = reflect(wo, wm);
        if (s.wi.z() * wo.z() <= 0) return std::nullopt;
      } else {
        float etap;
        if (!refract(wo, wm, eta, &etap, &s.wi)) return std::nullopt;
        if (s.wi.z() * wo.z() >= 0) return std::nullopt;
        s.eta = etap;
      }
      const DielectricEval e = rough_dielectric(*this, wo, s.wi);
      if (!(e.pdf > 0)) return std::nullopt;
      s.f = e.f;
      s.pdf = e.pdf;
      return s;
    }
  }
  return std::nullopt;
}

}  // namespace phellem
