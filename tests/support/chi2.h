// Chi-square goodness-of-fit test for sampling routines over the sphere of directions
// (the approach of pbrt-v4's and Mitsuba's chi2 tests): sample N directions into
// (cosθ, φ) bins, integrate the claimed pdf over every bin, merge sparse bins, and compute
// the p-value of Pearson's statistic.
#pragma once

#include <functional>
#include <optional>
#include <string>

#include "util/math.h"

namespace phellem::test {

struct Chi2Result {
  double p_value = 0;
  double statistic = 0;
  int dof = 0;
  double pdf_integral = 0;  // ∫ pdf over the sphere (≤ 1 when some samples fail)
  std::string summary() const;
};

// `sample(u)` returns a unit direction or nothing (a failed sample counts towards N);
// `pdf(w)` the solid-angle density claimed for it.
Chi2Result chi2_sphere(const std::function<std::optional<Vec3f>(const Vec2f&)>& sample,
                       const std::function<float(const Vec3f&)>& pdf, int samples = 1'000'000, int theta_bins = 40,
                       int phi_bins = 80, uint32_t seed = 1);

// Regularized upper incomplete gamma Q(a, x) (for chi-square p-values).
double gamma_q(double a, double x);

}  // namespace phellem::test
