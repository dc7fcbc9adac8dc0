// The statistics of one rendered picture of bark (issue 44 item 2): what the lit score compares
// between a reference render (a scan's height and albedo) and a candidate render under the same
// light rig. docs/compare.md, "Lit statistics (issue 44)", gives every equation and constant.
// Every statistic is independent of exposure: multiplying all RGB by k > 0 changes nothing
// (up to float rounding) — only median_luminance, which is reported and never scored.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "compare/octave_spectrum.h"        // SpectrumBand
#include "compare/orientation_histogram.h"  // OrientationHistogram (18 bins of 10°, centred on 0°, 10°, …)

namespace phellem {

// A rendered picture: linear Rec.709 RGB, row 0 at the top, one scale along both axes.
struct LitImage {
  int width = 0, height = 0;
  double px_per_cm = 0;
  std::vector<float> rgb;      // height × width × 3, row-major
  std::vector<uint8_t> valid;  // height × width, 1 = measured; empty = every pixel. Masked
                               // pixels are never read: any value (also NaN) changes nothing.
};

inline constexpr int kLitPercentileCount = 8;
inline constexpr int kLitContrastScales = 3;

// Every fixed parameter of the lit statistics, in one place.
struct LitParams {
  // Percentiles of ln Y − ln median(Y), Y the Rec.709 luminance of the valid pixels.
  std::array<double, kLitPercentileCount> percentiles = {1, 5, 10, 25, 75, 90, 95, 99};
  double near_black_ratio = 0.03;       // Y < this × median(Y) is near-black
  double luminance_floor_ratio = 1e-4;  // Y is floored at this × median(Y) before the log (ln → ≥ −9.21)
  double gradient_sigma_cm = 0.2;       // log-luminance smoothed by G(σ) before its gradient
  // Local contrast: the std of G(σ)∗ℓ − G(2σ)∗ℓ over the valid pixels, at each σ.
  std::array<double, kLitContrastScales> contrast_sigma_cm = {0.25, 1, 4};
  double contrast_min_sigma_px = 4;  // coarser scales are measured on a 2^k box-decimated grid
                                     // where σ is at least this many (decimated) pixels
  double colour_median_Y = 0.18;     // colour: RGB scaled so the median luminance is this (L* 49.5)
  double min_px_per_cm = 4;          // the finest contrast scale, 0.25 cm, is ≥ 1 px
  int min_side_px = 32;
  int min_valid_pixels = 1024;
};
inline constexpr LitParams kLitParams{};

// CIELAB (D65) statistics after the exposure is normalised (kLitParams.colour_median_Y).
struct LitColour {
  double L_mean = 0, a_mean = 0, b_mean = 0;  // the cast is (a_mean, b_mean)
  double chroma = 0;                          // hypot(a_mean, b_mean)
  double hue_deg = 0;                         // atan2(b_mean, a_mean) in [0, 360)
  double L_std = 0, a_std = 0, b_std = 0;     // the spread (population std)
};

struct LitStatistics {
  int width = 0, height = 0, valid_pixels = 0;
  double px_per_cm = 0;
  double median_luminance = 0;                                          // median Y: depends on exposure, reported only
  std::array<double, kLitPercentileCount> log_luminance_percentiles{};  // at LitParams::percentiles
  double near_black_share = 0;  // share of valid pixels with Y < near_black_ratio × median(Y)
  // Edge direction (gradient direction + 90°, counter-clockwise from +x with y up, mod 180°:
  // 90° = edges along the trunk, as the fissure histogram of compare), weighted by |∇ℓ|, Σ = 1.
  OrientationHistogram orientation_hist{};
  double orientation_anisotropy = 0;  // |Σ|∇ℓ|·e^{2iθ}| / Σ|∇ℓ|, 0 = isotropic, 1 = one direction
  double orientation_mean_deg = 0;    // ½·arg Σ|∇ℓ|·e^{2iθ}, in [0, 180)
  std::vector<SpectrumBand> bands;    // octave_band_power of ℓ (bands depend on size and scale)
  std::array<double, kLitContrastScales> local_contrast{};  // at LitParams::contrast_sigma_cm
  LitColour colour;
};

// Measures `image`. Throws UserError(name, "", …) when the image is empty or too small, the
// scale is under kLitParams.min_px_per_cm, the sizes of rgb/valid do not match, a valid pixel
// is NaN or infinite, fewer than min_valid_pixels are valid, or the median luminance is ≤ 0.
LitStatistics lit_statistics(const LitImage& image, const std::string& name, const LitParams& params = kLitParams);

}  // namespace phellem
