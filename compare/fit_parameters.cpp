#include "compare/fit_parameters.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "bark/stress/stress_presets.h"
#include "bark/strips/presets.h"

namespace phellem {

double FitParameter::value(double x) const {
  x = std::clamp(x, 0.0, 1.0);
  return log ? lo * std::pow(hi / lo, x) : lo + x * (hi - lo);
}

double FitParameter::normalized(double v) const {
  const double x = log ? std::log(v / lo) / std::log(hi / lo) : (v - lo) / (hi - lo);
  return std::isfinite(x) ? std::clamp(x, 0.0, 1.0) : 0.0;
}

FitCandidate FitSpace::candidate(const std::vector<double>& x) const {
  if (x.size() != table.size()) throw std::logic_error("FitSpace::candidate: wrong dimension");
  FitCandidate c = base;
  for (size_t i = 0; i < table.size(); ++i) table[i].apply(double(float(table[i].value(x[i]))), c);
  return c;
}

std::vector<double> FitSpace::values(const std::vector<double>& x) const {
  std::vector<double> v;
  for (size_t i = 0; i < table.size(); ++i) v.push_back(double(float(table[i].value(x[i]))));
  return v;
}

namespace {

using SP = bark::StripParams;

// A row that sets one member of the strip parameters.
FitParameter strip_row(std::string key, double lo, double hi, bool log, double SP::*member) {
  return {std::move(key), lo, hi, log, [member](double v, FitCandidate& c) { c.strips.params.*member = v; },
          [member](const FitCandidate& c) { return c.strips.params.*member; }};
}

// The softest epidermis element of a flat patch (bark::validate's): hardened fractures are
// softer when refracture is on.
double softest(const SP& p) { return p.stiffness * (p.refracture_width > 0 ? p.refracture_stiffness : 1.0); }

// K_f / (K_s + K_f): the valid threshold range is open while (1 − noise)(1 − weakness_noise)
// stays above it.
double stiffness_share(const SP& p) {
  const double kf = p.max_fracture_stiffness(), ks = softest(p);
  return kf / (ks + kf);
}

// The largest threshold noise that leaves the valid threshold range open (a little inside).
double max_threshold_noise(const SP& p) { return 0.95 * (1.0 - stiffness_share(p) / (1.0 - p.weakness_noise)); }

// Rounds to float, as the scene parser reads numbers.
double f32(double v) { return double(float(v)); }

}  // namespace

FitParameter relief_row(std::string key, double lo, double hi, bool log, double bark::ReliefLook::*member) {
  return {std::move(key), lo, hi, log, [member](double v, FitCandidate& c) { c.strips.relief.*member = v; },
          [member](const FitCandidate& c) { return c.strips.relief.*member; }};
}

FitSpace strip_fit_space() {
  FitSpace s;
  s.model = FitModel::strips;
  s.preset = "fissured";
  s.base.model = FitModel::strips;
  s.base.strips.params = *bark::strip_preset(s.preset);
  s.base.strips.params.steps = 500;
  s.base.strips.params.element_length = 0.01;
  s.base.strips.depth.shape = bark::DepthProfileShape::U;
  s.base.strips.depth.max_depth = 0.02;
  // Rough walls and plates that round down to the lips (the dressing's relief without its fbm
  // detail); depth_ratio 20 is barely any shoulder, wall_noise 0 smooth walls.
  s.base.strips.relief.enabled = true;
  s.base.strips.relief.detail = 0;
  s.base.strips.relief.depth_ratio = 20;
  s.base.strips.relief.wall_noise = 0;
  auto& t = s.table;
  t.push_back(strip_row("strip_width", 0.003, 0.05, true, &SP::strip_width));
  t.push_back(strip_row("growth_rate", 1.0005, 1.003, false, &SP::growth_rate));
  t.push_back(strip_row("location_jitter", 0, 1, false, &SP::location_jitter));
  t.push_back(strip_row("attachment", 0.01, 1, true, &SP::attachment));
  // fracture_stiffness {(0, k0), (0.05, k0·r)}: two rows, k0 first.
  t.push_back({"fracture_stiffness/k0", 0.01, 1, true,
               [](double v, FitCandidate& c) { c.strips.params.fracture_stiffness = {{0.0, v}}; },
               [](const FitCandidate& c) { return c.strips.params.fracture_stiffness.front().y(); }});
  t.push_back({"fracture_stiffness/ratio", 0.2, 5, true,
               [](double v, FitCandidate& c) {
                 auto& k = c.strips.params.fracture_stiffness;
                 k = {k.front(), {0.05, f32(k.front().y() * v)}};
               },
               [](const FitCandidate& c) {
                 const auto& k = c.strips.params.fracture_stiffness;
                 return k.size() < 2 ? 1.0 : k.back().y() / k.front().y();
               }});
  t.push_back(strip_row("inglis_threshold", 3, 100, true, &SP::inglis_threshold));
  t.push_back(strip_row("influence", 0, 1, false, &SP::influence));
  t.push_back(strip_row("propagation_tension", 0.1, 1, false, &SP::propagation_tension));
  t.push_back(strip_row("propagation_jitter_deg", 0, 45, false, &SP::propagation_jitter_deg));
  // Spiral grain, or a photo held a little askew: either leans the fissures off the vertical.
  t.push_back(strip_row("spiral_deg", -12, 12, false, &SP::spiral_deg));
  t.push_back({"refracture_width", 0, 0.1, false,
               [](double v, FitCandidate& c) { c.strips.params.refracture_width = v < 0.005 ? 0 : v; },
               [](const FitCandidate& c) { return c.strips.params.refracture_width; }});
  t.push_back(strip_row("refracture_stiffness", 0.1, 1, false, &SP::refracture_stiffness));
  // Rough fissure walls: the noise breaks the fissure mask into shorter pieces, a strong handle
  // on the fissure length. Rounded plates: the shoulder is the ridge relief that lowers the
  // depth ratio without breaking the fissures (fbm detail does break them: compare/fit_relief.h
  // fits it afterwards, with the geometry fixed).
  using RL = bark::ReliefLook;
  t.push_back(relief_row("relief/wall_noise", 0, 0.5, false, &RL::wall_noise));
  t.push_back(relief_row("relief/wall_size", 0.002, 0.03, true, &RL::wall_size));
  t.push_back(relief_row("relief/depth_ratio", 0.5, 20, true, &RL::depth_ratio));
  t.push_back(relief_row("relief/shoulder_width", 0.003, 0.03, true, &RL::shoulder_width));
  // The fissures' cross-section, from a cusp through V (1) and U (2) towards a box: V fissures
  // measure narrower and less wide-spread in the mask than U ones of the same opening.
  t.push_back({"depth/exponent", 0.5, 4, true,
               [](double v, FitCandidate& c) {
                 c.strips.depth.shape = bark::DepthProfileShape::Power;
                 c.strips.depth.exponent = v;
               },
               [](const FitCandidate& c) {
                 switch (c.strips.depth.shape) {
                   case bark::DepthProfileShape::V:
                     return 1.0;
                   case bark::DepthProfileShape::Power:
                     return c.strips.depth.exponent;
                   default:
                     return 2.0;
                 }
               }});
  t.push_back({"depth/depth_per_width", 0.2, 3, true, [](double v, FitCandidate& c) { c.strips.depth.depth_per_width = v; },
               [](const FitCandidate& c) { return c.strips.depth.depth_per_width; }});
  // Irregular fissures (strips22's knobs; 0 = the paper's model).
  t.push_back(strip_row("toughness_fraction", 0, 0.9, false, &SP::toughness_fraction));
  t.push_back(strip_row("toughness_size", 0.005, 0.1, true, &SP::toughness_size));
  t.push_back(strip_row("anastomosis", 0, 1, false, &SP::anastomosis));
  t.push_back(strip_row("fork_probability", 0, 1, false, &SP::fork_probability));
  t.push_back(strip_row("weakness_noise_size", 0.01, 0.3, true, &SP::weakness_noise_size));
  // The noises and the threshold depend on the stiffnesses and the growth: last, in this order.
  t.push_back({"weakness_noise", 0, 0.9, false,
               [](double v, FitCandidate& c) {
                 c.strips.params.weakness_noise = f32(std::min(v, 0.9 * (1.0 - stiffness_share(c.strips.params))));
               },
               [](const FitCandidate& c) { return c.strips.params.weakness_noise; }});
  // The noise is capped so that the valid threshold range stays open; the threshold is a
  // fraction of that range, so every candidate is valid.
  t.push_back({"threshold_noise", 0, 0.9, false,
               [](double v, FitCandidate& c) {
                 c.strips.params.threshold_noise = f32(std::min(v, max_threshold_noise(c.strips.params)));
               },
               [](const FitCandidate& c) { return c.strips.params.threshold_noise; }});
  t.push_back({"threshold/fraction", 0.05, 0.95, false,
               [](double v, FitCandidate& c) {
                 SP& p = c.strips.params;
                 bark::ThresholdRange r = bark::valid_threshold_range(p, softest(p));
                 p.threshold = f32(r.low + v * (r.high - r.low));
                 if (!(*p.threshold > r.low && *p.threshold <= r.high)) {
                   // Stiff fractures on soft bark leave a range a few floats wide: without
                   // the noises it is (G − 1)(1 − K_f/(K_s + K_f)) ≥ 1e-5 over the table.
                   p.threshold_noise = p.weakness_noise = 0;
                   r = bark::valid_threshold_range(p, softest(p));
                   p.threshold = f32(r.low + v * (r.high - r.low));
                 }
               },
               [](const FitCandidate& c) {
                 const SP& p = c.strips.params;
                 const bark::ThresholdRange r = bark::valid_threshold_range(p, softest(p));
                 return r.high > r.low ? (p.S() - r.low) / (r.high - r.low) : 1.0;
               }});
  for (const char* name : {"fissured", "furrowed", "plated", "brittle"}) {
    FitCandidate c = s.base;
    c.strips.params = *bark::strip_preset(name);
    std::vector<double> x;
    for (const FitParameter& row : t) x.push_back(row.normalized(row.read(c)));
    s.starts.push_back(x);
  }
  return s;
}

namespace {

using XP = bark::StressParams;

FitParameter look_row(std::string key, double lo, double hi, bool log, float CrackLook::*member) {
  return {std::move(key), lo, hi, log, [member](double v, FitCandidate& c) { c.stress.look.*member = float(v); },
          [member](const FitCandidate& c) { return double(c.stress.look.*member); }};
}

}  // namespace

FitSpace stress_fit_space() {
  FitSpace s;
  s.model = FitModel::stress;
  s.preset = "pine";
  s.base.model = FitModel::stress;
  s.base.stress.params = *bark::stress_preset(s.preset);
  // scenes/stress_pine.json's crack look.
  s.base.stress.look.width_per_edge = 0.0012f;
  s.base.stress.look.max_width = 0.008f;
  s.base.stress.look.max_depth = 0.012f;
  auto& t = s.table;
  t.push_back({"mix_ratio", 0, 1, false, [](double v, FitCandidate& c) { c.stress.params.mix_ratio = v; },
               [](const FitCandidate& c) { return c.stress.params.mix_ratio; }});
  t.push_back({"threshold", 0.3, 1.2, false, [](double v, FitCandidate& c) { c.stress.params.threshold = v; },
               [](const FitCandidate& c) { return c.stress.params.threshold; }});
  t.push_back({"iterations", 30, 300, true, [](double v, FitCandidate& c) { c.stress.params.iterations = int(std::lround(v)); },
               [](const FitCandidate& c) { return double(c.stress.params.iterations); }});
  t.push_back({"preprocess/edge_length", 0.005, 0.03, true, [](double v, FitCandidate& c) { c.stress.edge_length = v; },
               [](const FitCandidate& c) { return c.stress.edge_length; }});
  t.push_back(look_row("crack/width_per_edge", 0.0003, 0.003, true, &CrackLook::width_per_edge));
  t.push_back(look_row("crack/min_width", 0.0003, 0.003, true, &CrackLook::min_width));
  t.push_back(look_row("crack/max_width", 0.002, 0.02, true, &CrackLook::max_width));
  t.push_back(look_row("crack/depth_per_width", 0.3, 3, true, &CrackLook::depth_per_width));
  t.push_back(look_row("crack/noise", 0, 0.6, false, &CrackLook::noise));
  std::vector<double> x;
  for (const FitParameter& row : t) x.push_back(row.normalized(row.read(s.base)));
  s.starts.push_back(x);
  return s;
}

FitSpace restrict_space(const FitSpace& s, const std::vector<std::string>& keys) {
  FitSpace r = s;
  r.table.clear();
  for (const FitParameter& row : s.table)
    if (std::find(keys.begin(), keys.end(), row.key) != keys.end()) r.table.push_back(row);
  if (r.table.size() != keys.size()) throw std::logic_error("restrict_space: unknown or repeated key");
  std::vector<double> x;
  for (const FitParameter& row : r.table) x.push_back(row.normalized(row.read(r.base)));
  r.starts = {x};
  return r;
}

void narrow_row(FitSpace& s, const std::string& key, double centre, double half_width) {
  const auto row = std::find_if(s.table.begin(), s.table.end(), [&](const FitParameter& r) { return r.key == key; });
  if (row == s.table.end() || row->log || !(half_width > 0)) throw std::logic_error("narrow_row: unknown or log-mapped key");
  row->lo = centre - half_width;
  row->hi = centre + half_width;
  const size_t i = size_t(row - s.table.begin());
  for (std::vector<double>& x : s.starts) x[i] = 0.5;
}

FitSpace fit_space(FitModel model) { return model == FitModel::strips ? strip_fit_space() : stress_fit_space(); }

HeightField simulate_candidate(const FitCandidate& c, const PatchSize& size, uint64_t seed) {
  if (c.model == FitModel::strips) {
    StripPatchParams p = c.strips;
    p.params.orientation = bark::FractureOrientation::Vertical;
    return strip_patch(p, size, seed);
  }
  return stress_patch(c.stress, size, seed);
}

}  // namespace phellem
