// The fit's relief stage (compare/fit_relief.h): on a target dressed with a known ridge relief
// it finds a relief that brings the depth ratio closer than the geometry's faint relief, it never returns
// one that scores worse than the geometry's own, and it is deterministic.
#include <gtest/gtest.h>

#include <cmath>

#include "compare/fit_objective.h"
#include "compare/fit_relief.h"

using namespace phellem;

namespace {

double statistic(const Comparison& c, const std::string& name) {
  for (const auto& d : c.core)
    if (d.name == name) return d.difference;
  ADD_FAILURE() << "no statistic " << name;
  return 1;
}

}  // namespace

TEST(FitRelief, FindsARidgeReliefTheTargetHas) {
  const FitSpace space = strip_fit_space();
  const PatchSize size{256, 256, 5.0};
  FitCandidate geometry = space.candidate(space.starts[0]);  // fissured, a faint shoulder, no detail
  ASSERT_TRUE(geometry.strips.relief.enabled);
  ASSERT_EQ(geometry.strips.relief.detail, 0.0);
  FitCandidate want = geometry;
  want.strips.relief = bark::ReliefLook{};
  want.strips.relief.enabled = true;
  want.strips.relief.depth_ratio = 1.0;
  want.strips.relief.detail = 0.3;
  want.strips.relief.wall_noise = 0.1;
  const FissureStats target = analyse_fissures(simulate_candidate(want, size, 7), nullptr, "target").stats;

  const std::vector<uint64_t> seeds{fit_simulation_seed(1, 0), fit_simulation_seed(1, 1)};
  ReliefFitOptions o;
  o.max_evals = 30;
  const ReliefFitResult r = fit_relief(geometry.strips, target, size, seeds, o);
  EXPECT_EQ(r.evaluations, 30);
  EXPECT_LE(r.f, r.f_off);
  EXPECT_LT(r.f, r.f_off - 0.03) << "the relief should matter on this target";
  EXPECT_GT(r.look.detail, 0.0) << "the target's relief has fbm detail";

  // The depth ratio, the statistic the relief is for, is closer with the fitted relief.
  FitCandidate got = geometry;
  got.strips.relief = r.look;
  const double without = statistic(score_candidate(geometry, target, size, seeds[0]).comparison, "depth_ratio");
  const double with = statistic(score_candidate(got, target, size, seeds[0]).comparison, "depth_ratio");
  EXPECT_LT(with, without) << "depth_ratio difference with the fitted relief " << with << ", without " << without;

  // Deterministic: the same search again gives the same relief.
  const ReliefFitResult again = fit_relief(geometry.strips, target, size, seeds, o);
  EXPECT_EQ(again.f, r.f);
  EXPECT_EQ(again.look.depth_ratio, r.look.depth_ratio);
  EXPECT_EQ(again.look.wall_noise, r.look.wall_noise);
}

TEST(FitRelief, KeepsTheGeometrysOwnReliefWhenNothingBeatsIt) {
  const FitSpace space = strip_fit_space();
  const PatchSize size{256, 256, 5.0};
  const FitCandidate geometry = space.candidate(space.starts[0]);
  // The target is the geometry itself on the search's first seed: its own relief scores 0 there.
  const std::vector<uint64_t> seeds{fit_simulation_seed(1, 0)};
  const FissureStats target = analyse_fissures(simulate_candidate(geometry, size, seeds[0]), nullptr, "target").stats;
  ReliefFitOptions o;
  o.max_evals = 8;
  const ReliefFitResult r = fit_relief(geometry.strips, target, size, seeds, o);
  EXPECT_DOUBLE_EQ(r.f_off, 0.0);  // the very same field: every statistic equal
  EXPECT_EQ(r.f, r.f_off);
  EXPECT_EQ(r.look.detail, geometry.strips.relief.detail);
  EXPECT_EQ(r.look.depth_ratio, geometry.strips.relief.depth_ratio);
}
