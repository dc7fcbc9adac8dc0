#include "lookdev/lit_variants.h"

#include "compare/fissure_statistics.h"

namespace phellem {

namespace {

AlbedoField albedo_or_grey(const LitSubject& s) {
  if (s.albedo) return *s.albedo;
  AlbedoField a;
  a.width = s.height.width;
  a.height = s.height.height;
  a.rgb.assign(size_t(a.width) * size_t(a.height) * 3, kLitDefaultAlbedo);
  return a;
}

}  // namespace

LitSubject half_of(const LitSubject& s, bool vertical_cut, bool second) {
  const int w = s.height.width, h = s.height.height;
  const int x0 = vertical_cut && second ? w / 2 : 0, y0 = !vertical_cut && second ? h / 2 : 0;
  const int hw = vertical_cut ? w / 2 : w, hh = vertical_cut ? h : h / 2;
  LitSubject out;
  out.label = s.label + (vertical_cut ? (second ? " right" : " left") : (second ? " bottom" : " top"));
  out.height.width = hw;
  out.height.height = hh;
  out.height.px_per_cm = s.height.px_per_cm;
  if (s.albedo) {
    out.albedo = AlbedoField{};
    out.albedo->width = hw;
    out.albedo->height = hh;
  }
  for (int y = 0; y < hh; ++y)
    for (int x = 0; x < hw; ++x) {
      const size_t from = size_t(y + y0) * size_t(w) + size_t(x + x0);
      out.height.z.push_back(s.height.z[from]);
      if (s.albedo)
        for (int c = 0; c < 3; ++c) out.albedo->rgb.push_back(s.albedo->rgb[from * 3 + size_t(c)]);
    }
  return out;
}

LitSubject with_relief_scaled(const LitSubject& s, double factor) {
  LitSubject out = s;
  out.label += " relief ×" + std::to_string(factor).substr(0, 4);
  for (float& z : out.height.z) z = float(z * factor);
  return out;
}

LitSubject with_mean_albedo(const LitSubject& s) {
  LitSubject out = s;
  out.label += " mean albedo";
  AlbedoField a = albedo_or_grey(s);
  double mean[3] = {0, 0, 0};
  const size_t n = size_t(a.width) * size_t(a.height);
  for (size_t p = 0; p < n; ++p)
    for (int c = 0; c < 3; ++c) mean[c] += a.rgb[p * 3 + size_t(c)];
  for (size_t p = 0; p < n; ++p)
    for (int c = 0; c < 3; ++c) a.rgb[p * 3 + size_t(c)] = float(mean[c] / double(n));
  out.albedo = std::move(a);
  return out;
}

LitSubject with_black_fissure_floors(const LitSubject& s) {
  LitSubject out = s;
  out.label += " black fissures";
  const FissureAnalysis fa = analyse_fissures(s.height, nullptr, s.label);
  AlbedoField a = albedo_or_grey(s);
  for (size_t p = 0; p < fa.mask.size(); ++p)
    if (fa.mask[p])
      for (int c = 0; c < 3; ++c) a.rgb[p * 3 + size_t(c)] = 0.0f;
  out.albedo = std::move(a);
  return out;
}

}  // namespace phellem
