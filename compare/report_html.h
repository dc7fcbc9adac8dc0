// The compare report as one self-contained HTML file (images as data: URIs, charts as inline
// SVG, no external resources): the inputs side by side at the common scale, their fissure
// masks, orientation roses, spacing and width histograms, every statistic with the
// same-bark band marked, and the verdict.
#pragma once

#include <string>

#include "compare/compare_inputs.h"

namespace phellem {

std::string report_html(const CompareReport& report);

// The number of <img> elements report_html() writes for `report` (tests check each decodes).
int report_image_count(const CompareReport& report);

}  // namespace phellem
