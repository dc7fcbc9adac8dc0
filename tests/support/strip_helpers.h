// Quick strip-model settings shared by the strip tests: 1 cm strips and elements, strong
// attachment, soft fractures that propagate readily.
#pragma once

#include "bark/strips/strip_domain.h"
#include "bark/strips/strip_model.h"
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

// Small flat sample with quick settings.
inline bark::StripParams small_strip_params() { return quick_strip_params(120, 1.004); }

// A flat w × h sample grown for p.steps steps.
inline bark::StripModel run_flat(const bark::StripParams& p, double w = 0.3, double h = 0.3, bool check = false) {
  bark::StripModel m(bark::flat_domain(w, h, p), p);
  m.set_check_equilibrium(check);
  for (int i = 0; i < p.steps; ++i) m.step();
  return m;
}

}  // namespace phellem::test
