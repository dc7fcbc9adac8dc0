// Trigonometric functions for the hot paths (direction sampling, environment lookups) as
// polynomials: inverse functions from Abramowitz & Stegun 1964 (|error| ≤ 2e-8 rad before
// float rounding), sin/cos by quadrant reduction and Taylor series on [-π/4, π/4] (error
// below float rounding). libm's correctly rounded versions cost several times more.
// tests/util/test_fast_trig.cpp checks them against std:: over their whole domain.
#pragma once

#include <cmath>

#include "util/math.h"

namespace phellem {

// acos(x) for x ∈ [-1, 1] (A&S 4.4.46).
inline float fast_acos(float x) {
  const float a = std::min(std::abs(x), 1.0f);
  const float p =
      1.5707963050f +
      a * (-0.2145988016f +
           a * (0.0889789874f +
                a * (-0.0501743046f + a * (0.0308918810f + a * (-0.0170881256f + a * (0.0066700901f + a * -0.0012624911f))))));
  const float r = std::sqrt(1.0f - a) * p;
  return x < 0 ? kPi - r : r;
}

// atan2(y, x) (A&S 4.4.49 for atan on [0, 1], then octant reduction); 0 at the origin.
inline float fast_atan2(float y, float x) {
  const float ax = std::abs(x), ay = std::abs(y);
  const float hi = std::max(ax, ay), lo = std::min(ax, ay);
  if (hi == 0) return 0;
  const float t = lo / hi, t2 = t * t;
  float r =
      t * (1.0f +
           t2 * (-0.3333314528f +
                 t2 * (0.1999355085f +
                       t2 * (-0.1420889944f +
                             t2 * (0.1065626393f +
                                   t2 * (-0.0752896400f + t2 * (0.0429096138f + t2 * (-0.0161657367f + t2 * 0.0028662257f))))))));
  if (ay > ax) r = 0.5f * kPi - r;
  if (x < 0) r = kPi - r;
  return std::copysign(r, y);
}

// sin(x) and cos(x) together, for |x| up to a few thousand radians.
inline void fast_sincos(float x, float* sin_out, float* cos_out) {
  const float q = std::nearbyint(x * (2.0f * kInvPi));  // quadrant
  // r = x − q·π/2 in two steps (Cody–Waite) to keep the reduction exact enough.
  const float r = (x - q * 1.5703125f) - q * 4.8382679e-4f;
  const float r2 = r * r;
  const float s = r * (1.0f + r2 * (-1.0f / 6 + r2 * (1.0f / 120 + r2 * (-1.0f / 5040 + r2 * (1.0f / 362880)))));
  const float c = 1.0f + r2 * (-0.5f + r2 * (1.0f / 24 + r2 * (-1.0f / 720 + r2 * (1.0f / 40320 + r2 * (-1.0f / 3628800)))));
  switch (int(q) & 3) {
    case 0:
      *sin_out = s;
      *cos_out = c;
      break;
    case 1:
      *sin_out = c;
      *cos_out = -s;
      break;
    case 2:
      *sin_out = -s;
      *cos_out = -c;
      break;
    default:
      *sin_out = -c;
      *cos_out = s;
      break;
  }
}

}  // namespace phellem
