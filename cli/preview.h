// `phellem preview [SCENE.json] [--snapshot OUT.png [-o AOVS.exr]] [--res WxH]` (issue 23):
// the OpenGL tessellation preview. With --snapshot one frame is rendered headless (EGL) and
// written as a PNG, with -o also an EXR of its crack mask, crack depth and distance.
#pragma once

#include "cli/options.h"

namespace phellem {

int run_preview(const cli::Options& o);

}  // namespace phellem
