// The HTML report of `phellem compare --lit`: the two renders side by side at their true
// relative size (one exposure for both), a difference view, each statistic's bars, and the
// verdict in an artist's words.
#pragma once

#include <string>

#include "compare/lit_score.h"
#include "compare/lit_statistics.h"

namespace phellem {

struct LitReportSide {
  std::string label;  // "A" (the reference) or "B" (the candidate)
  std::string path;   // what the user named
  std::string note;   // how its heights were read (relief, scale, crop)
  const LitImage* image = nullptr;
  const LitStatistics* stats = nullptr;
};

// `rig`: one sentence on the light rig. Embeds the renders as PNG (sRGB display transform,
// exposed so that the reference's median luminance shows as middle grey).
std::string lit_report_html(const LitReportSide& reference, const LitReportSide& candidate, const LitComparison& comparison,
                            const std::string& rig);

// The renders' pixels in the report: linear RGB × exposure through the sRGB display transform,
// 8-bit, row 0 at the top (for tests).
std::vector<unsigned char> lit_render_png(const LitImage& image, double exposure);

}  // namespace phellem
