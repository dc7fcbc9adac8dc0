// Free fracture ends along the strips: where fracture tips stopped. A horizontal seam in the
// bark, a height where fractures stop and start again, shows as a strip holding many more
// ends than its neighbourhood; the tests and bench/strip_ends.cpp look for it.
#pragma once

#include <cstddef>
#include <vector>

#include "bark/strips/strip_model.h"

namespace phellem::bark {

// Per strip: the free sides of its fracture elements, not counting the sides that face past
// the first or last strip (where every fracture ends).
std::vector<int> fracture_ends_per_strip(const StripModel& m);

// The densest run of three strips against the median run, away from the first and last two
// strips.
struct EndsPeak {
  double median = 0;
  int peak = 0;
  size_t strip = 0;  // the run's middle strip
};
EndsPeak ends_peak(const std::vector<int>& ends);

}  // namespace phellem::bark
