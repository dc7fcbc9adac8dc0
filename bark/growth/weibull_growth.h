// Growth functions of cambial growth (Kratt et al., Woodification, sec. 4.1–4.2): the speed
// s(x, t) at which the cambium (the bark surface) moves along its normal, Eq. (1)
// ẋ = s(x, t)·n(x).
//  - Allometric growth, Eq. (2): the single-parameter Weibull density s(t) = c·t^(c−1)·exp(−t^c)
//    over an age t in units of the scene's age scale. Steps advance by its cumulative form
//    S(t) = 1 − exp(−t^c), so the total thickening of any number of steps over [t₀, t₁] is
//    exactly S(t₁) − S(t₀), whatever the step size.
//  - Eccentricity (reaction wood), Eq. (3): s_e = (1 + e·n̂·ŷ)·s, ŷ a configurable direction.
//  - Brush strokes (sec. 4.4): a point, a radius with Gaussian falloff and a value, multiplying
//    the speed by (1 + Σ value·exp(−d²/2r²)).
#pragma once

#include <vector>

#include "util/math.h"

namespace phellem::bark {

struct GrowthStroke {
  Vec3f point{0, 0, 0};
  float radius = 0.05f;  // m: the Gaussian's standard deviation
  float value = 1.0f;    // added to the speed factor at the point (−1 stops growth there)
  // Sec. 4.4's dragged growth vectors: where the stroke reaches (its Gaussian weight w), the
  // growth direction turns from the normal towards this one (unit; zero: the normal).
  Vec3f direction{0, 0, 0};
};

struct GrowthFunction {
  float weibull_c = 2.0f;       // the species parameter c of Eq. (2), > 0
  float age_scale = 1.0f;       // years per unit of t, > 0
  float thickness = 0.05f;      // m: the total thickening S(∞) = 1 maps to
  float eccentricity = 0.0f;    // e of Eq. (3), in (−1, 1)
  Vec3f eccentricity_direction{0, 1, 0};  // ŷ of Eq. (3), unit
  std::vector<GrowthStroke> strokes;

  // Eq. (2) at age t (years): the speed in metres per unit of t.
  double weibull(double t) const;
  // ∫ of Eq. (2) from 0 to t: S(t) = 1 − exp(−(t / age_scale)^c), times `thickness` (m).
  double cumulative(double t_years) const;
  // The thickening between ages t0 and t1 (years) at a point with unit normal n: the
  // cumulative difference × Eq. (3)'s eccentricity factor × the strokes' factor (≥ 0).
  double thickening(double t0, double t1, const Vec3f& position, const Vec3f& normal) const;
  // Eq. (3)'s factor and the strokes' factor alone.
  double eccentricity_factor(const Vec3f& normal) const;
  double stroke_factor(const Vec3f& position) const;
  // Sec. 4.4: the unit direction a point grows in: its normal, turned by each stroke with a
  // direction towards that direction by the stroke's weight, (1 − w)·d + w·D normalized, in
  // stroke order; never turned more than to kMinNormalShare of the normal (so the surface
  // still moves outwards where it grows).
  Vec3f growth_direction(const Vec3f& position, const Vec3f& normal) const;
  bool has_directions() const;
  // Sec. 4.4's painted directions: d turned towards `painted` by its length w (clamped to 1),
  // (1 − w)·d + w·painted/|painted| normalized, keeping kMinNormalShare of the normal n.
  static Vec3f turned_towards(const Vec3f& d, const Vec3f& n, const Vec3f& painted);
  // d (unit) with at least kMinNormalShare of the unit normal n: d itself, or turned back
  // towards n in the plane of the two.
  static Vec3f keep_normal_share(const Vec3f& d, const Vec3f& n);
  static constexpr float kMinNormalShare = 0.2f;
};

}  // namespace phellem::bark
