// `phellem simulate SCENE.json -o DIR`: runs the bark simulations of a scene and writes their
// results (strip model: one FractureField EXR per cylinder).
#pragma once

#include "cli/options.h"

namespace phellem {
int run_simulate(const cli::Options& o);
}
