// The fit's search driver on an analytic objective: a shifted quadratic in the unit cube.
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <cmath>
#include <thread>

#include "compare/fit_search.h"

using namespace phellem;

namespace {

const std::vector<double> kMinimum{0.31, 0.72, 0.45, 0.18};

double quadratic(const std::vector<double>& x) {
  double f = 0;
  for (size_t i = 0; i < x.size(); ++i) f += (i + 1.0) * (x[i] - kMinimum[i]) * (x[i] - kMinimum[i]);
  return f;
}

}  // namespace

TEST(FitSearch, FindsTheMinimumOfAShiftedQuadratic) {
  FitSearchOptions o;
  o.seed = 3;
  const FitSearchResult r = fit_search(4, [](const std::vector<double>& x, int) { return quadratic(x); }, {}, o);
  ASSERT_EQ(r.x.size(), 4u);
  for (size_t i = 0; i < 4; ++i) EXPECT_NEAR(r.x[i], kMinimum[i], 1e-3) << "parameter " << i;
  EXPECT_LT(r.f, 1e-5);
  EXPECT_EQ(r.replicates, 3);  // re-scored on 2 more replicates
}

TEST(FitSearch, SameSeedSamePointsWhateverTheTiming) {
  FitSearchOptions o;
  o.seed = 11;
  o.max_evals = 120;
  // Evaluations that take uneven times: the order of the results must not depend on them.
  auto slow = [](const std::vector<double>& x, int rep) {
    std::this_thread::sleep_for(std::chrono::microseconds(int(x[0] * 300)));
    return quadratic(x) + 1e-3 * rep;
  };
  const FitSearchResult a = fit_search(4, slow, {{0.5, 0.5, 0.5, 0.5}}, o);
  const FitSearchResult b = fit_search(4, slow, {{0.5, 0.5, 0.5, 0.5}}, o);
  ASSERT_EQ(a.history.size(), 120u);
  ASSERT_EQ(a.history.size(), b.history.size());
  for (size_t i = 0; i < a.history.size(); ++i) {
    EXPECT_EQ(a.history[i].x, b.history[i].x) << "evaluation " << i;
    EXPECT_EQ(a.history[i].replicate, b.history[i].replicate) << "evaluation " << i;
  }
  EXPECT_EQ(a.x, b.x);
  // The starts come first; another seed samples other points.
  EXPECT_EQ(a.history[0].x, (std::vector<double>{0.5, 0.5, 0.5, 0.5}));
  o.seed = 12;
  const FitSearchResult c = fit_search(4, slow, {{0.5, 0.5, 0.5, 0.5}}, o);
  EXPECT_NE(a.history[1].x, c.history[1].x);
}

TEST(FitSearch, TheTimeBudgetStopsIt) {
  FitSearchOptions o;
  o.time_budget_s = 0.5;
  std::atomic<int> calls{0};
  auto slow = [&](const std::vector<double>& x, int) {
    ++calls;
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
    return quadratic(x);
  };
  const auto t0 = std::chrono::steady_clock::now();
  const FitSearchResult r = fit_search(4, slow, {}, o);
  const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  EXPECT_TRUE(r.budget_stopped);
  EXPECT_LT(s, 0.8);
  EXPECT_GT(calls.load(), 10);
  EXPECT_EQ(r.replicates, 3);  // time was kept for the re-scoring
}

TEST(FitSearch, AnExceptionInTheObjectiveReachesTheCaller) {
  FitSearchOptions o;
  o.max_evals = 200;
  std::atomic<int> calls{0};
  auto failing = [&](const std::vector<double>& x, int) {
    if (++calls == 60) throw std::runtime_error("objective failed");
    return quadratic(x);
  };
  // Phase A is 4·8 = 32 points: the 60th call is inside a Subplex run.
  o.samples_per_dimension = 8;
  EXPECT_THROW(fit_search(4, [&](const std::vector<double>& x, int r) { return failing(x, r); }, {}, o), std::runtime_error);
}
