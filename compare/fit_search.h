// The search behind `phellem fit` (docs/plans/issue-22-compare-fit.md §4), on any objective
// over the unit cube [0, 1]^n:
//  - phase A: the given starts (the model's presets) and a scrambled Latin hypercube sample of
//    samples_per_dimension · n points drawn from the seed, evaluated two at a time;
//  - phase B: NLopt's Subplex (LN_SBPLX) from the best points, two local searches at a time,
//    round after round (each round restarts from the best point so far and the next best
//    phase-A point with a smaller step) until the budget is spent or the rounds run out;
//  - the end: the best `rescore_points` distinct points are scored again on
//    `rescore_replicates` more replicates (other simulation seeds) and the lowest mean wins.
// The sequence of evaluated points depends on the seed and the options only, never on the
// thread count or the timing: the time budget only truncates it (tests use max_evals).
#pragma once

#include <cstdint>
#include <functional>
#include <vector>

namespace phellem {

struct FitSearchOptions {
  uint64_t seed = 1;
  long long max_evals = 0;   // 0: no limit (the re-scoring is counted too)
  double time_budget_s = 0;  // 0: no limit; the search keeps back time for the re-scoring
  int samples_per_dimension = 8;
  int rounds = 3;  // local rounds when neither max_evals nor the time budget limits the search
  double initial_step = 0.15;
  double xtol_rel = 1e-3;
  int rescore_points = 3, rescore_replicates = 2;
};

// f(x, replicate): the objective at x ∈ [0, 1]^n; replicate 0 is the search's own (common
// random numbers), 1… the re-scoring's. Called from up to two threads at once. An exception
// stops the search and is rethrown by fit_search.
using FitObjective = std::function<double(const std::vector<double>& x, int replicate)>;

struct FitEvaluation {
  std::vector<double> x;
  double f = 0;
  int replicate = 0;
};

struct FitSearchResult {
  std::vector<double> x;      // the chosen point
  double f = 0;               // its mean over the replicates it was scored on
  double f_min = 0, f_max = 0;  // the spread of those scores
  int replicates = 1;
  std::vector<FitEvaluation> history;  // every evaluation, in the deterministic order
  bool budget_stopped = false;         // the time budget ended the search
};

// Called after each evaluation with the number done and the best objective value so far
// (search replicate), from either thread (never concurrently).
using FitProgress = std::function<void(long long evaluations, double best)>;

FitSearchResult fit_search(size_t n, const FitObjective& f, const std::vector<std::vector<double>>& starts,
                           const FitSearchOptions& options, const FitProgress& progress = {});

}  // namespace phellem
