#include "compare/percentile.h"

#include <algorithm>
#include <cmath>

namespace phellem {

namespace {

// Puts the order statistic of every rank in `ranks` (ascending, within [first, last)) at its
// position: nth_element at the middle rank splits the range, and each half holds only its
// own ranks, so every later selection runs on a part of the values.
template <class It>
void select_ranks(It begin, It first, It last, const size_t* ranks, size_t count) {
  if (count == 0) return;
  const size_t m = count / 2;
  const It nth = begin + long(ranks[m]);
  std::nth_element(first, nth, last);
  select_ranks(begin, first, nth, ranks, m);
  select_ranks(begin, nth + 1, last, ranks + m + 1, count - m - 1);
}

}  // namespace

template <class T>
std::vector<double> percentiles(std::vector<T> values, const std::vector<double>& qs) {
  std::vector<double> out(qs.size(), 0.0);
  if (values.empty()) return out;
  // Each q needs the order statistics at floor(rank) and the one after it.
  auto rank = [&](double q) { return q / 100.0 * double(values.size() - 1); };
  std::vector<size_t> ranks;
  for (double q : qs) {
    const size_t lo = size_t(std::floor(rank(q)));
    ranks.push_back(lo);
    ranks.push_back(std::min(lo + 1, values.size() - 1));
  }
  std::sort(ranks.begin(), ranks.end());
  ranks.erase(std::unique(ranks.begin(), ranks.end()), ranks.end());
  select_ranks(values.begin(), values.begin(), values.end(), ranks.data(), ranks.size());
  for (size_t i = 0; i < qs.size(); ++i) {
    const double r = rank(qs[i]);
    const size_t lo = size_t(std::floor(r)), hi = std::min(lo + 1, values.size() - 1);
    const double a = double(values[lo]), b = double(values[hi]);
    out[i] = hi == lo ? a : a + (b - a) * (r - double(lo));
  }
  return out;
}

template <class T>
double percentile(std::vector<T> values, double q) {
  return percentiles(std::move(values), {q})[0];
}

template <class T>
MeanStd mean_std(const std::vector<T>& values) {
  MeanStd m;
  if (values.empty()) return m;
  for (T v : values) m.mean += double(v);
  m.mean /= double(values.size());
  double var = 0;
  for (T v : values) var += (double(v) - m.mean) * (double(v) - m.mean);  // two passes: no cancellation
  m.std = std::sqrt(var / double(values.size()));
  return m;
}

template std::vector<double> percentiles(std::vector<float>, const std::vector<double>&);
template std::vector<double> percentiles(std::vector<double>, const std::vector<double>&);
template double percentile(std::vector<float>, double);
template double percentile(std::vector<double>, double);
template MeanStd mean_std(const std::vector<float>&);
template MeanStd mean_std(const std::vector<double>&);

}  // namespace phellem
