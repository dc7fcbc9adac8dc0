// The fit's parameter table: the normalized mapping and candidates the models accept.
#include <gtest/gtest.h>

#include "bark/stress/stress_params.h"
#include "bark/strips/presets.h"
#include "compare/fit_parameters.h"
#include "util/random.h"

using namespace phellem;

TEST(FitParameters, NormalizedValuesRoundTrip) {
  for (const FitSpace& s : {strip_fit_space(), stress_fit_space()})
    for (const FitParameter& p : s.table) {
      EXPECT_LT(p.lo, p.hi) << p.key;
      for (double x : {0.0, 0.25, 0.5, 1.0}) EXPECT_NEAR(p.normalized(p.value(x)), x, 1e-9) << p.key;
      EXPECT_DOUBLE_EQ(p.value(0), p.lo) << p.key;
      EXPECT_NEAR(p.value(1), p.hi, 1e-12 * p.hi) << p.key;
    }
}

TEST(FitParameters, EveryStripCandidateIsValid) {
  const FitSpace s = strip_fit_space();
  EXPECT_EQ(s.starts.size(), 4u);  // the vertical presets
  StreamRng rng(5, 0, 0);
  for (int k = 0; k < 2000; ++k) {
    std::vector<double> x(s.dimension());
    for (double& v : x) v = k < 4 ? double(k & 1) : rng.uniform();  // corners first
    const FitCandidate c = s.candidate(x);
    const auto e = bark::validate(c.strips.params);
    ASSERT_FALSE(e) << "candidate " << k << ": " << e->key << ": " << e->message;
  }
}

TEST(FitParameters, APresetIsReproducedFromItsStart) {
  const FitSpace s = strip_fit_space();
  // The fissured preset (the first start) within the table's ranges comes back.
  const FitCandidate c = s.candidate(s.starts[0]);
  const bark::StripParams p = *bark::strip_preset("fissured");
  EXPECT_NEAR(c.strips.params.attachment, p.attachment, 1e-6);
  EXPECT_NEAR(c.strips.params.inglis_threshold, p.inglis_threshold, 1e-4);
  EXPECT_NEAR(c.strips.params.propagation_jitter_deg, p.propagation_jitter_deg, 1e-4);
  EXPECT_NEAR(c.strips.params.strip_width, p.strip_width, 1e-7);
}

TEST(FitParameters, EveryStressCandidateIsValid) {
  const FitSpace s = stress_fit_space();
  StreamRng rng(6, 0, 0);
  for (int k = 0; k < 500; ++k) {
    std::vector<double> x(s.dimension());
    for (double& v : x) v = rng.uniform();
    const auto e = bark::validate(s.candidate(x).stress.params);
    ASSERT_FALSE(e) << e->key << ": " << e->message;
  }
}

TEST(FitParameters, NarrowRowSearchesAroundTheMeasuredValue) {
  FitSpace s = strip_fit_space();
  narrow_row(s, "spiral_deg", -5, 4);
  size_t i = 0;
  while (s.table[i].key != "spiral_deg") ++i;
  EXPECT_DOUBLE_EQ(s.table[i].lo, -9);
  EXPECT_DOUBLE_EQ(s.table[i].hi, -1);
  for (const auto& x : s.starts) EXPECT_NEAR(s.candidate(x).strips.params.spiral_deg, -5, 1e-6);
  std::vector<double> corner(s.dimension(), 1.0);
  EXPECT_NEAR(s.candidate(corner).strips.params.spiral_deg, -1, 1e-6);
  EXPECT_THROW(narrow_row(s, "no_such_key", 0, 1), std::logic_error);
  EXPECT_THROW(narrow_row(s, "strip_width", 0.01, 0.005), std::logic_error);  // log-mapped
}
