// The connected parts of the bark interface (Kratt et al., Woodification, sec. 4.5): fronts in
// contact are frozen, never merged, so two trunks growing into each other stay two surfaces.
#pragma once

#include <vector>

#include "bark/growth/tet_complex.h"

namespace phellem::bark {

struct InterfaceComponents {
  int count = 0;
  // Per point: its component (0 … count − 1, numbered in order of their smallest point
  // index), or −1 for a point on no interface face.
  std::vector<int> of_point;
};

// Components of the interface faces, connected through shared corners. Deterministic.
InterfaceComponents interface_components(const TetComplex& c);

}  // namespace phellem::bark
