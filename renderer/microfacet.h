// Isotropic GGX / Trowbridge-Reitz microfacet distribution with height-correlated Smith
// masking and sampling of visible normals (Heitz 2018, "Sampling the GGX Distribution of
// Visible Normals"; pdf and conventions as in pbrt-v4, sec. 9.6). Local frame: n = +z.
#pragma once

#include "util/math.h"

namespace phellem {

class GGX {
 public:
  explicit GGX(float alpha) : alpha_(std::max(alpha, 1e-4f)) {}
  float alpha() const { return alpha_; }

  float D(const Vec3f& wm) const {
    const float cos2 = wm.z() * wm.z();
    if (cos2 < 1e-16f) return 0.0f;
    const float tan2 = (1.0f - cos2) / cos2;
    const float e = tan2 / (alpha_ * alpha_);
    return 1.0f / (kPi * alpha_ * alpha_ * cos2 * cos2 * sqr(1.0f + e));
  }
  float lambda(const Vec3f& w) const {
    const float cos2 = w.z() * w.z();
    if (cos2 < 1e-16f) return 1e8f;
    const float tan2 = std::max(0.0f, 1.0f - cos2) / cos2;
    return (std::sqrt(1.0f + alpha_ * alpha_ * tan2) - 1.0f) / 2.0f;
  }
  float G1(const Vec3f& w) const { return 1.0f / (1.0f + lambda(w)); }
  float G(const Vec3f& wo, const Vec3f& wi) const { return 1.0f / (1.0f + lambda(wo) + lambda(wi)); }
  // Density of visible normals D_w(wm) = G1(w) max(0, w·wm) D(wm) / |w.z|.
  float visible_pdf(const Vec3f& w, const Vec3f& wm) const { return G1(w) / std::abs(w.z()) * D(wm) * std::abs(w.dot(wm)); }
  // Samples a visible normal seen from w (w on either side; the sample faces w's side).
  Vec3f sample_visible(const Vec3f& w, const Vec2f& u) const {
    Vec3f wh = Vec3f(alpha_ * w.x(), alpha_ * w.y(), w.z()).normalized();
    if (wh.z() < 0) wh = -wh;
    const Vec3f t1 = wh.z() < 0.99999f ? Vec3f(Vec3f(0, 0, 1).cross(wh).normalized()) : Vec3f(1, 0, 0);
    const Vec3f t2 = wh.cross(t1);
    // Uniform disk (polar), warped towards the projected hemisphere.
    const float r = std::sqrt(u.x()), phi = kTwoPi * u.y();
    Vec2f p(r * std::cos(phi), r * std::sin(phi));
    const float h = std::sqrt(1.0f - p.x() * p.x());
    p.y() = (1.0f - (1.0f + wh.z()) / 2.0f) * h + ((1.0f + wh.z()) / 2.0f) * p.y();
    const float pz = safe_sqrt(1.0f - p.squaredNorm());
    const Vec3f nh = p.x() * t1 + p.y() * t2 + pz * wh;
    return Vec3f(alpha_ * nh.x(), alpha_ * nh.y(), std::max(1e-6f, nh.z())).normalized();
  }

 private:
  float alpha_;
};

inline Vec3f reflect(const Vec3f& wo, const Vec3f& n) { return -wo + 2.0f * wo.dot(n) * n; }

// Fresnel reflectance of a dielectric interface; eta = n_t / n_i for cos_i > 0.
inline float fresnel_dielectric(float cos_i, float eta) {
  cos_i = std::clamp(cos_i, -1.0f, 1.0f);
  if (cos_i < 0) {
    eta = 1.0f / eta;
    cos_i = -cos_i;
  }
  const float sin2_t = (1.0f - cos_i * cos_i) / (eta * eta);
  if (sin2_t >= 1.0f) return 1.0f;
  const float cos_t = safe_sqrt(1.0f - sin2_t);
  const float r_parl = (eta * cos_i - cos_t) / (eta * cos_i + cos_t);
  const float r_perp = (cos_i - eta * cos_t) / (cos_i + eta * cos_t);
  return 0.5f * (r_parl * r_parl + r_perp * r_perp);
}

// Refraction of wi about n (same side as wi or not); returns false on total internal
// reflection. etap receives the relative index actually used.
inline bool refract(const Vec3f& wi, Vec3f n, float eta, float* etap, Vec3f* wt) {
  float cos_i = n.dot(wi);
  if (cos_i < 0) {
    eta = 1.0f / eta;
    cos_i = -cos_i;
    n = -n;
  }
  const float sin2_t = std::max(0.0f, 1.0f - cos_i * cos_i) / (eta * eta);
  if (sin2_t >= 1.0f) return false;
  const float cos_t = safe_sqrt(1.0f - sin2_t);
  *wt = -wi / eta + (cos_i / eta - cos_t) * n;
  if (etap) *etap = eta;
  return true;
}

inline Color fresnel_schlick(const Color& f0, float cos_t) {
  const float m = std::clamp(1.0f - cos_t, 0.0f, 1.0f);
  const float m5 = m * m * m * m * m;
  return f0 + (Color::Ones() - f0) * m5;
}

}  // namespace phellem
