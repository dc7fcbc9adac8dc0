// Every fixed parameter of the fissure measurement (docs/compare.md, plan issue-22 §3), in one
// place; the JSON report writes them out.
#pragma once

#include "compare/gaussian_blur.h"

namespace phellem {

struct CompareParams {
  // How every blur reads beyond the border (plan §2: clamped). The prototype used scipy's
  // "reflect"; on the reference scans the two differ by ≤ 0.01 in every score (docs/compare.md).
  BlurBorder blur_border = BlurBorder::clamp;
  double highpass_sigma_cm = 1.5;        // §3.1 hp = z − G(σ)∗z
  double smooth_sigma_cm = 0.1;          // §3.1 hs = G(σ)∗hp
  double threshold_percentile = 5;       // §3.1 t = ½(median(hs) + P5(hs))
  double min_component_cm2 = 0.25;       // §3.1 smaller 8-connected fissure components are dropped
  double tensor_sigma_cm = 0.3;          // §3.3 structure tensor window
  double vertical_halfwidth_deg = 30;    // §3.3 |φ − 90°| ≤ this counts as vertical
  double ridge_dilation_cm = 0.1;        // §3.7 ridge = NOT(mask dilated by this)
  double min_size_cm = 20;               // §3.0 refuse smaller images (after resampling)
  int min_size_px = 128;
  double min_px_per_cm = 2;
};
inline constexpr CompareParams kCompareParams{};

}  // namespace phellem
