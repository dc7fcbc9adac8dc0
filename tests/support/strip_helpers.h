// Quick strip-model settings shared by the strip tests: 1 cm strips and elements, strong
// attachment, soft fractures that propagate readily.
#pragma once

#include "bark/strips/strip_params.h"

namespace phellem::test {

inline bark::StripParams quick_strip_params(int steps, double growth_rate) {
  bark::StripParams p;
  p.steps = steps;
  p.growth_rate = growth_rate;
  p.strip_width = 0.01;
  p.element_length = 0.01;
  p.attachment = 0.2;
  p.inglis_threshold = 10;
  p.fracture_stiffness = {{0.0, 0.1}};
  return p;
}

}  // namespace phellem::test
