// `phellem simulate` for the scene's mesh objects with `"bark": {"model": "stress"}`: the
// stress-field cracking model (bark/stress/), written as a CrackedMesh .glb and a JSON summary
// per object.
#pragma once

#include <filesystem>
#include <nlohmann/json.hpp>

#include "cli/options.h"
#include "scene/scene_desc.h"
#include "util/output_set.h"

namespace phellem {

struct StressRunTotals {
  int objects = 0;
  long long triangles_in = 0, triangles_out = 0, cracks = 0, crack_edges = 0;
  int iterations = 0;
  double crack_length = 0, t_preprocess = 0, t_simulate = 0, t_write = 0;
  nlohmann::json outputs = nlohmann::json::array();
};

// Runs the stress objects of `desc` and stages their outputs, in folder `dir`, in `out`.
StressRunTotals simulate_stress_objects(const cli::Options& o, const SceneDesc& desc, const std::filesystem::path& dir,
                                        OutputSet& out);

}  // namespace phellem
