#include "compare/lit_statistic_names.h"

#include <sstream>

namespace phellem {
namespace {

std::string number(double v) {
  std::ostringstream s;
  s << v;
  return s.str();
}

}  // namespace

std::vector<NamedStatistic> named_lit_statistics(const LitStatistics& s) {
  std::vector<NamedStatistic> v;
  v.push_back({"median_luminance", "", "median Rec.709 luminance (depends on exposure; not scored)", s.median_luminance, false});
  for (int k = 0; k < kLitPercentileCount; ++k) {
    const double q = kLitParams.percentiles[size_t(k)];
    // Appended piecewise: "P" + number(q) trips a known false -Wrestrict of GCC 12 at -O3.
    std::string description = "P";
    description += number(q);
    description += " of ln Y − ln median(Y)";
    v.push_back({"log_luminance_p" + std::string(q < 10 ? "0" : "") + number(q), "ln", description,
                 s.log_luminance_percentiles[size_t(k)], true});
  }
  v.push_back({"near_black_share", "",
               "share of pixels darker than " + number(100 * kLitParams.near_black_ratio) + " % of the median luminance",
               s.near_black_share, true});
  v.push_back({"orientation_anisotropy", "", "how strongly the edges share one direction (0 isotropic, 1 one direction)",
               s.orientation_anisotropy, true});
  v.push_back({"orientation_mean_deg", "°", "mean edge direction (90° = along the trunk)", s.orientation_mean_deg, false});
  for (int k = 0; k < kOrientationHistogramBins; ++k)
    v.push_back({"orientation_bin_" + number(10 * k), "", "share of edge strength within ±5° of " + number(10 * k) + "°",
                 s.orientation_hist[size_t(k)], true});
  for (const SpectrumBand& b : s.bands)
    v.push_back({"band_" + number(b.lo_cycles_per_cm) + "_" + number(b.hi_cycles_per_cm), "",
                 "share of log-luminance power at " + number(b.lo_cycles_per_cm) + "–" + number(b.hi_cycles_per_cm) +
                     " cycles/cm (periods " + number(1 / b.hi_cycles_per_cm) + "–" + number(1 / b.lo_cycles_per_cm) + " cm)",
                 b.share, true});
  for (int k = 0; k < kLitContrastScales; ++k) {
    const double sigma = kLitParams.contrast_sigma_cm[size_t(k)];
    v.push_back({"local_contrast_" + number(sigma) + "cm", "ln",
                 "std of the log-luminance band G(" + number(sigma) + " cm) − G(" + number(2 * sigma) + " cm)",
                 s.local_contrast[size_t(k)], true});
  }
  const LitColour& c = s.colour;
  v.push_back({"colour_L_mean", "", "CIELAB L*, mean (exposure normalised: median luminance at L* 49.5)", c.L_mean, false});
  v.push_back({"colour_a_mean", "", "CIELAB a* (green–red), mean", c.a_mean, false});
  v.push_back({"colour_b_mean", "", "CIELAB b* (blue–yellow), mean", c.b_mean, false});
  v.push_back({"colour_chroma", "", "chroma of the mean colour: the strength of the cast", c.chroma, true});
  v.push_back({"colour_hue_deg", "°", "hue of the mean colour (0° red, 90° yellow, 180° green, 270° blue)", c.hue_deg, false});
  v.push_back({"colour_L_std", "", "CIELAB L*, spread", c.L_std, true});
  v.push_back({"colour_a_std", "", "CIELAB a*, spread", c.a_std, true});
  v.push_back({"colour_b_std", "", "CIELAB b*, spread", c.b_std, true});
  return v;
}

}  // namespace phellem
