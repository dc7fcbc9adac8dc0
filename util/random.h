// Counter-based random numbers for the strip model: every draw is a pure function of
// (seed, stream, step, counter), so results do not depend on the thread count.
#pragma once

#include <cstdint>

#include "util/hash.h"

namespace phellem {

class StreamRng {
 public:
  StreamRng(uint64_t seed, uint64_t stream, uint64_t step)
      : state_(mix64(seed * 0x9e3779b97f4a7c15ULL + mix64(stream * 0x632be59bd9b4e019ULL + step))) {}
  uint64_t next() { return mix64(state_ += 0x9e3779b97f4a7c15ULL); }
  double uniform() { return double(next() >> 11) * 0x1.0p-53; }  // [0, 1)
  double symmetric() { return 2.0 * uniform() - 1.0; }           // [-1, 1)

 private:
  uint64_t state_;
};

}  // namespace phellem
