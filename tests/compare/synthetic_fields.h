// Height fields built in code for the compare tests and benchmarks (plan issue-22 §3,
// "Synthetic tests"; the prototype's synth.py and synth2.py).
#pragma once

#include <cstdint>

#include "compare/height_field.h"

namespace phellem::test {

// z = −1 inside fissures of width `W` px repeating every `P` px, 0 elsewhere; the fissures run at
// `angle_deg` counter-clockwise from +x with y up (90 = vertical). Across them, u = x·sin θ + y·cos θ
// (y down the rows), and a pixel is in a fissure when (u − offset_px) mod P < W.
HeightField stripes(int size, double px_per_cm, double P, double W, double angle_deg = 90, double offset_px = 0);

// White Gaussian noise (σ 1) blurred by G(sigma_px), seeded.
HeightField smooth_noise(int size, double px_per_cm, double sigma_px, uint64_t seed);

// `count` random V-shaped vertical fissures (length 50–200 px, width 3–8 px, tilt N(0, 0.08))
// cut into 0.6·G(4 px)∗white noise (plan §3, "Two scales").
HeightField v_fissures(int size, double px_per_cm, int count, uint64_t seed);

// a + k·b pixel by pixel (same size).
HeightField add(const HeightField& a, const HeightField& b, double k);

}  // namespace phellem::test
