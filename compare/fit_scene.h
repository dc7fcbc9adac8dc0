// fitted.json: a scene that renders a trunk with the fitted bark (in the style of
// scenes/strips_*.json and scenes/stress_pine.json). The text is parsed back with scene/
// before it is written, so a fit never leaves a scene the renderer refuses.
#pragma once

#include <cstdint>
#include <string>

#include "compare/fit_parameters.h"

namespace phellem {

// The photograph the bark's colours come from (`fit --albedo`): the dressing's `photo` key
// (scene/bark_photo.h), paths as the scene file will read them (relative to its folder).
struct FitPhotoColours {
  std::string albedo, height;
  double px_per_cm = 0;
};

// The scene's JSON text: the candidate's parameters in full, the simulation seed `seed`, and
// the photo's colours when `photo` is given.
std::string fitted_scene_json(const FitCandidate& c, const std::string& preset, uint64_t seed,
                              const FitPhotoColours* photo = nullptr);

// Parses `text` (its paths relative to `base_dir`) with the scene parser and checks that the
// bark it describes is the candidate's (to float precision); throws std::logic_error naming
// the first difference, and the parser's UserError when it refuses the scene.
void check_fitted_scene(const std::string& text, const FitCandidate& c, const std::string& base_dir = ".");

}  // namespace phellem
