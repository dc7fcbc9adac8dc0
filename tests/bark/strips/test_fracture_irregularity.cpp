// The irregular-fissure extension (issue 22; our own, not Lefebvre & Neyret's): with every
// knob at its default the model is the paper's, bit for bit; each knob, turned on alone on a
// small patch, measurably does what it claims (fissures of varying lengths, tips joining
// other fractures, forks, irregular spacing).
#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <vector>

#include "bark/strips/presets.h"
#include "bark/strips/strip_model.h"
#include "tests/support/strip_helpers.h"

using namespace phellem::bark;

namespace {

// A vertical patch like the presets' at a tenth of their growth: 5 mm strips, 30 × 30 cm.
StripParams patch_params() {
  StripParams p = *strip_preset("fissured");
  p.steps = 250;
  p.growth_rate = 1.0024;
  p.seed = 5;
  return p;
}

StripModel run(const StripParams& p) { return phellem::test::run_flat(p, 0.3, 0.3); }

// Per fracture component (skeleton root): the strips it spans.
std::vector<double> component_spans(const StripModel& m) {
  std::map<int32_t, std::pair<size_t, size_t>> span;
  for (size_t j = 0; j < m.strips().size(); ++j)
    for (const Element& e : m.strips()[j].elements) {
      if (e.kind != ElementKind::Fracture) continue;
      auto [it, fresh] = span.try_emplace(m.skeleton().find(e.id), j, j);
      it->second.first = std::min(it->second.first, j);
      it->second.second = std::max(it->second.second, j);
    }
  std::vector<double> out;
  for (const auto& [root, s] : span) out.push_back(double(s.second - s.first + 1));
  return out;
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v.empty() ? 0 : v[v.size() / 2];
}

// Fraction of the components that cross the whole patch.
double fraction_spanning(const StripModel& m) {
  const auto spans = component_spans(m);
  double n = 0;
  for (double s : spans) n += s >= double(m.strips().size()) ? 1 : 0;
  return spans.empty() ? 0 : n / double(spans.size());
}

// Strips in which one fracture id (before merging) holds two elements: a fork.
long twice_in_a_strip(const StripModel& m) {
  long n = 0;
  for (const Strip& s : m.strips()) {
    std::map<int32_t, int> count;
    for (const Element& e : s.elements)
      if (e.kind == ElementKind::Fracture) n += ++count[e.id] == 2 ? 1 : 0;
  }
  return n;
}

// Coefficient of variation of the gaps between consecutive fractures along each strip.
double spacing_cv(const StripModel& m) {
  std::vector<double> gaps;
  for (const Strip& s : m.strips()) {
    std::vector<double> at;
    for (size_t i = 0; i < s.size(); ++i)
      if (s.elements[i].kind == ElementKind::Fracture) at.push_back(s.x[i] / s.circumference);
    for (size_t k = 0; k + 1 < at.size(); ++k) gaps.push_back(at[k + 1] - at[k]);
    if (at.size() > 1) gaps.push_back(at.front() + 1 - at.back());
  }
  double mean = 0, var = 0;
  for (double g : gaps) mean += g;
  mean /= double(gaps.size());
  for (double g : gaps) var += (g - mean) * (g - mean);
  return std::sqrt(var / double(gaps.size())) / mean;
}

}  // namespace

TEST(FractureIrregularity, Explore) {
  for (int k = 0; k < 5; ++k) {
    StripParams p = patch_params();
    if (k == 1) p.toughness_fraction = 0.1;
    if (k == 2) p.anastomosis = 0.5;
    if (k == 3) p.fork_probability = 0.1;
    if (k == 4) p.weakness_noise = 0.8;
    const StripModel m = run(p);
    const auto sp = component_spans(m);
    printf("k %d comps %zu median span %g spanning %g joined %lld merged %lld forked %lld twice %ld cv %g created %lld\n", k, sp.size(),
           median(sp), fraction_spanning(m), m.stats().joined, m.stats().merged, m.stats().forked, twice_in_a_strip(m), spacing_cv(m),
           m.stats().created);
  }
}
