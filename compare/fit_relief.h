// The fit's second stage: the fbm detail of strip bark's ridge relief
// (bark/dressing/bark_relief.h), with the rest of the relief refined, fitted to the photo with
// the fissure geometry held fixed. The geometry search dresses its candidates with the relief
// minus the detail (shoulder and rough walls: rows of its table); detail dips break fissures
// into short pieces, so searching it jointly spoils the fissure length. Each seed is simulated
// once and every relief candidate dresses copies of those fields, so candidates differ by their
// relief only. The geometry's own relief is the baseline, kept unless another scores below it.
#pragma once

#include <cstdint>
#include <vector>

#include "compare/fissure_statistics.h"
#include "compare/fit_parameters.h"

namespace phellem {

struct ReliefFitOptions {
  int max_evals = 60;        // relief candidates, each scored on every seed
  double time_budget_s = 0;  // 0: no limit
};

struct ReliefFitResult {
  bark::ReliefLook look;   // the geometry's own (walls only) unless a ridge relief scores below it
  double f_off = 0;        // the geometry's mean objective with its own relief
  double f = 0;            // with `look` (== f_off when the relief is off)
  int evaluations = 0;     // relief candidates scored (not counting the undressed one)
};

// The rows searched, on the candidate's strips.relief: depth_ratio, shoulder_width, detail,
// detail_size, wall_noise, wall_size.
const std::vector<FitParameter>& relief_fit_rows();

// Fits the relief of `geometry` (strip model; its own relief is the baseline) to `target` at
// `size`, the objective being the mean of fit_objective_value over `seeds`. Deterministic.
ReliefFitResult fit_relief(const StripPatchParams& geometry, const FissureStats& target, const PatchSize& size,
                           const std::vector<uint64_t>& seeds, const ReliefFitOptions& options);

}  // namespace phellem
