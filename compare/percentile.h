// Percentiles as numpy computes them by default (linear interpolation between order
// statistics), which the issue-22 prototype's thresholds and medians use.
#pragma once

#include <vector>

namespace phellem {

// q in [0, 100]: the value at rank q/100·(n − 1) of the sorted values, interpolated linearly
// between its two neighbours; 0 for no values. T is float or double (finite values).
template <class T>
double percentile(const std::vector<T>& values, double q);
template <class T>
double median(const std::vector<T>& values) {
  return percentile(values, 50);
}

// Several percentiles of one sample, one result per q (in the order of `qs`), in two passes
// over the values whatever the number of qs.
template <class T>
std::vector<double> percentiles(const std::vector<T>& values, const std::vector<double>& qs);

// Population mean and standard deviation (ddof = 0, as numpy's std); {0, 0} for no values.
struct MeanStd {
  double mean = 0, std = 0;
};
template <class T>
MeanStd mean_std(const std::vector<T>& values);

}  // namespace phellem
