// Named strip-model settings for visually distinct fracture-based barks (Lefebvre & Neyret
// 2002, Figures 10, 15, 22). A scene's `"bark": {"model": "strips", "preset": NAME, ...}`
// starts from one and overrides single parameters.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "bark/strips/strip_params.h"

namespace phellem::bark {

std::optional<StripParams> strip_preset(const std::string& name);
std::vector<std::string> strip_preset_names();

}  // namespace phellem::bark
