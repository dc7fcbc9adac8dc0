// Growth rings (Kratt et al., sec. 4.2, Fig. 6a): every N steps the cambium (the interface of
// the growing TetComplex) is recorded as a ring; a cross-section of the wood shows the rings'
// traces in a plane. Rings of a growth that never moves the interface inwards stay nested.
#pragma once

#include <array>
#include <vector>

#include "bark/growth/tet_complex.h"

namespace phellem::bark {

struct GrowthRing {
  int step = 0;
  std::vector<Eigen::Vector3d> points;
  std::vector<std::array<uint32_t, 3>> faces;  // outwards
};

// The interface as it is now (its own compact copy).
GrowthRing record_ring(const TetComplex& c, int step);
// The same from the interface faces the caller has already.
GrowthRing record_ring(const TetComplex& c, const std::vector<std::array<uint32_t, 3>>& faces, int step);

// The ring's trace in the plane through `origin` with unit normal `normal`: segments of the
// faces the plane crosses (faces lying in the plane are skipped).
std::vector<std::array<Eigen::Vector3d, 2>> slice_ring(const GrowthRing& ring, const Eigen::Vector3d& origin,
                                                         const Eigen::Vector3d& normal);

}  // namespace phellem::bark
