// Frame sequences (`phellem turntable`, `phellem growth`): the -o pattern, frame names and the
// optional MP4 encoded from the PNG frames with ffmpeg.
#pragma once

#include <string>

#include "cli/options.h"

namespace phellem {

// The pattern needs exactly one %d-style field; --mp4 needs ffmpeg. UserError otherwise.
void check_frame_outputs(const cli::Options& o);
std::string frame_name(const std::string& pattern, int frame);
// Encodes the PNG frames next to the -o pattern into o.mp4 (atomically).
void encode_mp4(const cli::Options& o);

}  // namespace phellem
