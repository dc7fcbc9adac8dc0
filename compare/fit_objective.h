// What `phellem fit` minimizes: a candidate simulated at the evaluation scale, measured, and
// compared with the photo's statistics: score + orientation EMD / 100° + 0.1 per degree of EMD
// beyond 2°. A candidate the model refuses, or a patch without any relief, scores kFitPenalty.
#pragma once

#include <algorithm>
#include <cstdint>
#include <optional>
#include <vector>

#include "compare/compare_score.h"
#include "compare/fissure_statistics.h"
#include "compare/fit_parameters.h"

namespace phellem {

// Above any objective: the score is at most 1 and the EMD at most 90° (1 + 3 + 8.8).
inline constexpr double kFitPenalty = 16.0;

// The simulation seed of replicate r (0: the search's, the one fitted.json keeps).
uint64_t fit_simulation_seed(uint64_t seed, int replicate);

struct FitScore {
  double f = kFitPenalty;
  Comparison comparison;
  bool valid = false;
};

// `target`: the photo's statistics at `size`'s scale.
FitScore score_candidate(const FitCandidate& c, const FissureStats& target, const PatchSize& size, uint64_t seed);
// Its two halves: the candidate's patch (none when the model refuses the parameters), and a
// patch's score against the target (invalid, kFitPenalty, when its relief is constant).
std::optional<HeightField> try_simulate_candidate(const FitCandidate& c, const PatchSize& size, uint64_t seed);
FitScore score_field(const HeightField& field, const FissureStats& target);

// Degrees of orientation distance that weigh as much as 1 of score. Before the fit searched
// the fissures' lean (spiral_deg), pine's 5° lean was out of reach and 30 was needed to hold
// its EMD near 3°; with the lean fitted, the hinge below holds it, and at 30 the search gave
// up 0.03 of score per degree it won below 2° (pine: 0.146 at 1.8°).
inline constexpr double kFitDegreesPerScore = 100.0;
// Beyond 2° (the middle of the 1.1–3.1° that two halves of one scan measure, docs/compare.md),
// each degree costs 0.1 more: with the linear term alone, a pine fit settled at 4.1° for a
// lower score (0.10), where the halves of the same scan reach 3.1° at most.
inline constexpr double kFitFreeDegrees = 2.0;
inline constexpr double kFitExcessPerDegree = 0.1;
inline double fit_objective_value(const Comparison& c) {
  const double emd = c.orientation_emd_deg;
  return c.score + emd / kFitDegreesPerScore + kFitExcessPerDegree * std::max(0.0, emd - kFitFreeDegrees);
}

}  // namespace phellem
