// Fracture propagation (Lefebvre & Neyret 2002, sec. 4.3): tips advance only into stretched
// bark, continue across strip boundaries, and the Inglis measure counts every fracture element
// exactly once.
#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <map>

#include "bark/strips/fracture_ends.h"
#include "bark/strips/presets.h"
#include "bark/strips/strip_model.h"
#include "tests/support/strip_helpers.h"

using namespace phellem::bark;

TEST(StripModel, InglisMeasureCountsEveryFractureElementOnce) {
  // After each step, a fracture's count is the number of its elements in the strips, whichever
  // thread settled them (the widths are summed in integers by fracture id as strips settle),
  // and its summed width is positive and below the strips' total circumference.
  for (int threads : {1, 2}) {
    tbb::global_control c(tbb::global_control::max_allowed_parallelism, size_t(threads));
    StripParams p = phellem::test::small_strip_params();
    p.steps = 60;
    StripModel m(flat_domain(0.3, 0.3, p), p);
    size_t checked = 0;
    for (int step = 0; step + 1 < p.steps; ++step) {  // the last step also settles
      m.step();
      std::map<int32_t, double> count;
      double total = 0;
      for (const Strip& s : m.strips()) {
        total += s.circumference;
        for (const Element& e : s.elements)
          if (e.kind == ElementKind::Fracture) count[m.skeleton().find(s.fractures[size_t(e.fracture)].id)] += 1;
      }
      for (const auto& [root, n] : count) {
        const auto [measured, width] = m.inglis_measure(root);
        ASSERT_EQ(measured, n) << "fracture " << root << " after step " << step << ", " << threads << " threads";
        EXPECT_GT(width, 0.0);
        EXPECT_LT(width, total);
        ++checked;
      }
    }
    EXPECT_GT(checked, 100u);
  }
}

TEST(StripModel, FractureReachingAStripBoundaryContinuesInTheNeighbour) {
  StripParams p = phellem::test::small_strip_params();
  p.threshold_noise = 0;
  p.threshold = p.growth_rate;  // nothing breaks on its own before the scripted fracture
  p.steps = 3;
  p.scripted.push_back({0.155, 3.0, 0});
  p.inglis_threshold = 1e-3;  // any sharp fracture propagates
  p.propagation_tension = 0;
  StripModel m(flat_domain(0.3, 0.3, p), p);
  m.step();
  ASSERT_EQ(m.stats().scripted, 1);
  EXPECT_GT(m.stats().propagated, 0);
  // The scripted fracture's component now spans strips above and below its own.
  const size_t j = 15;
  const Strip& s = m.strips()[j];
  ASSERT_FALSE(s.fractures.empty());
  const FractureElement& fe = s.fractures[0];
  EXPECT_GE(fe.up, 0);
  EXPECT_GE(fe.down, 0);
  const FractureElement& up = m.strips()[j + 1].fractures[size_t(fe.up)];
  EXPECT_EQ(m.skeleton().find(up.id), m.skeleton().find(fe.id));

  // The same fracture with an Inglis threshold it cannot reach stays on its strip.
  p.inglis_threshold = 1e9;
  StripModel q(flat_domain(0.3, 0.3, p), p);
  q.step();
  EXPECT_EQ(q.stats().propagated, 0);
  EXPECT_LT(q.strips()[j].fractures[0].up, 0);
}

TEST(StripModel, TipAdvancesOnlyIntoStretchedBark) {
  // Inglis: the stress concentrates at a tip, so a sharp tip advances only if the bark across
  // it in the next strip is in tension. Strip 16's substrate does not grow (a zero dilatation
  // exponent), so its bark stays at rest; strip 14 is stretched like the rest.
  StripParams p = phellem::test::small_strip_params();
  p.threshold_noise = 0;
  p.threshold = p.growth_rate;  // nothing breaks on its own before the scripted fracture
  p.steps = 3;
  p.inglis_threshold = 1e-3;  // any sharp fracture propagates
  p.propagation_tension = 0.5;
  p.scripted.push_back({0.155, 3.0, 0});
  StripDomain domain = flat_domain(0.3, 0.3, p);
  const auto run_step = [&](const StripDomain& d) {
    StripModel m(d, p);
    m.step();
    EXPECT_EQ(m.stats().scripted, 1);
    return m.strips()[15].fractures.at(0);
  };
  const FractureElement free_growth = run_step(domain);
  EXPECT_GE(free_growth.up, 0);
  EXPECT_GE(free_growth.down, 0);
  domain.strips[16].exponent.assign(domain.strips[16].bin_length.size(), 0.0);
  const FractureElement at_rest_above = run_step(domain);
  EXPECT_LT(at_rest_above.up, 0) << "advanced into bark at rest";
  EXPECT_GE(at_rest_above.down, 0) << "did not advance into stretched bark";
}

TEST(StripModel, InglisCountsStayExactOnMatureBark) {
  // A mature bark (the furrowed preset, 500 steps) has merged fractures, whose elements keep
  // ids that are no longer roots; when one of them propagates into a strip that also breaks
  // on its own in the same step, the new element must be counted once (it was counted twice,
  // once by the propagation and again as a new fracture, off by one for a step: 39 against
  // 38 elements for fracture 219 after step 446 of this run).
  StripParams p = *strip_preset("furrowed");
  StripModel m(flat_domain(0.94, 1.5, p), p);
  size_t checked = 0;
  for (int step = 0; step + 1 < p.steps; ++step) {  // the last step also settles
    m.step();
    std::map<int32_t, double> count;
    for (const Strip& s : m.strips())
      for (const Element& e : s.elements)
        if (e.kind == ElementKind::Fracture) count[m.skeleton().find(s.fractures[size_t(e.fracture)].id)] += 1;
    for (const auto& [root, n] : count)
      ASSERT_EQ(m.inglis_measure(root).first, n) << "fracture " << root << " after step " << step;
    checked += count.size();
  }
  EXPECT_GT(checked, 10000u);
  EXPECT_GT(m.stats().merged, 100);
}
