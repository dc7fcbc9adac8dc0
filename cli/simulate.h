// `phellem simulate SCENE.json -o DIR`: runs the bark simulations of a scene and writes their
// results (strip model: one FractureField EXR per cylinder and its .glb bark mesh; stress
// model: one CrackedMesh .glb and a JSON summary per mesh object).
#pragma once

#include "cli/options.h"

namespace phellem {
int run_simulate(const cli::Options& o);
}
