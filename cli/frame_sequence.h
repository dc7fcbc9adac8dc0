// Frame sequences (`phellem turntable`, `phellem growth`): the -o pattern, frame names and the
// optional MP4 encoded from the PNG frames with ffmpeg.
#pragma once

#include <string>

#include "cli/options.h"
#include "cli/render_job.h"
#include "renderer/camera.h"
#include "renderer/render_scene.h"
#include "util/output_set.h"

namespace phellem {

// The pattern needs exactly one %d-style field; --mp4 needs ffmpeg. UserError otherwise.
void check_frame_outputs(const cli::Options& o);
std::string frame_name(const std::string& pattern, int frame);
// The PNG written beside an EXR frame.
std::string png_frame_name(const std::string& exr_frame);
// Renders frame `frame` of `frames` and stages its EXR (and PNG beside it when asked) in `out`.
void render_frame(const cli::Options& o, const Loaded& l, const RenderScene& scene, const Camera& camera, int frame, int frames,
                  OutputSet& out);
// Encodes the staged PNG frames of the -o pattern into o.mp4 (staged in `out` too).
void encode_mp4(const cli::Options& o, OutputSet& out);

}  // namespace phellem
