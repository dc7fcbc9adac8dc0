#include "bark/strips/strip_params.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

namespace phellem::bark {

float sample_wrapped(const std::vector<float>& values, int W, int H, double x, double y) {
  const double fx = x - 0.5, fy = std::clamp(y - 0.5, 0.0, double(H - 1));
  const double flx = std::floor(fx);
  const int y0 = std::min(int(fy), H - 1), y1 = std::min(y0 + 1, H - 1);
  const double tx = fx - flx, ty = fy - y0;
  const int x0 = (int(flx) % W + W) % W, x1 = (x0 + 1) % W;
  auto at = [&](int i, int j) { return double(values[size_t(j) * W + i]); };
  return float((1 - ty) * ((1 - tx) * at(x0, y0) + tx * at(x1, y0)) + ty * ((1 - tx) * at(x0, y1) + tx * at(x1, y1)));
}

float ParamImage::sample(double u, double v) const {
  if (values.empty()) return 0.0f;
  return sample_wrapped(values, width, height, (u - std::floor(u)) * width, v * height);
}

double StripParams::fracture_stiffness_at(double rest) const {
  const auto& c = fracture_stiffness;
  if (c.size() == 1 || rest <= c.front().x()) return c.front().y();
  for (size_t i = 1; i < c.size(); ++i)
    if (rest <= c[i].x()) {
      const double t = (rest - c[i - 1].x()) / (c[i].x() - c[i - 1].x());
      return c[i - 1].y() + t * (c[i].y() - c[i - 1].y());
    }
  return c.back().y();
}

double StripParams::max_fracture_stiffness() const {
  double m = 0;
  for (const auto& p : fracture_stiffness) m = std::max(m, p.y());
  return m;
}

ThresholdRange valid_threshold_range(const StripParams& p, double softest_epidermis) {
  // Lefebvre & Neyret 2002, sec. 3.2.3: S > 1 + e/l0 · K_f / (K_s + K_f), S < G.
  const double kf = p.max_fracture_stiffness(), ks = softest_epidermis;
  const double bound = 1.0 + (p.growth_rate - 1.0) * kf / (ks + kf);
  ThresholdRange r;
  // The jittered thresholds 1 + (S − 1)(1 − noise) stay above the bound; weakness_noise (our
  // extension) lowers S − 1 by up to that fraction more.
  r.low = 1.0 + (bound - 1.0) / ((1.0 - p.threshold_noise) * (1.0 - p.weakness_noise));
  r.high = p.growth_rate;
  return r;
}

int max_steps_for_growth(double growth_rate) {
  if (!(growth_rate > 1.0)) return 1000000;
  // The largest n with growth_rate^n <= kMaxStripGrowth, exact at the boundary.
  int n = int(std::floor(std::log(kMaxStripGrowth) / std::log(growth_rate)));
  while (n > 0 && std::pow(growth_rate, n) > kMaxStripGrowth) --n;
  while (std::pow(growth_rate, n + 1) <= kMaxStripGrowth) ++n;
  return std::min(n, 1000000);
}

std::optional<StripParamError> validate(const StripParams& p) {
  auto err = [](std::string key, std::string msg) { return StripParamError{std::move(key), std::move(msg)}; };
  auto positive = [&](const char* key, double v) -> std::optional<StripParamError> {
    if (!(v > 0) || !std::isfinite(v)) return err(key, "must be a positive number");
    return std::nullopt;
  };
  for (auto [key, v] : {std::pair<const char*, double>{"strip_width", p.strip_width},
                        {"element_length", p.element_length},
                        {"stiffness", p.stiffness}})
    if (auto e = positive(key, v)) return e;
  if (p.steps < 1 || p.steps > 1000000) return err("steps", "must be an integer in [1, 1000000]");
  if (!(p.growth_rate > 1.0) || !(p.growth_rate < 2.0))
    return err("growth_rate", "must be in (1, 2): relative circumference growth per step");
  // The bark starts growth_rate^steps times smaller than the scene's tree (sec. 5.2); past
  // kMaxStripGrowth its first elements would be far below any length the model resolves.
  if (const int most = max_steps_for_growth(p.growth_rate); p.steps > most) {
    std::ostringstream m;
    m.precision(4);
    const double l10 = p.steps * std::log10(p.growth_rate);  // the power itself may overflow a double
    const double e = std::floor(l10);
    m << "growth_rate^steps = " << p.growth_rate << "^" << p.steps << " = " << std::pow(10.0, l10 - e) << "e+" << e << " exceeds "
      << kMaxStripGrowth << " (the bark would start that many times smaller than the tree); growth_rate " << p.growth_rate
      << " allows at most " << most << " steps";
    return err("steps", m.str());
  }
  // Dilatation bulges raise the growth exponent to at most 1 + the sum of their positive
  // amounts where they overlap: the same bound holds there.
  double bulges = 0;
  for (const auto& b : p.dilatation) {
    if (!std::isfinite(b.amount)) return err("dilatation", "amounts must be finite");
    bulges += std::max(0.0, b.amount);
  }
  if (p.steps * std::log(p.growth_rate) * (1.0 + bulges) > std::log(kMaxStripGrowth)) {
    char m[400];
    std::snprintf(m, sizeof m,
                  "bulge amounts summing to %g raise the growth at their centre to growth_rate^(steps x (1 + %g)) = "
                  "10^%.1f, more than %g; with growth_rate %g and %d steps the amounts may sum to at most %.2f",
                  bulges, bulges, p.steps * std::log10(p.growth_rate) * (1.0 + bulges), kMaxStripGrowth, p.growth_rate, p.steps,
                  std::floor(100 * (std::log(kMaxStripGrowth) / (p.steps * std::log(p.growth_rate)) - 1.0)) / 100);
    return err("dilatation", m);
  }
  if (p.fracture_stiffness.empty()) return err("fracture_stiffness", "needs at least one value");
  for (size_t i = 0; i < p.fracture_stiffness.size(); ++i) {
    const auto& c = p.fracture_stiffness[i];
    if (!(c.y() > 0) || !std::isfinite(c.y()) || !(c.x() >= 0))
      return err("fracture_stiffness", "points must be [rest length >= 0 (m), stiffness > 0]");
    if (i > 0 && !(c.x() > p.fracture_stiffness[i - 1].x())) return err("fracture_stiffness", "rest lengths must increase");
  }
  if (!(p.attachment >= 0) || !std::isfinite(p.attachment)) return err("attachment", "must be >= 0");
  if (!(p.threshold_noise >= 0 && p.threshold_noise < 1)) return err("threshold_noise", "must be in [0, 1)");
  if (!(p.location_jitter >= 0 && p.location_jitter <= 1)) return err("location_jitter", "must be in [0, 1]");
  if (!(p.weakness_strength >= 0 && p.weakness_strength < 1)) return err("weakness_strength", "must be in [0, 1)");
  if (auto e = positive("inglis_threshold", p.inglis_threshold)) return e;
  if (!(p.influence >= 0) || !std::isfinite(p.influence)) return err("influence", "must be >= 0");
  if (!(p.propagation_jitter_deg >= 0 && p.propagation_jitter_deg < 90))
    return err("propagation_jitter_deg", "must be in [0, 90)");
  if (!(p.spiral_deg >= -45 && p.spiral_deg <= 45)) return err("spiral_deg", "must be in [-45, 45]");
  if (!(p.propagation_tension >= 0 && p.propagation_tension <= 1)) return err("propagation_tension", "must be in [0, 1]");
  if (!(p.toughness_fraction >= 0 && p.toughness_fraction < 1)) return err("toughness_fraction", "must be in [0, 1)");
  if (!(p.anastomosis >= 0 && p.anastomosis <= 1)) return err("anastomosis", "must be in [0, 1]");
  if (!(p.fork_probability >= 0 && p.fork_probability <= 1)) return err("fork_probability", "must be in [0, 1]");
  if (!(p.weakness_noise >= 0 && p.weakness_noise < 1)) return err("weakness_noise", "must be in [0, 1)");
  for (auto [key, v] : {std::pair<const char*, double>{"toughness_size", p.toughness_size},
                        {"anastomosis_reach", p.anastomosis_reach},
                        {"fork_offset", p.fork_offset},
                        {"weakness_noise_size", p.weakness_noise_size}})
    if (auto e = positive(key, v)) return e;
  if (!(p.opening_mix.minCoeff() >= 0) || !(p.opening_mix.sum() > 0))
    return err("opening", "weights must be >= 0 and not all zero");
  if (!(p.refracture_width >= 0)) return err("refracture_width", "must be >= 0 (0 disables refracture)");
  if (!(p.refracture_stiffness > 0 && p.refracture_stiffness <= 1)) return err("refracture_stiffness", "must be in (0, 1]");
  for (const auto& s : p.scripted)
    if (s.step < 0 || s.step >= p.steps) return err("fractures", "step must be in [0, steps)");
  const double S = p.S();
  // The reference element (nominal width, element_length) has stiffness R.
  const double softest = p.stiffness * (p.refracture_width > 0 ? p.refracture_stiffness : 1.0);
  const ThresholdRange r = valid_threshold_range(p, softest);
  if (!(S > r.low && S <= r.high)) return threshold_error(p, r, softest);
  return std::nullopt;
}

StripParamError threshold_error(const StripParams& p, const ThresholdRange& r, double softest_epidermis) {
  std::ostringstream m;
  m.precision(6);
  m << "S = " << p.S() << " is outside its valid range (" << r.low << ", " << r.high << "] for growth_rate " << p.growth_rate
    << ", threshold_noise " << p.threshold_noise << ", fracture_stiffness up to " << p.max_fracture_stiffness()
    << " and softest epidermis element " << softest_epidermis
    << " (Lefebvre & Neyret 2002 sec. 3.2.3: below it broken bark breaks again without end, above it unbroken "
       "bark never breaks)";
  return {"threshold", m.str()};
}

}  // namespace phellem::bark
