// What `phellem fit` minimizes: a candidate simulated at the evaluation scale, measured, and
// compared with the photo's statistics: score + orientation EMD / 90°. A candidate the model
// refuses, or a patch without any relief, scores kFitPenalty.
#pragma once

#include <cstdint>
#include <vector>

#include "compare/compare_score.h"
#include "compare/fissure_statistics.h"
#include "compare/fit_parameters.h"

namespace phellem {

inline constexpr double kFitPenalty = 2.0;  // above any score + EMD/90 (at most 1 + 1)

// The simulation seed of replicate r (0: the search's, the one fitted.json keeps).
uint64_t fit_simulation_seed(uint64_t seed, int replicate);

struct FitScore {
  double f = kFitPenalty;
  Comparison comparison;
  bool valid = false;
};

// `target`: the photo's statistics at `size`'s scale.
FitScore score_candidate(const FitCandidate& c, const FissureStats& target, const PatchSize& size, uint64_t seed);

// Degrees of orientation distance that weigh as much as 1 of score: 30 makes the target's
// 3° cost 0.1, as much as the score's same-bark band (at 90 a 3.5° miss cost only 0.04 and
// the search let it stand).
inline constexpr double kFitDegreesPerScore = 30.0;
inline double fit_objective_value(const Comparison& c) { return c.score + c.orientation_emd_deg / kFitDegreesPerScore; }

}  // namespace phellem
