// `phellem simulate` for the scene's mesh objects with `"growth"`: cambial growth
// (bark/growth/), then, when the object has stress bark, the cracking of the grown surface.
// Per object: `<name>.glb` (the grown surface with its UVs, and its cracks when it has stress
// bark), `<name>_rings.glb` (one primitive per growth ring) and `<name>.json` (a summary).
#pragma once

#include <filesystem>
#include <nlohmann/json.hpp>

#include "cli/options.h"
#include "scene/scene_desc.h"
#include "util/output_set.h"

namespace phellem {

struct GrowthRunTotals {
  int objects = 0;
  long long steps = 0, vertices_start = 0, vertices_end = 0, remeshes = 0;
  double t_setup = 0, t_growth = 0, t_crack = 0, t_write = 0;
  double t_remesh = 0, t_motion = 0, t_contact = 0, t_repair = 0;  // parts of t_growth
  nlohmann::json outputs = nlohmann::json::array();
};

GrowthRunTotals simulate_growth_objects(const cli::Options& o, const SceneDesc& desc, const std::filesystem::path& dir,
                                        OutputSet& out);

// The rings as one mesh with one primitive ("ring_<step>") per ring, lighter for later rings.
struct GlbMesh;
GlbMesh rings_mesh(const std::vector<bark::GrowthRing>& rings);

}  // namespace phellem
