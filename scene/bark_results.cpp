#include "scene/bark_results.h"

#include <chrono>
#include <optional>

#include "scene/growth_run.h"
#include "scene/stress_bark_run.h"
#include "scene/strip_bark_tree.h"
#include "util/hash.h"

namespace phellem {

bool has_simulated_bark(const ObjectDesc& o) {
  return o.stress_bark || o.growth || (o.type == ObjectType::Tree && o.tree.strip_bark);
}

ObjectBark simulate_object_bark(const SceneDesc& desc, size_t object, bool progress) {
  const ObjectDesc& o = desc.objects.at(object);
  ObjectBark out;
  if (o.growth) {
    const GrowthRun run = run_growth_object(desc, object, progress);
    out.grown = run.surface;
    out.cracked = run.cracked;  // stress bark cracked as it grew (none with "cracks": false)
    out.texture_levels = run.texture_levels;
  } else if (o.stress_bark) {
    out.cracked = run_stress_object(desc, object, std::nullopt, progress).cracked;
  } else if (o.type == ObjectType::Tree && o.tree.strip_bark) {
    TreeStripSimulation sim(o, object);
    sim.run(progress);
    out.strip_parts = sim.surfaces();
  }
  return out;
}

BarkResults simulate_bark(const SceneDesc& desc, bool progress) {
  const auto t0 = std::chrono::steady_clock::now();
  BarkResults r;
  for (size_t oi = 0; oi < desc.objects.size(); ++oi)
    if (has_simulated_bark(desc.objects[oi])) r.objects.emplace(oi, simulate_object_bark(desc, oi, progress));
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return r;
}

std::shared_ptr<const bark::CrackBarkSurface> crack_surface(const ObjectDesc& o, const bark::CrackedMesh& cracked) {
  return std::make_shared<const bark::CrackBarkSurface>(cracked, o.stress_bark->look, fold_seed(o.stress_bark->params.seed));
}

}  // namespace phellem
