// The length-weighted orientation histogram of the fissure skeleton, its vertical fraction and
// circular mean, and the earth mover's distance between two such histograms (plan §3.3).
#pragma once

#include <array>
#include <vector>

namespace phellem {

inline constexpr int kOrientationHistogramBins = 18;  // 10° bins centred on 0°, 10°, …, 170°
using OrientationHistogram = std::array<double, kOrientationHistogramBins>;

// A digital line at angle φ has 1/max(|cos φ|, |sin φ|) units of length per pixel.
double skeleton_length_weight(double angle_deg);

struct OrientationSummary {
  OrientationHistogram histogram{};  // sums to 1 (all 0 without samples)
  double vertical_fraction = 0;     // weight share with |φ − 90°| ≤ the half-width
  double mean_deg = 0;              // circular (axial) mean in [0, 180)
  double total_weight = 0;          // Σw: the skeleton length in pixels
};

// `angles_deg` in [0, 180): one per skeleton pixel, each weighted by skeleton_length_weight.
OrientationSummary orientation_summary(const std::vector<double>& angles_deg, double vertical_halfwidth_deg);

// The exact 1-D circular EMD (Rabin, Delon & Gousseau 2011; Werman et al. 1985): with
// D = cumsum(a − b), EMD = bin width · Σ|D − median(D)|, in degrees. a, b each sum to 1.
double circular_emd_deg(const OrientationHistogram& a, const OrientationHistogram& b);

}  // namespace phellem
