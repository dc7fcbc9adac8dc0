// STAND-IN until branch `stats` lands: crude versions of analyse_fissures and
// compare_fissures so that `phellem fit` builds and runs end to end. Delete this file at the
// merge (the real definitions then link in its place).
#include <algorithm>
#include <cmath>
#include <numeric>
#include <tuple>

#include "compare/compare_score.h"
#include "compare/fissure_statistics.h"
#include "util/errors.h"

namespace phellem {

namespace {

double percentile(std::vector<float> v, double q) {
  if (v.empty()) return 0;
  const size_t k = std::min(v.size() - 1, size_t(q * double(v.size())));
  std::nth_element(v.begin(), v.begin() + long(k), v.end());
  return v[k];
}

// Centres of the runs of 1 along a line that do not touch its ends: gaps and run lengths.
void runs(const std::vector<uint8_t>& m, size_t start, size_t stride, int n, std::vector<double>& gaps, std::vector<double>& lens) {
  double last = -1;
  int i = 0;
  while (i < n) {
    if (!m[start + size_t(i) * stride]) {
      ++i;
      continue;
    }
    int j = i;
    while (j < n && m[start + size_t(j) * stride]) ++j;
    if (i > 0 && j < n) {
      const double c = 0.5 * (i + j - 1);
      if (last >= 0) gaps.push_back(c - last);
      last = c;
      lens.push_back(j - i);
    }
    i = j;
  }
}

std::pair<double, double> mean_std(const std::vector<double>& v) {
  if (v.empty()) return {0, 0};
  const double m = std::accumulate(v.begin(), v.end(), 0.0) / double(v.size());
  double s = 0;
  for (double x : v) s += (x - m) * (x - m);
  return {m, std::sqrt(s / double(v.size()))};
}

}  // namespace

FissureAnalysis analyse_fissures(const HeightField& f, const AlbedoField*, const std::string& name) {
  const int W = f.width, H = f.height;
  if (W < 16 || H < 16) throw UserError(name, "", "stand-in statistics: image too small");
  FissureAnalysis a;
  a.field = f;
  const double lo = percentile(f.z, 0.05), med = percentile(f.z, 0.5);
  if (!(med > lo)) throw UserError(name, "", "the relief is constant");
  const double t = 0.5 * (lo + med);
  a.mask.resize(f.z.size());
  for (size_t i = 0; i < f.z.size(); ++i) a.mask[i] = f.z[i] < t;
  FissureStats& s = a.stats;
  s.fissure_fraction = double(std::count(a.mask.begin(), a.mask.end(), 1)) / double(a.mask.size());
  std::vector<double> gh, lh, gv, lv;
  for (int y = 0; y < H; ++y) runs(a.mask, size_t(y) * W, 1, W, gh, lh);
  for (int x = 0; x < W; ++x) runs(a.mask, size_t(x), size_t(W), H, gv, lv);
  const double cm = 1.0 / f.px_per_cm;
  std::tie(s.spacing_h_mean, s.spacing_h_std) = mean_std(gh);
  std::tie(s.spacing_v_mean, s.spacing_v_std) = mean_std(gv);
  s.spacing_h_mean *= cm, s.spacing_h_std *= cm, s.spacing_v_mean *= cm, s.spacing_v_std *= cm;
  s.width_mean = mean_std(lh).first * cm;
  s.length_median = mean_std(lv).first * cm;
  double gx = 0, gy = 0;
  for (int y = 1; y < H; ++y)
    for (int x = 1; x < W; ++x) {
      gx += std::abs(f.at(x, y) - f.at(x - 1, y));
      gy += std::abs(f.at(x, y) - f.at(x, y - 1));
    }
  s.vertical_fraction = gx / std::max(1e-30, gx + gy);
  std::vector<float> ridge, fissure;
  for (size_t i = 0; i < f.z.size(); ++i) (a.mask[i] ? fissure : ridge).push_back(f.z[i]);
  const double relief = percentile(ridge, 0.9) - percentile(ridge, 0.1);
  s.depth_ratio = (percentile(ridge, 0.5) - percentile(fissure, 0.5)) / std::max(1e-30, relief);
  return a;
}

Comparison compare_fissures(const FissureStats& a, const FissureStats& b) {
  Comparison c;
  auto add = [&](const char* name, double x, double y) {
    const double m = std::max(std::abs(x), std::abs(y));
    c.core.push_back({name, x, y, m > 0 ? std::abs(x - y) / m : 0.0});
  };
  add("fissure_fraction", a.fissure_fraction, b.fissure_fraction);
  add("vertical_fraction", a.vertical_fraction, b.vertical_fraction);
  add("spacing_h_mean", a.spacing_h_mean, b.spacing_h_mean);
  add("spacing_h_std", a.spacing_h_std, b.spacing_h_std);
  add("width_mean", a.width_mean, b.width_mean);
  add("length_median", a.length_median, b.length_median);
  add("depth_ratio", a.depth_ratio, b.depth_ratio);
  for (const auto& d : c.core) c.score += d.difference / double(c.core.size());
  c.verdict = c.score <= kSameBarkScore ? "same bark" : c.score <= kCloseScore ? "close" : "different";
  return c;
}

}  // namespace phellem
