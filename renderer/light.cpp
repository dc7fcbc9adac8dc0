#include "renderer/light.h"

#include <limits>

#include "util/fast_trig.h"

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

Vec2f EnvironmentMap::direction_to_uv(const Vec3f& d) {
  float u = 0.5f + fast_atan2(d.x(), -d.z()) * (0.5f * kInvPi);
  if (u >= 1.0f) u -= 1.0f;
  if (u < 0.0f) u = 0.0f;
  const float v = fast_acos(std::clamp(d.y(), -1.0f, 1.0f)) * kInvPi;
  return Vec2f(u, v);
}

Vec3f EnvironmentMap::uv_to_direction(const Vec2f& uv) {
  float sp, cp, st, ct;
  fast_sincos((uv.x() - 0.5f) * kTwoPi, &sp, &cp);
  fast_sincos(uv.y() * kPi, &st, &ct);
  return Vec3f(st * sp, ct, -st * cp);
}

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

// ---- Preetham sky
namespace {

struct Perez {
  float A, B, C, D, E;
  float operator()(float cos_theta, float gamma) const {
    const float cg = std::cos(gamma);
    return (1 + A * std::exp(B / std::max(cos_theta, 0.01f))) * (1 + C * std::exp(D * gamma) + E * cg * cg);
  }
};

}  // namespace

Color preetham_radiance(const Vec3f& sun, float T, const Vec3f& d) {
  // Preetham, Shirley, Smits 1999, "A Practical Analytic Model for Daylight", appendix A.
  const float theta_s = std::acos(std::clamp(sun.y(), 0.0f, 1.0f));
  const float chi = (4.0f / 9.0f - T / 120.0f) * (kPi - 2 * theta_s);
  const float Yz = (4.0453f * T - 4.9710f) * std::tan(chi) - 0.2155f * T + 2.4192f;  // kcd/m²
  const float t2 = theta_s * theta_s, t3 = t2 * theta_s;
  const float xz = T * T * (0.00166f * t3 - 0.00375f * t2 + 0.00209f * theta_s) +
                   T * (-0.02903f * t3 + 0.06377f * t2 - 0.03202f * theta_s + 0.00394f) +
                   (0.11693f * t3 - 0.21196f * t2 + 0.06052f * theta_s + 0.25886f);
  const float yz = T * T * (0.00275f * t3 - 0.00610f * t2 + 0.00317f * theta_s) +
                   T * (-0.04214f * t3 + 0.08970f * t2 - 0.04153f * theta_s + 0.00516f) +
                   (0.15346f * t3 - 0.26756f * t2 + 0.06670f * theta_s + 0.26688f);
  const Perez pY{0.1787f * T - 1.4630f, -0.3554f * T + 0.4275f, -0.0227f * T + 5.3251f, 0.1206f * T - 2.5771f,
                 -0.0670f * T + 0.3703f};
  const Perez px{-0.0193f * T - 0.2592f, -0.0665f * T + 0.0008f, -0.0004f * T + 0.2125f, -0.0641f * T - 0.8989f,
                 -0.0033f * T + 0.0452f};
  const Perez py{-0.0167f * T - 0.2608f, -0.0950f * T + 0.0092f, -0.0079f * T + 0.2102f, -0.0441f * T - 1.6537f,
                 -0.0109f * T + 0.0529f};
  const Vec3f dd = Vec3f(d.x(), std::max(d.y(), 0.001f), d.z()).normalized();
  const float cos_t = dd.y();
  const float gamma = std::acos(std::clamp(dd.dot(sun), -1.0f, 1.0f));
  const float Y = Yz * pY(cos_t, gamma) / pY(1.0f, theta_s);
  const float x = xz * px(cos_t, gamma) / px(1.0f, theta_s);
  const float y = yz * py(cos_t, gamma) / py(1.0f, theta_s);
  // xyY -> XYZ -> linear Rec.709.
  const float X = x / y * Y, Z = (1 - x - y) / y * Y;
  Color rgb(3.2404542f * X - 1.5371385f * Y - 0.4985314f * Z, -0.9692660f * X + 1.8760108f * Y + 0.0415560f * Z,
            0.0556434f * X - 0.2040259f * Y + 1.0572252f * Z);
  return rgb.max(0.0f);
}

std::unique_ptr<EnvironmentMap> make_preetham_sky(const Vec3f& sun_direction, float turbidity, float intensity,
                                                  float ground_albedo, int width) {
  const int height = width / 2;
  std::vector<float> rgb(size_t(width) * height * 3);
  const Vec3f sun = sun_direction.normalized();
  const float scale = intensity / 100.0f;  // 1 scene unit of radiance = 100 kcd/m²
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      Vec3f d = EnvironmentMap::uv_to_direction(Vec2f((x + 0.5f) / width, (y + 0.5f) / height));
      Color c;
      if (d.y() >= 0) {
        c = preetham_radiance(sun, turbidity, d) * scale;
      } else {
        c = preetham_radiance(sun, turbidity, Vec3f(d.x(), 0.0f, d.z())) * scale * ground_albedo;
      }
      std::copy(c.data(), c.data() + 3, &rgb[(size_t(y) * width + x) * 3]);
    }
  return std::make_unique<EnvironmentMap>(std::move(rgb), width, height, 1.0f, 0.0f);
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
