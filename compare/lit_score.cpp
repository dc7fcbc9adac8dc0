#include "compare/lit_score.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace phellem {
namespace {

// The floor of each relative difference: differences between values both under it count as
// small (a near-black share of 0.001 against 0.002 is not a 50 % change in the picture).
constexpr double kPercentileFloor = 0.05;  // ln units: 5 % in luminance
constexpr double kNearBlackFloor = 0.01;   // 1 % of the pixels
constexpr double kAnisotropyFloor = 0.05;
constexpr double kBandShareFloor = 0.01;
constexpr double kContrastFloor = 0.01;       // ln units
constexpr double kColourStdFloor = 1;         // CIELAB units
constexpr double kChromaFloor = 5;            // ΔE*ab: casts below this are all "neutral"
constexpr double kMaxOrientationEmdDeg = 90;  // the largest axial EMD (two peaks 90° apart)

double signed_relative(double reference, double candidate, double floor) {
  return (candidate - reference) / std::max({std::abs(candidate), std::abs(reference), floor});
}

std::string number(double v) {
  std::ostringstream s;
  s << v;
  return s.str();
}

struct Rows {
  std::vector<LitDifference> v;
  void relative(std::string name, std::string group, double r, double c, double floor) {
    const double sd = signed_relative(r, c, floor);
    v.push_back({std::move(name), std::move(group), r, c, sd, std::abs(sd)});
  }
  double signed_of(const std::string& name) const {
    for (const LitDifference& d : v)
      if (d.name == name) return d.signed_difference;
    return 0;
  }
};

// The shares of the octaves both statistics have, renormalised to sum 1 over those.
std::vector<SpectrumBand> common_bands(const std::vector<SpectrumBand>& a, const std::vector<SpectrumBand>& b) {
  std::vector<SpectrumBand> out;
  for (const SpectrumBand& x : a)
    for (const SpectrumBand& y : b)
      if (x.lo_cycles_per_cm == y.lo_cycles_per_cm) out.push_back({x.lo_cycles_per_cm, x.hi_cycles_per_cm, x.share});
  double total = 0;
  for (const SpectrumBand& x : out) total += x.share;
  for (SpectrumBand& x : out) x.share = total > 0 ? x.share / total : 0;
  return out;
}

// The term of largest magnitude: the clearest signal of a group whose terms may disagree.
double strongest(std::initializer_list<double> terms) {
  double best = 0;
  for (double t : terms)
    if (std::abs(t) > std::abs(best)) best = t;
  return best;
}

}  // namespace

