// fitted.json: a scene that renders a trunk with the fitted bark (in the style of
// scenes/strips_*.json and scenes/stress_pine.json). The text is parsed back with scene/
// before it is written, so a fit never leaves a scene the renderer refuses.
#pragma once

#include <cstdint>
#include <string>

#include "compare/fit_parameters.h"

namespace phellem {

// The scene's JSON text: the candidate's parameters in full, the simulation seed `seed`.
std::string fitted_scene_json(const FitCandidate& c, const std::string& preset, uint64_t seed);

// Parses `text` with the scene parser and checks that the bark it describes is the candidate's
// (to float precision); throws std::logic_error naming the first difference.
void check_fitted_scene(const std::string& text, const FitCandidate& c);

}  // namespace phellem
