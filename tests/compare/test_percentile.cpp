// compare/percentile: numpy's linear-interpolation percentiles, checked against a full sort on
// samples with negatives, zeros of both signs, ties and tiny sizes, in float and double.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "compare/percentile.h"

namespace phellem {
namespace {

template <class T>
double sorted_percentile(std::vector<T> v, double q) {
  std::sort(v.begin(), v.end());
  const double rank = q / 100 * double(v.size() - 1);
  const size_t lo = size_t(std::floor(rank)), hi = std::min(lo + 1, v.size() - 1);
  return double(v[lo]) + (double(v[hi]) - double(v[lo])) * (rank - double(lo));
}

template <class T>
void expect_like_sort(const std::vector<T>& v) {
  const std::vector<double> qs = {50, 0, 5, 10, 37.5, 90, 99.9, 100};
  const std::vector<double> got = percentiles(v, qs);
  for (size_t i = 0; i < qs.size(); ++i) {
    EXPECT_EQ(got[i], sorted_percentile(v, qs[i])) << "q " << qs[i] << " n " << v.size();
    EXPECT_EQ(percentile(v, qs[i]), got[i]);
  }
}

TEST(Percentile, EqualsTheSortedSampleInterpolatedLikeNumpy) {
  std::mt19937 rng(7);
  std::normal_distribution<double> g(0, 1);
  for (size_t n : {1, 2, 3, 10, 1000, 100001}) {
    std::vector<double> d(n);
    std::vector<float> f(n);
    for (size_t i = 0; i < n; ++i) {
      d[i] = g(rng) * (i % 3 == 0 ? 1e-30 : 10);  // values near zero land in many fine buckets
      if (i % 17 == 0) d[i] = i % 2 ? 0.0 : -0.0;
      if (i % 5 == 0) d[i] = std::round(d[i]);  // ties
      f[i] = float(d[i]);
    }
    expect_like_sort(d);
    expect_like_sort(f);
  }
  std::vector<float> same(1000, 2.5f);  // a single bucket
  expect_like_sort(same);
  EXPECT_EQ(median(std::vector<double>{3, 1, 2, 10}), 2.5);
  EXPECT_EQ(percentile(std::vector<double>{}, 50), 0);
}

TEST(Percentile, MeanAndPopulationStd) {
  const MeanStd m = mean_std(std::vector<float>{1, 2, 3, 4});
  EXPECT_DOUBLE_EQ(m.mean, 2.5);
  EXPECT_DOUBLE_EQ(m.std, std::sqrt(1.25));
}

}  // namespace
}  // namespace phellem
