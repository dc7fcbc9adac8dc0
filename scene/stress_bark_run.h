// Runs the stress-field cracking model for one scene mesh object with
// `"bark": {"model": "stress"}`: its mesh (file or procedural), the preprocessing, the
// simulation with a progress bar; errors become UserErrors naming the scene or mesh file and
// where. Shared by `phellem simulate` and the renderer (which cracks the mesh while the scene
// is built).
#pragma once

#include <memory>
#include <optional>

#include "bark/stress/cracked_mesh.h"
#include "bark/stress/stress_cracker.h"
#include "scene/scene_desc.h"

namespace phellem {

struct StressRun {
  std::shared_ptr<const bark::CrackedMesh> cracked;
  bark::StressStats stats;
  size_t triangles_in = 0;  // after preprocessing
  double threshold_absolute = 0;
  double preprocess_s = 0, simulate_s = 0;
};

StressRun run_stress_object(const SceneDesc& desc, size_t object_index, std::optional<uint64_t> seed, bool progress);

}  // namespace phellem
