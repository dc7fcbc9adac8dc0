// `phellem growth SCENE --frames N -o DIR/frame_%04d.exr`: a time-lapse of strip-bark growth.
// One simulation per tree runs through its steps; frame k (1..N) renders the state after
// k/N of them, each frame continuing the previous one (Lefebvre & Neyret 2002, sec. 4: growth
// with continuity), with the tree drawn at that step's girth.
#pragma once

#include "cli/options.h"

namespace phellem {

int run_growth(const cli::Options& o);

}  // namespace phellem
