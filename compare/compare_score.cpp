#include "compare/compare_score.h"

#include <algorithm>
#include <cmath>

#include "compare/orientation_histogram.h"

namespace phellem {

// Plan §3.9: the mean over the 7 core statistics of |a − b| / max(|a|, |b|), each in [0, 1].
Comparison compare_fissures(const FissureStats& a, const FissureStats& b) {
  struct Core {
    const char* name;
    double FissureStats::*field;
  };
  static constexpr Core kCore[] = {
      {"fissure_fraction", &FissureStats::fissure_fraction}, {"vertical_fraction", &FissureStats::vertical_fraction},
      {"spacing_h_mean", &FissureStats::spacing_h_mean},     {"spacing_h_std", &FissureStats::spacing_h_std},
      {"width_mean", &FissureStats::width_mean},             {"length_median", &FissureStats::length_median},
      {"depth_ratio", &FissureStats::depth_ratio},
  };
  Comparison c;
  double sum = 0;
  for (const Core& k : kCore) {
    StatisticDifference d;
    d.name = k.name;
    d.a = a.*k.field;
    d.b = b.*k.field;
    d.difference = std::abs(d.a - d.b) / std::max({std::abs(d.a), std::abs(d.b), 1e-12});
    sum += d.difference;
    c.core.push_back(d);
  }
  c.score = sum / double(c.core.size());
  c.orientation_emd_deg = circular_emd_deg(a.orientation_hist, b.orientation_hist);
  c.verdict = c.score <= kSameBarkScore ? "same bark" : c.score <= kCloseScore ? "close" : "different";
  return c;
}

}  // namespace phellem
