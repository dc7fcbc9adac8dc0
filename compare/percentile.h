// Percentiles as numpy computes them by default (linear interpolation between order
// statistics), which the issue-22 prototype's thresholds and medians use.
#pragma once

#include <vector>

namespace phellem {

// q in [0, 100]: the value at rank q/100·(n − 1) of the sorted values, interpolated linearly
// between its two neighbours. `values` is taken by value and reordered. 0 for no values.
double percentile(std::vector<double> values, double q);
inline double median(std::vector<double> values) { return percentile(std::move(values), 50); }

// Population mean and standard deviation (ddof = 0, as numpy's std); {0, 0} for no values.
struct MeanStd {
  double mean = 0, std = 0;
};
MeanStd mean_std(const std::vector<double>& values);

}  // namespace phellem
