// `phellem slice SCENE.json -o SECTION.png [--object NAME] [--plane x|y|z=VALUE] [--res WxH]`:
// grows a mesh object with `"growth"` (scene/growth_run.h) and draws the cross-section of its
// wood in an axis-aligned plane with the growth rings (bark/growth/ring_section.h) and the
// obstacles' sections. Default object: the scene's only growing one; default plane: y at the
// middle of the grown surface's height; default size 1024 × 1024.
#pragma once

#include "cli/options.h"

namespace phellem {

// The section image's size without --res (and never smaller than 16: draw_ring_section's floor).
inline constexpr int kSliceDefaultSize = 1024;

int run_slice(const cli::Options& o);

}  // namespace phellem
