// The lit comparison for scripts and reports: score, verdict, words, thresholds, every
// per-statistic difference, and each side's statistics by name (for their bars).
#pragma once

#include <nlohmann/json.hpp>

#include "compare/lit_score.h"

namespace phellem {

nlohmann::json lit_comparison_json(const LitStatistics& reference, const LitStatistics& candidate,
                                   const LitComparison& comparison, const LitThresholds& thresholds = kLitThresholds);

}  // namespace phellem
