// The lit objective of `phellem fit --objective lit|both` (issue 44 item 2): the photo's relief
// and each candidate's relief rendered under the lit rig (lookdev/lit_rig.h) with one uniform
// albedo, compared by the lit score without its colour group. Fit fits the relief; colour is
// the dressing's (the fitted scene takes it from the photo), so colour must not steer the search.
#pragma once

#include <optional>
#include <string>

#include "compare/height_field.h"
#include "compare/lit_score.h"
#include "lookdev/lit_rig.h"

namespace phellem {

inline constexpr int kLitObjectiveSpp = 4;  // per pixel, per evaluation (the noise is far under the halves' band)

struct LitObjective {
  LitRig rig;
  float albedo[3] = {kLitDefaultAlbedo, kLitDefaultAlbedo, kLitDefaultAlbedo};  // the photo's mean, when it has one
  LitStatistics reference;
};

// `photo_m`: the photo's heights in metres at the evaluation scale; `albedo`: its colours (only
// their mean is used), if any.
LitObjective make_lit_objective(const HeightField& photo_m, const AlbedoField* albedo, const std::string& name);

// The mean of the lit score's groups other than colour, in [0, 1], for a candidate's heights in
// metres at the same scale; the full comparison in `comparison` when it is not null.
double lit_objective_value(const LitObjective& o, const HeightField& candidate_m, LitComparison* comparison = nullptr);

}  // namespace phellem
