// The memory check of every command (scene/memory_estimate.h): the scene's stages and the
// film, against the budget (--memory-limit, PHELLEM_MEMORY_LIMIT or a share of physical
// memory), before any stage runs.
#pragma once

#include "cli/options.h"
#include "scene/scene_desc.h"

namespace phellem {

// Throws UserError, at the knob of the largest part, when the command would not fit. `width`
// × `height`: the film (render, turntable, growth), the section image (slice); ignored by simulate.
// Then prints how long each cambial growth will take (unless --quiet; scene/growth_time.h) and
// throws UserError at the longest one's steps when together they would take longer than
// --time-limit (1 h).
void check_scene_memory(const cli::Options& o, const SceneDesc& desc, int width, int height);
// `--memory-estimate`: prints the estimate of the command, stage by stage, and the budget;
// exit code 0 when it fits (else the refusal, exit 2).
int run_memory_estimate(const cli::Options& o);

}  // namespace phellem
