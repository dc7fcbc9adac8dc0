#include "tests/support/chi2.h"

#include <cmath>
#include <random>
#include <sstream>
#include <vector>

namespace phellem::test {

double gamma_q(double a, double x) {
  if (x <= 0) return 1.0;
  const double gln = std::lgamma(a);
  if (x < a + 1) {  // series for P, Q = 1 - P
    double ap = a, sum = 1.0 / a, del = sum;
    for (int n = 0; n < 1000; ++n) {
      ap += 1;
      del *= x / ap;
      sum += del;
      if (std::abs(del) < std::abs(sum) * 1e-15) break;
    }
    return 1.0 - sum * std::exp(-x + a * std::log(x) - gln);
  }
  // Continued fraction (modified Lentz).
  double b = x + 1 - a, c = 1e300, d = 1 / b, h = d;
  for (int i = 1; i < 1000; ++i) {
    const double an = -i * (i - a);
    b += 2;
    d = an * d + b;
    if (std::abs(d) < 1e-300) d = 1e-300;
    c = b + an / c;
    if (std::abs(c) < 1e-300) c = 1e-300;
    d = 1 / d;
    const double del = d * c;
    h *= del;
    if (std::abs(del - 1) < 1e-15) break;
  }
  return std::exp(-x + a * std::log(x) - gln) * h;
}

std::string Chi2Result::summary() const {
  std::ostringstream s;
  s << "chi2=" << statistic << " dof=" << dof << " p=" << p_value << " ∫pdf=" << pdf_integral;
  return s.str();
}

Chi2Result chi2_sphere(const std::function<std::optional<Vec3f>(const Vec2f&)>& sample,
                       const std::function<float(const Vec3f&)>& pdf, int samples, int nt, int np, uint32_t seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> uni(0.0f, kOneMinusEpsilon);
  std::vector<double> observed(size_t(nt) * np, 0.0), expected(size_t(nt) * np, 0.0);
  auto bin_of = [&](const Vec3f& w) {
    const float z = std::clamp(w.z(), -1.0f, 1.0f);
    const int t = std::min(nt - 1, int((1 - z) * 0.5f * nt));
    float phi = std::atan2(w.y(), w.x());
    if (phi < 0) phi += kTwoPi;
    const int p = std::min(np - 1, int(phi / kTwoPi * np));
    return size_t(t) * np + p;
  };
  for (int i = 0; i < samples; ++i) {
    if (auto w = sample(Vec2f(uni(rng), uni(rng)))) observed[bin_of(*w)] += 1;
  }
  // Integrate the pdf over every bin (bins are equal-area in cosθ × φ) by midpoint rule.
  const int sub = 12;
  const double bin_area = (2.0 / nt) * (2.0 * M_PI / np);
  Chi2Result r;
  for (int t = 0; t < nt; ++t)
    for (int p = 0; p < np; ++p) {
      double sum = 0;
      for (int a = 0; a < sub; ++a)
        for (int b = 0; b < sub; ++b) {
          const double z = 1 - 2.0 * (t + (a + 0.5) / sub) / nt;
          const double phi = 2 * M_PI * (p + (b + 0.5) / sub) / np;
          const double s = std::sqrt(std::max(0.0, 1 - z * z));
          sum += pdf(Vec3f(float(s * std::cos(phi)), float(s * std::sin(phi)), float(z)));
        }
      const double integral = sum / (sub * sub) * bin_area;
      expected[size_t(t) * np + p] = integral * samples;
      r.pdf_integral += integral;
    }
  // Pool bins with small expectation (Cochran's rule) into one.
  std::vector<size_t> order(expected.size());
  for (size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::sort(order.begin(), order.end(), [&](size_t a, size_t b) { return expected[a] < expected[b]; });
  double pool_obs = 0, pool_exp = 0, chsq = 0;
  int dof = 0;
  for (size_t i : order) {
    if (expected[i] == 0) {
      if (observed[i] > samples * 1e-5) {  // samples where the pdf claims none: certain failure
        r.p_value = 0;
        r.statistic = INFINITY;
        return r;
      }
      continue;
    }
    if (expected[i] < 5) {
      pool_obs += observed[i];
      pool_exp += expected[i];
      continue;
    }
    chsq += (observed[i] - expected[i]) * (observed[i] - expected[i]) / expected[i];
    ++dof;
  }
  if (pool_exp > 0) {
    chsq += (pool_obs - pool_exp) * (pool_obs - pool_exp) / pool_exp;
    ++dof;
  }
  dof -= 1;
  r.statistic = chsq;
  r.dof = dof;
  r.p_value = dof > 0 ? gamma_q(dof / 2.0, chsq / 2.0) : 0;
  return r;
}

}  // namespace phellem::test
