// Marking the points next to a set of points of a TetComplex, in parallel: the rings of free
// vertices around the interface that the motion carries and smooths and the repair inspects.
#pragma once

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cstdint>
#include <vector>

#include "bark/growth/tet_complex.h"

namespace phellem::bark {

// Sets mark[w] = value for every corner w of the tetrahedra with a corner p for which from(p)
// holds, where mark[w] is still 0 and take(w) holds. One pass over all tetrahedra in order,
// which at the growth benchmark's sizes costs less than walking the stars of the points (about
// 25 scattered tetrahedra each). The pass only reads (from may read mark); the marks are set
// after it, so they are the same whatever the thread count.
template <class From, class Take>
void mark_next_to(const TetComplex& c, std::vector<uint8_t>& mark, uint8_t value, From from, Take take) {
  constexpr size_t kBlock = 16384;
  std::vector<std::vector<uint32_t>> found((c.tets.size() + kBlock - 1) / kBlock);
  tbb::parallel_for(size_t(0), found.size(), [&](size_t b) {
    const size_t end = std::min(c.tets.size(), (b + 1) * kBlock);
    for (size_t t = b * kBlock; t < end; ++t) {
      const auto& T = c.tets[t];
      if (!(from(T[0]) || from(T[1]) || from(T[2]) || from(T[3]))) continue;
      for (uint32_t w : T)
        if (mark[w] == 0 && take(w)) found[b].push_back(w);
    }
  });
  for (const auto& f : found)
    for (uint32_t w : f) mark[w] = value;
}

// The points p (ascending) with mark[p] == value.
inline std::vector<uint32_t> marked(const std::vector<uint8_t>& mark, uint8_t value) {
  std::vector<uint32_t> out;
  for (uint32_t p = 0; p < mark.size(); ++p)
    if (mark[p] == value) out.push_back(p);
  return out;
}

}  // namespace phellem::bark
