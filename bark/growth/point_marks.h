// Marking the points around a set of points of a TetComplex, in parallel: the rings of free
// vertices around the interface that the motion smooths and the repair inspects.
#pragma once

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <atomic>
#include <cstdint>
#include <span>
#include <vector>

#include "bark/growth/tet_adjacency.h"

namespace phellem::bark {

// Sets mark[w] = value for every corner w of the tetrahedra around the points of `from` for
// which take(w) holds and whose mark is still 0. Every writer of a point writes the same value,
// so the marks are the same whatever the thread count.
template <class Take>
void mark_around(const TetComplex& c, const TetAdjacency& adj, std::span<const uint32_t> from, std::vector<uint8_t>& mark,
                 uint8_t value, Take take) {
  tbb::parallel_for(tbb::blocked_range<size_t>(0, from.size(), 256), [&](const tbb::blocked_range<size_t>& r) {
    for (size_t i = r.begin(); i != r.end(); ++i)
      for (uint32_t t : adj.around(from[i]))
        for (uint32_t w : c.tets[t])
          if (take(w) && std::atomic_ref<uint8_t>(mark[w]).load(std::memory_order_relaxed) == 0)
            std::atomic_ref<uint8_t>(mark[w]).store(value, std::memory_order_relaxed);
  });
}

// The points p (ascending) with mark[p] == value.
inline std::vector<uint32_t> marked(const std::vector<uint8_t>& mark, uint8_t value) {
  std::vector<uint32_t> out;
  for (uint32_t p = 0; p < mark.size(); ++p)
    if (mark[p] == value) out.push_back(p);
  return out;
}

}  // namespace phellem::bark
