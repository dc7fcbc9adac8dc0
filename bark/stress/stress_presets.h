// Named stress-model settings: the thesis's Table 1 rows (Spicker 2014) — the tree trunks
// (birch, pine, palm; their "user defined" stress is given here as the pattern that gives
// each its look) and the uniform-tension rows (bunny, mouse) — plus "woodification", the
// look of the Woodification paper's figures on arbitrary objects. A scene's
// `"bark": {"model": "stress", "preset": NAME, ...}` starts from one and overrides parameters.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "bark/stress/stress_params.h"

namespace phellem::bark {

std::optional<StressParams> stress_preset(const std::string& name);
std::vector<std::string> stress_preset_names();

}  // namespace phellem::bark
