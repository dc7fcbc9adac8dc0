#include "bark/growth/weibull_growth.h"

#include <algorithm>
#include <cmath>

namespace phellem::bark {

double GrowthFunction::weibull(double t) const {
  if (!(t > 0)) return weibull_c > 1 ? 0.0 : (weibull_c == 1 ? 1.0 : HUGE_VAL);  // the limit at t → 0⁺
  const double c = weibull_c;
  return c * std::pow(t, c - 1) * std::exp(-std::pow(t, c));  // Eq. (2)
}

double GrowthFunction::cumulative(double t_years) const {
  const double t = std::max(0.0, t_years / double(age_scale));
  return double(thickness) * -std::expm1(-std::pow(t, double(weibull_c)));  // ∫₀ᵗ Eq. (2) = 1 − exp(−t^c)
}

double GrowthFunction::eccentricity_factor(const Vec3f& n) const {
  return 1.0 + double(eccentricity) * double(n.dot(eccentricity_direction));  // Eq. (3)
}

bool GrowthFunction::has_directions() const {
  for (const auto& s : strokes)
    if (s.direction.squaredNorm() > 0) return true;
  return false;
}

Vec3f GrowthFunction::growth_direction(const Vec3f& p, const Vec3f& n) const {
  Vec3f d = n;
  for (const auto& s : strokes) {
    if (!(s.direction.squaredNorm() > 0)) continue;
    const float w = std::exp(-(p - s.point).squaredNorm() / (2.0f * s.radius * s.radius));
    const Vec3f t = (1 - w) * d + w * s.direction.normalized();
    if (t.squaredNorm() > 1e-12f) d = t.normalized();
  }
  return keep_normal_share(d, n);
}

Vec3f GrowthFunction::keep_normal_share(const Vec3f& d, const Vec3f& n) {
  // d = cos·n + sin·(tangent) with cos ≥ kMinNormalShare.
  const float along = d.dot(n);
  if (along >= kMinNormalShare) return d;
  Vec3f tangent = d - along * n;
  const float len = tangent.norm();
  tangent = len > 1e-12f ? Vec3f(tangent / len) : Vec3f::Zero();
  return kMinNormalShare * n + std::sqrt(1 - kMinNormalShare * kMinNormalShare) * tangent;
}

Vec3f GrowthFunction::turned_towards(const Vec3f& d, const Vec3f& n, const Vec3f& painted) {
  const float len = painted.norm();
  if (!(len > 1e-12f)) return d;
  const float w = std::min(1.0f, len);
  const Vec3f t = (1 - w) * d + w * (painted / len);
  return keep_normal_share(t.squaredNorm() > 1e-12f ? Vec3f(t.normalized()) : n, n);
}

double GrowthFunction::stroke_factor(const Vec3f& p) const {
  double f = 1.0;
  for (const auto& s : strokes) f += double(s.value) * std::exp(-double((p - s.point).squaredNorm()) / (2.0 * double(s.radius * s.radius)));
  return std::max(0.0, f);
}

double GrowthFunction::thickening(double t0, double t1, const Vec3f& p, const Vec3f& n) const {
  return (cumulative(t1) - cumulative(t0)) * std::max(0.0, eccentricity_factor(n)) * stroke_factor(p);
}

}  // namespace phellem::bark