LitComparison compare_lit(const LitStatistics& ref, const LitStatistics& cand, const LitThresholds& t) {
  Rows rows;
  // Tone: the log-luminance percentiles relative to the median.
  for (int k = 0; k < kLitPercentileCount; ++k) {
    std::ostringstream name;
    name << "log_luminance_p" << (kLitParams.percentiles[size_t(k)] < 10 ? "0" : "") << kLitParams.percentiles[size_t(k)];
    rows.relative(name.str(), "tone", ref.log_luminance_percentiles[size_t(k)], cand.log_luminance_percentiles[size_t(k)],
                  kPercentileFloor);
  }
  rows.relative("near_black_share", "dark", ref.near_black_share, cand.near_black_share, kNearBlackFloor);
  // Orientation: the circular EMD of the edge histograms (compare's, Rabin et al. 2011) over its
  // largest value, and the anisotropy.
  LitComparison c;
  c.orientation_emd_deg = circular_emd_deg(ref.orientation_hist, cand.orientation_hist);
  const double emd = std::min(1.0, c.orientation_emd_deg / kMaxOrientationEmdDeg);
  rows.v.push_back({"orientation_emd_deg", "orientation", 0, c.orientation_emd_deg, emd, emd});
  rows.relative("orientation_anisotropy", "orientation", ref.orientation_anisotropy, cand.orientation_anisotropy,
                kAnisotropyFloor);
  // Spectrum: per common octave, the renormalised shares.
  const std::vector<SpectrumBand> br = common_bands(ref.bands, cand.bands), bc = common_bands(cand.bands, ref.bands);
  double fine_r = 0, fine_c = 0;
  for (size_t k = 0; k < br.size(); ++k) {
    rows.relative("band_" + number(br[k].lo_cycles_per_cm) + "_" + number(br[k].hi_cycles_per_cm), "spectrum", br[k].share,
                  bc[k].share, kBandShareFloor);
    if (br[k].lo_cycles_per_cm >= t.fine_band_cycles_per_cm) fine_r += br[k].share, fine_c += bc[k].share;
  }
  for (int k = 0; k < kLitContrastScales; ++k)
    rows.relative("local_contrast_" + number(kLitParams.contrast_sigma_cm[size_t(k)]) + "cm", "contrast",
                  ref.local_contrast[size_t(k)], cand.local_contrast[size_t(k)], kContrastFloor);
  // Colour: the spread of L*, a*, b*, and the cast as the 2-D distance of the mean (a*, b*).
  const LitColour& cr = ref.colour;
  const LitColour& cc = cand.colour;
  rows.relative("colour_L_std", "colour", cr.L_std, cc.L_std, kColourStdFloor);
  rows.relative("colour_a_std", "colour", cr.a_std, cc.a_std, kColourStdFloor);
  rows.relative("colour_b_std", "colour", cr.b_std, cc.b_std, kColourStdFloor);
  const double da = cc.a_mean - cr.a_mean, db = cc.b_mean - cr.b_mean, cast = std::hypot(da, db);
  const double cast_difference = std::min(1.0, cast / std::max({cr.chroma, cc.chroma, kChromaFloor}));
  rows.v.push_back({"colour_cast", "colour", cr.chroma, cc.chroma, cast_difference, cast_difference});
  c.differences = rows.v;

  // The score: the mean over the groups of each group's mean difference, so that eight
  // percentiles weigh as much as one near-black share.
  double sum = 0;
  for (const char* g : {"tone", "dark", "orientation", "spectrum", "contrast", "colour"}) {
    double gs = 0;
    int count = 0;
    for (const LitDifference& d : c.differences)
      if (d.group == g) gs += d.difference, ++count;
    if (count == 0) continue;  // no common octave
    c.groups.push_back({g, gs / count});
    sum += gs / count;
  }
  c.score = c.groups.empty() ? 0 : sum / double(c.groups.size());
  double worst_group = 0;
  for (const LitGroupScore& g : c.groups) worst_group = std::max(worst_group, g.score);
  c.verdict = c.score <= t.same_score && worst_group <= t.group ? "same look" : c.score <= t.close_score ? "close" : "different";
  // A word is said when its signal passes `word` and its group as a whole differs beyond `group`,
  // or when the signal alone passes `strong_word`: two halves of one scan differ by up to 0.26
  // in a group, and their words' signals then are noise, not a defect.
  auto group_differs = [&](std::initializer_list<const char*> names) {
    for (const LitGroupScore& g : c.groups)
      for (const char* n : names)
        if (g.group == n && g.score > t.group) return true;
    return false;
  };
  auto says = [&](bool group, double signal) { return (group && signal > t.word) || signal > t.strong_word; };

  // The words, each from the signed differences of its statistics (candidate − reference).
  const double dark =
      strongest({rows.signed_of("near_black_share"), -rows.signed_of("log_luminance_p01"), -rows.signed_of("log_luminance_p05")});
  const bool dark_differs = group_differs({"dark", "tone"});
  if (says(dark_differs, dark)) c.words.push_back("fissures too dark");
  if (says(dark_differs, -dark)) c.words.push_back("fissures too light");
  const double fine_contrast = rows.signed_of("local_contrast_" + number(kLitParams.contrast_sigma_cm[0]) + "cm");
  const double fine =
      fine_r + fine_c > 0 ? 0.5 * (fine_contrast + signed_relative(fine_r, fine_c, kBandShareFloor)) : fine_contrast;
  const bool detail_differs = group_differs({"spectrum", "contrast"});
  if (says(detail_differs, -fine)) c.words.push_back("ridges too smooth");
  if (says(detail_differs, fine)) c.words.push_back("too much fine detail");
  const double relief = 0.5 * (rows.signed_of("local_contrast_" + number(kLitParams.contrast_sigma_cm[1]) + "cm") +
                               rows.signed_of("local_contrast_" + number(kLitParams.contrast_sigma_cm[2]) + "cm"));
  const bool relief_differs = group_differs({"contrast"});
  if (says(relief_differs, relief)) c.words.push_back("relief too strong");
  if (says(relief_differs, -relief)) c.words.push_back("relief too weak");
  // Colour spread along the chroma axis that changed most (a* red–green or b* yellow–blue).
  const double spread = strongest({rows.signed_of("colour_a_std"), rows.signed_of("colour_b_std")});
  const bool colour_differs = group_differs({"colour"});
  if (says(colour_differs, -spread)) c.words.push_back("colour too uniform");
  if (says(colour_differs, spread)) c.words.push_back("colour too varied");
  // The cast along its stronger axis: b* is yellow (warm) – blue (cool), a* red – green.
  if (cast > t.cast_delta_e) {
    if (std::abs(db) >= std::abs(da))
      c.words.push_back(db > 0 ? "too warm" : "too cool");
    else
      c.words.push_back(da > 0 ? "too red" : "too green");
  }
  if (c.orientation_emd_deg > t.orientation_emd_deg) c.words.push_back("grain direction differs");
  return c;
}

}  // namespace phellem
