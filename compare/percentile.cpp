#include "compare/percentile.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <type_traits>

namespace phellem {
namespace {

// An unsigned integer that orders like the floating-point value (finite values; −0 before +0):
// the sign bit set for positives, every bit flipped for negatives.
template <class T>
using KeyOf = std::conditional_t<sizeof(T) == 4, uint32_t, uint64_t>;

template <class T>
KeyOf<T> order_key(T v) {
  using K = KeyOf<T>;
  constexpr K sign = K(1) << (8 * sizeof(K) - 1);
  const K bits = std::bit_cast<K>(v);
  return bits & sign ? ~bits : bits | sign;
}

// The order statistics at `ranks` (ascending, < values.size()) by a radix selection: a
// histogram of the keys' top 16 bits finds the bucket of each rank and its rank within the
// bucket; the values of those few buckets are gathered and nth_element picks the statistic.
// Exact, two passes, and `values` is not reordered.
template <class T>
std::vector<T> order_statistics(const std::vector<T>& values, const std::vector<size_t>& ranks) {
  constexpr int kShift = 8 * int(sizeof(KeyOf<T>)) - 16;
  std::vector<size_t> count(size_t(1) << 16, 0);
  for (T v : values) ++count[size_t(order_key(v) >> kShift)];
  std::vector<size_t> bucket(ranks.size()), within(ranks.size());
  size_t below = 0, b = 0;
  for (size_t i = 0; i < ranks.size(); ++i) {
    while (below + count[b] <= ranks[i]) below += count[b++];
    bucket[i] = b;
    within[i] = ranks[i] - below;
  }
  std::vector<size_t> wanted;  // the distinct buckets, ascending
  for (size_t i = 0; i < ranks.size(); ++i)
    if (wanted.empty() || wanted.back() != bucket[i]) wanted.push_back(bucket[i]);
  std::vector<std::vector<T>> in_bucket(wanted.size());
  for (size_t k = 0; k < wanted.size(); ++k) in_bucket[k].reserve(count[wanted[k]]);
  for (T v : values) {
    const size_t key = size_t(order_key(v) >> kShift);
    for (size_t k = 0; k < wanted.size(); ++k)
      if (key == wanted[k]) in_bucket[k].push_back(v);
  }
  std::vector<T> out(ranks.size());
  for (size_t i = 0; i < ranks.size(); ++i) {
    std::vector<T>& m = in_bucket[size_t(std::lower_bound(wanted.begin(), wanted.end(), bucket[i]) - wanted.begin())];
    std::nth_element(m.begin(), m.begin() + long(within[i]), m.end());
    out[i] = m[within[i]];
  }
  return out;
}

}  // namespace

template <class T>
std::vector<double> percentiles(const std::vector<T>& values, const std::vector<double>& qs) {
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
  const std::vector<T> at = order_statistics(values, ranks);
  auto value_at = [&](size_t r) { return double(at[size_t(std::lower_bound(ranks.begin(), ranks.end(), r) - ranks.begin())]); };
  for (size_t i = 0; i < qs.size(); ++i) {
    const double r = rank(qs[i]);
    const size_t lo = size_t(std::floor(r)), hi = std::min(lo + 1, values.size() - 1);
    const double a = value_at(lo), b = value_at(hi);
    out[i] = hi == lo ? a : a + (b - a) * (r - double(lo));
  }
  return out;
}

template <class T>
double percentile(const std::vector<T>& values, double q) {
  return percentiles(values, {q})[0];
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

template std::vector<double> percentiles(const std::vector<float>&, const std::vector<double>&);
template std::vector<double> percentiles(const std::vector<double>&, const std::vector<double>&);
template double percentile(const std::vector<float>&, double);
template double percentile(const std::vector<double>&, double);
template MeanStd mean_std(const std::vector<float>&);
template MeanStd mean_std(const std::vector<double>&);

}  // namespace phellem
