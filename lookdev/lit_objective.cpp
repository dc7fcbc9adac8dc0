#include "lookdev/lit_objective.h"

namespace phellem {

namespace {

LitSubject uniform_subject(const HeightField& h, const float albedo[3], const std::string& label) {
  LitSubject s;
  s.label = label;
  s.height = h;
  AlbedoField a;
  a.width = h.width;
  a.height = h.height;
  a.rgb.resize(size_t(h.width) * size_t(h.height) * 3);
  for (size_t p = 0; p < a.rgb.size(); ++p) a.rgb[p] = albedo[p % 3];
  s.albedo = std::move(a);
  return s;
}

}  // namespace

LitObjective make_lit_objective(const HeightField& photo_m, const AlbedoField* albedo, const std::string& name) {
  LitObjective o;
  o.rig.spp = kLitObjectiveSpp;
  if (albedo && !albedo->rgb.empty()) {
    double sum[3] = {0, 0, 0};
    const size_t n = albedo->rgb.size() / 3;
    for (size_t p = 0; p < n; ++p)
      for (int c = 0; c < 3; ++c) sum[c] += albedo->rgb[p * 3 + size_t(c)];
    for (int c = 0; c < 3; ++c) o.albedo[c] = float(sum[c] / double(n));
  }
  o.reference = lit_statistics(render_lit(uniform_subject(photo_m, o.albedo, name), o.rig).image, name);
  return o;
}

double lit_objective_value(const LitObjective& o, const HeightField& candidate_m, LitComparison* comparison) {
  const LitRender r = render_lit(uniform_subject(candidate_m, o.albedo, "<fit candidate>"), o.rig, 1);
  const LitComparison c = compare_lit(o.reference, lit_statistics(r.image, "<fit candidate>"));
  double sum = 0;
  int n = 0;
  for (const LitGroupScore& g : c.groups)
    if (g.group != "colour") sum += g.score, ++n;
  if (comparison) *comparison = c;
  return n ? sum / n : 1.0;
}

}  // namespace phellem
