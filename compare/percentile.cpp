#include "compare/percentile.h"

#include <algorithm>
#include <cmath>

namespace phellem {

double percentile(std::vector<double> values, double q) {
  if (values.empty()) return 0;
  const double rank = q / 100.0 * double(values.size() - 1);
  const size_t lo = size_t(std::floor(rank));
  const size_t hi = std::min(lo + 1, values.size() - 1);
  std::nth_element(values.begin(), values.begin() + long(lo), values.end());
  const double a = values[lo];
  if (hi == lo) return a;
  // The next order statistic is the smallest value above position lo.
  const double b = *std::min_element(values.begin() + long(hi), values.end());
  const double t = rank - double(lo);
  return a + (b - a) * t;
}

MeanStd mean_std(const std::vector<double>& values) {
  MeanStd m;
  if (values.empty()) return m;
  for (double v : values) m.mean += v;
  m.mean /= double(values.size());
  double var = 0;
  for (double v : values) var += (v - m.mean) * (v - m.mean);  // two passes: no cancellation
  m.std = std::sqrt(var / double(values.size()));
  return m;
}

}  // namespace phellem
