// Variants of a lit subject for calibrating the lit score (docs/compare.md, "Lit calibration"):
// halves of one piece of bark, and the three deliberate defects the score must detect — relief
// × 3, the albedo replaced by its mean, and the fissure floors painted black.
#pragma once

#include "lookdev/lit_rig.h"

namespace phellem {

// The left/right (`vertical_cut`) or top/bottom half; `second` picks right/bottom.
LitSubject half_of(const LitSubject& s, bool vertical_cut, bool second);
LitSubject with_relief_scaled(const LitSubject& s, double factor);
// Every pixel the albedo's mean colour (kLitDefaultAlbedo grey without an albedo).
LitSubject with_mean_albedo(const LitSubject& s);
// The albedo black over the fissures compare finds (compare/fissure_statistics.h's mask).
LitSubject with_black_fissure_floors(const LitSubject& s);

}  // namespace phellem
