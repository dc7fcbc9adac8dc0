// Pictures built in code for the lit statistics tests (issue 44 item 2): linear Rec.709 RGB.
#pragma once

#include <cstdint>

#include "compare/lit_statistics.h"

namespace phellem::test {

// Grey (times `rgb`) with log-luminance ℓ = amplitude·sin(2π·u/period_px), u = x·sin θ + y·cos θ
// (y down the rows): stripes running at `angle_deg` counter-clockwise from +x with y up
// (90 = vertical), as test::stripes.
LitImage sine_stripes(int size, double px_per_cm, double period_px, double angle_deg, double amplitude = 0.5);

// Isotropic log-normal noise: ℓ = amplitude·(G(sigma_px)∗white noise normalised to std 1).
LitImage noise_picture(int size, double px_per_cm, double sigma_px, double amplitude, uint64_t seed);

// A bark-like picture: test::v_fissures heights z, albedo brown·exp(2 z) with a little colour
// noise, lit by a sun at 30° elevation from +x (across the fissures) plus a sky term (5 %).
LitImage bark_picture(int size, double px_per_cm, uint64_t seed);

// Every channel of every pixel times k.
LitImage exposed(const LitImage& im, float k);

}  // namespace phellem::test
