#include "renderer/light.h"

#include <limits>

#include "util/fast_trig.h"
#include "util/latlong.h"

namespace phellem {

namespace {
constexpr float kInf = std::numeric_limits<float>::infinity();
}

// ---- uniform environment
std::optional<LightSample> UniformEnvironment::sample(const Vec3f&, const Vec2f& u) const {
  LightSample s;
  s.wi = sample_uniform_sphere(u);
  s.pdf = 1.0f / (4 * kPi);
  s.L = L_;
  s.dist = kInf;
  return s;
}

std::optional<LightSample> UniformEnvironment::sample_at(const Vec3f& p, const Vec3f& n, const Vec2f& u) const {
  if (!(n.squaredNorm() > 0)) return sample(p, u);
  LightSample s;
  s.wi = Frame(n).to_world(sample_cosine_hemisphere(u));
  s.pdf = pdf_at(s.wi, n);
  if (!(s.pdf > 0)) return std::nullopt;
  s.L = L_;
  s.dist = kInf;
  return s;
}

// ---- environment map
EnvironmentMap::EnvironmentMap(std::vector<float> rgb, int width, int height, float intensity, float rotation_deg)
    : rgb_(std::move(rgb)), w_(width), h_(height), intensity_(intensity), cos_r_(std::cos(radians(rotation_deg))),
      sin_r_(std::sin(radians(rotation_deg))) {
  std::vector<float> f(size_t(w_) * h_);
  double sum = 0;
  for (int y = 0; y < h_; ++y) {
    const float sin_t = std::sin(kPi * (y + 0.5f) / h_);
    for (int x = 0; x < w_; ++x) {
      const float l = std::max(0.0f, luminance(texel(x, y)));
      f[size_t(y) * w_ + x] = l * sin_t;
      sum += l * sin_t;
    }
  }
  // Average radiance over the sphere (sum of L·sinθ·dθdφ / 4π).
  average_ = float(sum * (kPi / h_) * (kTwoPi / w_) / (4 * kPi)) * intensity_;
  dist_ = Distribution2D(f, w_, h_);
}

Color EnvironmentMap::texel(int x, int y) const {
  const float* p = &rgb_[(size_t(y) * w_ + x) * 3];
  return Color(p[0], p[1], p[2]);
}

Vec2f EnvironmentMap::direction_to_uv(const Vec3f& d) { return direction_to_latlong(d); }

Vec3f EnvironmentMap::uv_to_direction(const Vec2f& uv) { return latlong_to_direction(uv); }

Vec3f EnvironmentMap::to_local(const Vec3f& w) const {
  return Vec3f(cos_r_ * w.x() - sin_r_ * w.z(), w.y(), sin_r_ * w.x() + cos_r_ * w.z());
}
Vec3f EnvironmentMap::to_world(const Vec3f& w) const {
  return Vec3f(cos_r_ * w.x() + sin_r_ * w.z(), w.y(), -sin_r_ * w.x() + cos_r_ * w.z());
}

Color EnvironmentMap::Le(const Vec3f& dir) const { return bilinear(direction_to_uv(to_local(dir))) * intensity_; }

Color EnvironmentMap::Le_pdf(const Vec3f& dir, const Vec3f&, float* pdf) const {
  const Vec2f uv = direction_to_uv(to_local(dir));
  const float sin_t = std::sqrt(std::max(0.0f, 1.0f - dir.y() * dir.y()));
  *pdf = sin_t > 0 ? dist_.pdf(uv) / (2 * kPi * kPi * sin_t) : 0.0f;
  return bilinear(uv) * intensity_;
}

Color EnvironmentMap::bilinear(const Vec2f& uv) const {
  // Bilinear lookup (the pdf stays piecewise constant; that is still unbiased).
  const float fx = uv.x() * w_ - 0.5f, fy = std::clamp(uv.y() * h_ - 0.5f, 0.0f, float(h_ - 1));
  const float flx = std::floor(fx);
  const int y0 = std::min(int(fy), h_ - 1), y1 = std::min(y0 + 1, h_ - 1);
  const float tx = fx - flx, ty = fy - float(y0);
  // uv.x ∈ [0, 1] puts x0 in [-1, w]: wrap with compares, not integer division.
  int x0 = int(flx), x1 = x0 + 1;
  if (x0 < 0) x0 += w_;
  if (x0 >= w_) x0 -= w_;
  if (x1 >= w_) x1 -= w_;
  return (1 - ty) * ((1 - tx) * texel(x0, y0) + tx * texel(x1, y0)) + ty * ((1 - tx) * texel(x0, y1) + tx * texel(x1, y1));
}

std::optional<LightSample> EnvironmentMap::sample(const Vec3f&, const Vec2f& u) const {
  float pdf_uv;
  const Vec2f uv = dist_.sample(u, &pdf_uv);
  if (pdf_uv <= 0) return std::nullopt;
  LightSample s;
  s.wi = to_world(uv_to_direction(uv));
  const float sin_t = std::sqrt(std::max(0.0f, 1.0f - s.wi.y() * s.wi.y()));  // rotation is about +y
  if (sin_t <= 0) return std::nullopt;
  s.pdf = pdf_uv / (2 * kPi * kPi * sin_t);
  s.L = bilinear(uv) * intensity_;  // the same radiance function as Le(): MIS stays consistent
  s.dist = kInf;
  return s;
}

float EnvironmentMap::pdf(const Vec3f& wi) const {
  const Vec2f uv = direction_to_uv(to_local(wi));
  const float sin_t = std::sqrt(std::max(0.0f, 1.0f - wi.y() * wi.y()));  // rotation is about +y
  if (sin_t <= 0) return 0;
  return dist_.pdf(uv) / (2 * kPi * kPi * sin_t);
}

// ---- sun
SunLight::SunLight(const Vec3f& direction, float irradiance, float angle_deg, const Color& color)
    : dir_(direction.normalized()), frame_(dir_), cos_max_(std::cos(radians(angle_deg * 0.5f))), E_(color * irradiance) {
  const float sin2 = 1.0f - cos_max_ * cos_max_;
  // ∫_cone L cosθ' dω = L π sin²θmax for a surface facing the sun.
  L_ = sin2 > 0 ? Color(E_ / (kPi * sin2)) : E_;
}

std::optional<LightSample> SunLight::sample(const Vec3f&, const Vec2f& u) const {
  LightSample s;
  s.dist = kInf;
  if (is_delta()) {
    s.wi = dir_;
    s.L = E_;
    s.pdf = 1;
    s.delta = true;
    return s;
  }
  s.wi = frame_.to_world(sample_uniform_cone(u, cos_max_));
  s.pdf = uniform_cone_pdf(cos_max_);
  s.L = L_;
  return s;
}

float SunLight::pdf(const Vec3f& wi) const {
  if (is_delta()) return 0;
  return wi.dot(dir_) >= cos_max_ ? uniform_cone_pdf(cos_max_) : 0.0f;
}

Color SunLight::Le(const Vec3f& d) const {
  if (is_delta()) return Color::Zero();
  return d.dot(dir_) >= cos_max_ ? L_ : Color::Zero();
}

// ---- Preetham sky (scene/sky_model.h)
std::unique_ptr<EnvironmentMap> make_preetham_sky(const Vec3f& sun_direction, float turbidity, float intensity,
                                                  float ground_albedo, int width) {
  std::vector<float> rgb = preetham_sky_image(sun_direction, turbidity, intensity, ground_albedo, width);
  return std::make_unique<EnvironmentMap>(std::move(rgb), width, width / 2, 1.0f, 0.0f);
}

// ---- area lights
AreaLights::AreaLights(std::vector<Triangle> tris) : tris_(std::move(tris)) {
  std::vector<float> w(tris_.size());
  for (size_t i = 0; i < tris_.size(); ++i) {
    const auto& t = tris_[i];
    area_.push_back(0.5f * (t.p1 - t.p0).cross(t.p2 - t.p0).norm());
    w[i] = area_[i] * luminance(t.L);
  }
  if (!w.empty()) dist_ = Distribution1D(std::move(w));
}

std::optional<LightSample> AreaLights::sample(const Vec3f& p, const Vec2f& u) const {
  if (tris_.empty()) return std::nullopt;
  // Pick a triangle with u.x and reuse its position inside the chosen bin as a fresh
  // uniform number for the point on the triangle.
  float density;
  int bin;
  const float x = dist_.sample(u.x(), &density, &bin);
  const size_t i = size_t(bin);
  const float pmf = density / float(tris_.size());
  if (pmf <= 0) return std::nullopt;
  const float u_reused = std::clamp(x * float(tris_.size()) - float(bin), 0.0f, kOneMinusEpsilon);
  const auto& t = tris_[i];
  const Vec2f b = sample_uniform_triangle(Vec2f(u_reused, u.y()));
  const Vec3f q = t.p0 * (1 - b.x() - b.y()) + t.p1 * b.x() + t.p2 * b.y();
  Vec3f d = q - p;
  const float dist2 = d.squaredNorm();
  if (dist2 <= 0) return std::nullopt;
  const float dist = std::sqrt(dist2);
  d /= dist;
  const Vec3f n = (t.p1 - t.p0).cross(t.p2 - t.p0).normalized();
  const float cos_l = std::abs(n.dot(d));
  if (cos_l <= 1e-6f) return std::nullopt;
  LightSample s;
  s.wi = d;
  s.dist = dist;
  s.L = t.L;
  s.pdf = pmf / area_[i] * dist2 / cos_l;
  return s;
}

float AreaLights::pdf_hit(size_t i, const Vec3f& p, const Vec3f& hit, const Vec3f& wi) const {
  const auto& t = tris_[i];
  const Vec3f n = (t.p1 - t.p0).cross(t.p2 - t.p0).normalized();
  const float cos_l = std::abs(n.dot(wi));
  if (cos_l <= 1e-6f) return 0;
  return dist_.pmf(i) / area_[i] * (hit - p).squaredNorm() / cos_l;
}

}  // namespace phellem
