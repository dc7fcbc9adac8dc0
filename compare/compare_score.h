// The compare score: the mean relative difference of the core fissure statistics, and the
// earth mover's distance between the orientation histograms.
#pragma once

#include <string>
#include <vector>

#include "compare/fissure_statistics.h"

namespace phellem {

inline constexpr double kSameBarkScore = 0.13;  // two halves of one scan score 0.03–0.13
inline constexpr double kCloseScore = 0.18;

struct StatisticDifference {
  std::string name;  // e.g. "spacing_h_mean"
  double a = 0, b = 0;
  double difference = 0;  // |a − b| / max(|a|, |b|), in [0, 1]
};

struct Comparison {
  double score = 0;                  // mean of the core differences
  double orientation_emd_deg = 0;    // circular earth mover's distance of the histograms
  std::vector<StatisticDifference> core;
  std::string verdict;               // "same bark", "close", "different"
};

Comparison compare_fissures(const FissureStats& a, const FissureStats& b);

}  // namespace phellem
