#include "bark/strips/fracture_ends.h"

#include <algorithm>

namespace phellem::bark {

std::vector<int> fracture_ends_per_strip(const StripModel& m) {
  const size_t n = m.strips().size();
  const bool wrap = m.domain().wrap_s;
  std::vector<int> ends(n, 0);
  for (size_t j = 0; j < n; ++j)
    for (const Element& e : m.strips()[j].elements)
      if (e.kind == ElementKind::Fracture) ends[j] += int(e.up < 0 && (wrap || j + 1 < n)) + int(e.down < 0 && (wrap || j > 0));
  return ends;
}

EndsPeak ends_peak(const std::vector<int>& ends) {
  EndsPeak r;
  if (ends.size() < 7) return r;
  std::vector<int> runs;
  for (size_t j = 3; j + 3 < ends.size(); ++j) runs.push_back(ends[j - 1] + ends[j] + ends[j + 1]);
  const auto peak = std::max_element(runs.begin(), runs.end());
  r.peak = *peak;
  r.strip = size_t(peak - runs.begin()) + 3;
  std::nth_element(runs.begin(), runs.begin() + long(runs.size() / 2), runs.end());
  r.median = runs[runs.size() / 2];
  return r;
}

}  // namespace phellem::bark
