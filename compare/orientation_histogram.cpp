#include "compare/orientation_histogram.h"

#include <algorithm>
#include <cmath>
#include <complex>
#include <numbers>

#include "compare/percentile.h"

namespace phellem {
namespace {

constexpr double kBinDeg = 180.0 / kOrientationHistogramBins;
constexpr double kRad = std::numbers::pi / 180;

}  // namespace

double skeleton_length_weight(double angle_deg) {
  const double a = angle_deg * kRad;
  return 1.0 / std::max(std::abs(std::cos(a)), std::abs(std::sin(a)));
}

OrientationSummary orientation_summary(const std::vector<double>& angles_deg, double vertical_halfwidth_deg) {
  OrientationSummary s;
  double vertical = 0;
  std::complex<double> axial = 0;
  for (double a : angles_deg) {
    const double w = skeleton_length_weight(a);
    // Bins centred on 0°, 10°, …: bin k holds [10k − 5°, 10k + 5°), and 175° and above wrap to
    // bin 0 (plan §3.3: edge-aligned bins would put a 90° stripe at 95°).
    const int bin = int(std::floor((a + kBinDeg / 2) / kBinDeg)) % kOrientationHistogramBins;
    s.histogram[size_t(bin)] += w;
    s.total_weight += w;
    if (std::abs(a - 90) <= vertical_halfwidth_deg) vertical += w;
    axial += w * std::polar(1.0, 2 * a * kRad);  // axial data: average e^{2iφ}
  }
  if (s.total_weight <= 0) return s;
  for (double& h : s.histogram) h /= s.total_weight;
  s.vertical_fraction = vertical / s.total_weight;
  double mean = 0.5 * std::arg(axial) / kRad;
  if (mean < 0) mean += 180;
  s.mean_deg = mean >= 180 ? mean - 180 : mean;
  return s;
}

double circular_emd_deg(const OrientationHistogram& a, const OrientationHistogram& b) {
  // On a circle, the transport cost of a flow shifted by c everywhere is Σ|D − c|, minimal at
  // c = median(D) (Rabin et al. 2011, §3).
  std::vector<double> d(a.size());
  double run = 0;
  for (size_t k = 0; k < a.size(); ++k) d[k] = run += a[k] - b[k];
  const double c = median(d);
  double emd = 0;
  for (double v : d) emd += std::abs(v - c);
  return kBinDeg * emd;
}

}  // namespace phellem
