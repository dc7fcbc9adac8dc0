// The outputs each command writes: all checked before any work (UserError naming the option),
// then written through one OutputSet and committed together at the end of the run.
#pragma once

#include <nlohmann/json.hpp>
#include <string>

#include "cli/options.h"
#include "scene/scene_desc.h"
#include "util/output_set.h"

namespace phellem {

// `render` without -o or --png writes render.exr.
std::string render_exr_path(const cli::Options& o);
// The option that asks for a frame sequence's PNG frames (--png, or --mp4, encoded from them).
std::string png_frames_option(const cli::Options& o);
// Checks and declares every output of o.command: render -o, --png, --stats; turntable and
// growth every frame of -o (and its PNG), --mp4; simulate the -o folder and --stats.
void expect_outputs(const cli::Options& o, OutputSet& out);
// Declares the files the loaded scene names (meshes, images) as inputs: no output replaces one.
void expect_scene_inputs(const SceneDesc& desc, OutputSet& out);
// Stages `j` (indented by 2) as the output `path` of `option`.
void write_json_output(OutputSet& out, const std::string& option, const std::string& path, const nlohmann::json& j);

}  // namespace phellem
