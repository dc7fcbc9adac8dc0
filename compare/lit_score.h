// The lit score (issue 44 item 2): how far a candidate render's statistics are from the
// reference render's, per statistic, as a verdict and in the words an artist uses.
// docs/compare.md, "Lit statistics (issue 44)", gives the equations.
#pragma once

#include <string>
#include <vector>

#include "compare/lit_statistics.h"

namespace phellem {

// Every threshold of the verdict and the words, calibrated on the reference scans under the lit
// rig (docs/compare.md, "Lit calibration"; bench/lit_calibration.cpp): halves of one scan score
// 0.054–0.157 with no group above 0.26; the deliberate defects each put one group at 0.37 or
// more; Bark Brown vs Pine scores 0.25.
struct LitThresholds {
  double same_score = 0.16;            // score ≤ this and no group over `group`: "same look"
  double close_score = 0.22;           // score ≤ this: "close", above: "different"
  double group = 0.30;                 // a group differing by more is never the "same look", and only then are its words said
  double word = 0.25;                  // a signed difference beyond ± this names a defect (when its group differs)
  double strong_word = 0.5;            // ... and beyond ± this whatever its group
  double cast_delta_e = 4;             // |Δ(mean a*, mean b*)| in ΔE*ab units that names a cast
  double orientation_emd_deg = 10;     // circular EMD of the edge histograms: "grain direction differs"
  double fine_band_cycles_per_cm = 1;  // octaves from here up are the "fine detail" of the spectrum
};
inline constexpr LitThresholds kLitThresholds{};

struct LitDifference {
  std::string name;   // e.g. "log_luminance_p05", "near_black_share", "band_1_2"
  std::string group;  // "tone", "dark", "orientation", "spectrum", "contrast", "colour"
  double reference = 0, candidate = 0;
  double signed_difference = 0;  // (candidate − reference) / max(|candidate|, |reference|, floor), in [−1, 1]
  double difference = 0;         // its magnitude, in [0, 1]: what the score averages
};

struct LitGroupScore {
  std::string group;
  double score = 0;  // mean difference of the group's statistics
};

struct LitComparison {
  double score = 0;  // mean over the groups of each group's mean difference, in [0, 1]
  std::vector<LitGroupScore> groups;
  std::vector<LitDifference> differences;
  double orientation_emd_deg = 0;  // circular EMD of the two edge histograms
  std::string verdict;             // "same look", "close", "different"
  std::vector<std::string> words;  // e.g. "fissures too dark", "too warm"; empty when nothing stands out
};

// Candidate against reference (the order matters for the signs and the words). Both were measured
// with kLitParams (the rows are named after its percentiles and scales). Spectrum bands are
// compared over the octaves both have, their shares renormalised to sum 1 over those.
LitComparison compare_lit(const LitStatistics& reference, const LitStatistics& candidate,
                          const LitThresholds& thresholds = kLitThresholds);

}  // namespace phellem
